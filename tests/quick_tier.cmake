# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# The quick tier (`ctest -L quick`, the edit-build-test loop): every GoogleTest of every
# folder gets the label `quick` beside its folder's label, except those matching a line of
# tests/slow_tests.txt (tests that drive the browser or run many whole cases). CTest
# includes this file after every folder's discovered list (TEST_INCLUDE_FILES, appended
# after the gtest_discover_tests calls), so the <target>_TESTS lists are known here. A line
# that matches no test is reported, so that a renamed test is not silently left in the tier.
file(STRINGS "@SLOW_LIST@" slow_patterns REGEX "^[^#]")
set(slow_matched "")
foreach(folder @QUICK_FOLDERS@)
  foreach(test IN LISTS ${folder}_tests_TESTS)
    set(slow FALSE)
    foreach(pattern IN LISTS slow_patterns)
      string(STRIP "${pattern}" pattern)
      if(pattern AND test MATCHES "^${pattern}$")
        set(slow TRUE)
        list(APPEND slow_matched "${pattern}")
        break()
      endif()
    endforeach()
    if(NOT slow)
      set_tests_properties("${test}" PROPERTIES LABELS "${folder};quick")
    else()
      # started first in a run with no timings yet (a fresh clone, CI): a long test begun
      # last keeps one core busy after the other has finished
      set_tests_properties("${test}" PROPERTIES COST 60)
    endif()
  endforeach()
endforeach()
foreach(pattern IN LISTS slow_patterns)
  string(STRIP "${pattern}" pattern)
  list(FIND slow_matched "${pattern}" found)
  if(pattern AND found EQUAL -1)
    message(WARNING "tests/slow_tests.txt: '${pattern}' names no test (renamed or removed?)")
  endif()
endforeach()
