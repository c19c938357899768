# Precompiled headers. Parsing the standard library, Eigen and nlohmann-json again in every
# file was most of the front end's time (e.g. results_record.cpp: 4.0 of its 8.0 CPU-s
# were -fsyntax-only); each target now parses them once. ARMSTUDY_PCH=OFF builds without
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
