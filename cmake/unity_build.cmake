# Unity (jumbo) builds: CMake compiles a target's sources a few at a time as one translation
# unit (unity_<n>_cxx.cxx including them), so that the templates several files use (nlohmann-json,
# GoogleTest, Eigen, the results mapping of report/results_fields.hpp) are instantiated and
# optimised once per batch instead of once per file. Most of the build's time is code
# generation at -O3 (results_sections_test.cpp: 19 of its 21 CPU-s), much of it for the same
# inline functions in every test file. Files with their own COMPILE_OPTIONS stay on their own
# (CMake leaves them out of the batches). A name in an anonymous namespace must therefore be
# unique across a target's files. ARMSTUDY_UNITY=OFF builds every file on its own (and shows
# a missing #include that another file of the batch happens to provide).
option(ARMSTUDY_UNITY "Compile each target's sources in batches (CMake unity build)" ON)
set(ARMSTUDY_UNITY_BATCH 8 CACHE STRING "Source files per unity batch (0: a whole target in one)")

# armstudy_unity(target): the target's sources in batches of ARMSTUDY_UNITY_BATCH
function(armstudy_unity target)
  if(ARMSTUDY_UNITY)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON
                          UNITY_BUILD_BATCH_SIZE ${ARMSTUDY_UNITY_BATCH})
  endif()
endfunction()
