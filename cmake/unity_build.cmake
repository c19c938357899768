# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# Unity (jumbo) builds: CMake compiles a target's sources a few at a time as one translation
# unit (Unity/unity_<n>_cxx.cxx including them), so that the templates several files use
# (nlohmann-json, GoogleTest, the results mapping of report/results_fields.hpp, the records'
# destructors) are instantiated and optimised once per batch instead of once per file: with
# the precompiled headers most of the build was code generation at -O3
# (study_results_test.cpp: 19 of its 21 CPU-s), and 6.7 of the 15.6 MB of code the
# objects held were the same inline functions again. The Release build from scratch (tests
# and benchmarks too) compiled for 556 CPU-s against about 1130 file by file (batches of 8,
# with the shared precompiled headers); on two cores 542 s at load 3.4-5 (the machine shared)
# against 586 s at load 0.6-2.9, so about 290 s on two quiet cores.
#
# Files with their own COMPILE_OPTIONS stay on their own (CMake leaves them out of the
# batches), and so do the files listed with SKIP_UNITY_BUILD_INCLUSION (CMakeLists.txt): a
# name in an anonymous namespace must be unique among the files of a batch (the tests share
# their helpers through tests/testing/ and all compile in batches: tests/CMakeLists.txt). The lists were checked with the whole of each target in one batch
# (-DARMSTUDY_UNITY_BATCH=0), so any batch size builds; a new file that clashes ("redefinition
# of ... {anonymous}::...") gets a unique name or goes on a list. ARMSTUDY_UNITY=OFF builds
# every file on its own (and shows a missing #include that a file of the batch provided).
option(ARMSTUDY_UNITY "Compile each target's sources in batches (CMake unity build)" ON)
set(ARMSTUDY_UNITY_BATCH 8 CACHE STRING "Source files per unity batch (0: a whole target in one)")

# armstudy_unity(target): the target's sources in batches of ARMSTUDY_UNITY_BATCH
function(armstudy_unity target)
  if(ARMSTUDY_UNITY)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON
                          UNITY_BUILD_BATCH_SIZE ${ARMSTUDY_UNITY_BATCH})
  endif()
endfunction()
