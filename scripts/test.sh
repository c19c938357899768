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
  # the sanitizer build beside the Release suite: it fills the CPU the tests leave idle
  # (their waits on the Slurm and ssh daemons, Chromium, ffmpeg, the single-test tail) and
  # goes on at full speed when the suite ends. setsid gives it its own session, so that a
  # failed suite stops the whole build; where the kernel groups the scheduler by session
  # (autogroup, on in Debian's kernels) that session shares the CPU evenly with the suite's
  # and nice 19 only ranks the build's own processes; without autogroup the build takes only
  # what the tests leave. Measured with autogroup: docs/testing.md.
  mkdir -p build-asan
  ARMSTUDY_SANITIZER_PHASE=build setsid nice -n 19 scripts/test_sanitizers.sh >build-asan/build.log 2>&1 &
  asan_build=$!
  trap 'kill -- "-$asan_build" 2>/dev/null || true' EXIT
fi
status=0
ctest --test-dir build --output-on-failure -j"$jobs" --timeout 900 || status=$?
if [ "$sanitizers" != 0 ]; then
  if [ "$status" != 0 ]; then
    echo "test: the Release suite failed (exit $status); the sanitizer tier is not run"
    exit "$status"
  fi
  echo "test: waiting for the sanitizer build (started beside the Release suite)"
  if ! wait "$asan_build"; then
    tail -n 60 build-asan/build.log
    echo "test: the sanitizer build failed (build-asan/build.log)"
    exit 1
  fi
  trap - EXIT
  tail -n 1 build-asan/build.log
  ARMSTUDY_SANITIZER_PHASE=test scripts/test_sanitizers.sh
fi
exit "$status"
