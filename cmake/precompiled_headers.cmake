# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# Precompiled headers. Parsing the standard library, Eigen and nlohmann-json again in every
# file was much of the front end's time (results_record.cpp: 4.0 of its 8.0 CPU-s were
# -fsyntax-only; run_case.cpp 11.9 -> 8.6 CPU-s with them); each target now parses them
# once. The Release build from scratch on two cores: 434 s with them, 503 s without (load
# about 2, both measured at the commit that added them; the unity build,
# cmake/unity_build.cmake, then halved the compiling again). ARMSTUDY_PCH=OFF builds without
# them (the fuzz build, tests/fuzz, never uses them, so a missing #include still shows
# there and in this build with the option off).
option(ARMSTUDY_PCH "Precompile the standard library, Eigen and nlohmann-json headers" ON)

set(ARMSTUDY_PCH_COMMON <algorithm> <array> <cmath> <cstdio> <filesystem> <fstream>
    <functional> <map> <memory> <optional> <sstream> <stdexcept> <string> <vector>
    <Eigen/Dense>)

# armstudy_pch(target [OWN] [more headers...]): the common headers plus the target's own.
# Targets with the same list share one precompiled header (REUSE_FROM the first of them; each
# took 4-6 CPU-s): the test executables one, core, studies and scene one, report and the app
# one. OWN: a header of its own, for a target whose definitions change the headers (the case
# loaders' _GLIBCXX_ASSERTIONS). GCC checks that a shared header fits (-Winvalid-pch).
function(armstudy_pch target)
  if(NOT ARMSTUDY_PCH)
    return()
  endif()
  set(headers ${ARGN})
  if("${ARGV1}" STREQUAL "OWN")
    list(REMOVE_AT headers 0)
    target_precompile_headers(${target} PRIVATE ${ARMSTUDY_PCH_COMMON} ${headers})
    return()
  endif()
  string(MAKE_C_IDENTIFIER "pch_${headers}" key)
  get_property(first GLOBAL PROPERTY ARMSTUDY_PCH_FIRST_${key})
  if(first)
    target_precompile_headers(${target} REUSE_FROM ${first})
  else()
    set_property(GLOBAL PROPERTY ARMSTUDY_PCH_FIRST_${key} ${target})
    target_precompile_headers(${target} PRIVATE ${ARMSTUDY_PCH_COMMON} ${headers})
  endif()
endfunction()
