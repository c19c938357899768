#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# armstudy set-up and the whole test suite, command 2 of the README (.ci/run calls it):
# installs the missing packages, builds in Release and runs every test with CTest, then
# the suite again built with AddressSanitizer and UndefinedBehaviorSanitizer
# (scripts/test_sanitizers.sh; ARMSTUDY_SANITIZERS=0 skips that part).
set -euo pipefail
cd "$(dirname "$0")/.."
# warnings are errors here (-Wall -Wextra -Wshadow, CMakeLists.txt)
ARMSTUDY_WERROR=ON scripts/setup.sh --no-reports
export LP_NUM_THREADS=1
jobs=$(nproc 2>/dev/null || echo 2)
ctest --test-dir build --output-on-failure -j"$jobs" --timeout 900
if [ "${ARMSTUDY_SANITIZERS:-1}" != 0 ]; then
  scripts/test_sanitizers.sh
fi
