# Precompiled headers. Parsing the standard library, Eigen and nlohmann-json again in every
# file was much of the front end's time (results_record.cpp: 4.0 of its 8.0 CPU-s were
# -fsyntax-only; run_case.cpp 11.9 -> 8.6 CPU-s with them); each target now parses them
# once. The Release build from scratch on two cores: 434 s with them, 503 s without (load
# about 2, both measured at the commit that added them). ARMSTUDY_PCH=OFF builds without
# them (the fuzz build, tests/fuzz, never uses them, so a missing #include still shows
# there and in this build with the option off).
option(ARMSTUDY_PCH "Precompile the standard library, Eigen and nlohmann-json headers" ON)

set(ARMSTUDY_PCH_COMMON <algorithm> <array> <cmath> <cstdio> <filesystem> <fstream>
    <functional> <map> <memory> <optional> <sstream> <stdexcept> <string> <vector>
    <Eigen/Dense>)

# armstudy_pch(target [more headers...]): the common headers plus the target's own
function(armstudy_pch target)
  if(ARMSTUDY_PCH)
    target_precompile_headers(${target} PRIVATE ${ARMSTUDY_PCH_COMMON} ${ARGN})
  endif()
endfunction()
