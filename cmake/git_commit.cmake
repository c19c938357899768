# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# Writes OUT (a C++ source defining armstudy::git_commit()) from `git describe` of SOURCE_DIR,
# rewriting it only when the text changes, so that a build after a commit records the new
# commit without recompiling anything else. "-dirty" marks uncommitted changes.
execute_process(COMMAND git describe --always --dirty --abbrev=12
                WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
set(text "// generated at build time by cmake/git_commit.cmake\nnamespace armstudy {\nconst char* git_commit() { return \"${commit}\"; }\n}  // namespace armstudy\n")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
else()
  set(old "")
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUT} "${text}")
endif()
