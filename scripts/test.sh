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
sanitizers=${ARMSTUDY_SANITIZERS:-1}
if [ "$sanitizers" != 0 ]; then
  # the sanitizer tier beside the Release suite, build and tests: it fills the CPU the
  # Release tests leave idle (their waits on the Slurm and ssh daemons, Chromium, ffmpeg, the
  # single-test tail) and goes on at full speed when the suite ends; its tests start as soon
  # as its build is done, not when the Release suite is. setsid gives it its own session, so
  # that a failed suite stops the whole tier; where the kernel groups the scheduler by
  # session (autogroup, on in Debian's kernels) that session shares the CPU evenly with the
  # suite's and nice 19 only ranks the tier's own processes; without autogroup the tier takes
  # only what the tests leave. Measured with autogroup: docs/testing.md.
  mkdir -p build-asan
  setsid nice -n 19 scripts/test_sanitizers.sh >build-asan/tier.log 2>&1 &
  asan_tier=$!
  trap 'kill -- "-$asan_tier" 2>/dev/null || true' EXIT
fi
status=0
ctest --test-dir build --output-on-failure -j"$jobs" --timeout 900 || status=$?
if [ "$sanitizers" != 0 ]; then
  if [ "$status" != 0 ]; then
    echo "test: the Release suite failed (exit $status); the sanitizer tier is stopped"
    exit "$status"
  fi
  echo "test: the Release suite passed; waiting for the sanitizer tier (build-asan/tier.log)"
  asan_status=0
  wait "$asan_tier" || asan_status=$?
  trap - EXIT
  if [ "$asan_status" != 0 ]; then
    # the failed tests' output (ctest --output-on-failure), or the build's last lines
    if grep -q "tests failed out of" build-asan/tier.log; then
      grep -E -B2 -A60 "\*\*\*Failed|\*\*\*Exception|\*\*\*Timeout|Failed +[0-9.]+ sec" build-asan/tier.log | head -n 400
      sed -n '/tests failed out of/,$p' build-asan/tier.log
    else
      tail -n 60 build-asan/tier.log
    fi
    echo "test: the sanitizer tier failed (exit $asan_status; build-asan/tier.log)"
    exit "$asan_status"
  fi
  grep -E "tests passed|^sanitizers:" build-asan/tier.log
fi
exit "$status"
