#!/usr/bin/env bash
# The test suite built with AddressSanitizer and UndefinedBehaviorSanitizer (gcc's, in a
# second build folder, build-asan/) and run with CTest: any memory error, leak or
# undefined behaviour fails the test that triggers it. scripts/test.sh runs it after the
# ordinary suite.
#
# Left out (ARMSTUDY_SANITIZE_EXCLUDE, a CTest -E regular expression): the browser tests
# (headless Chromium prints the pages; armstudy's part is the same fork/exec code that
# e2e.interrupt runs here with a stand-in browser) and the fault-injection test (strace
# stops the run at each of its renames; LeakSanitizer cannot run under ptrace, and the
# run's memory is what the other tests exercise).
#
#   scripts/test_sanitizers.sh            configure, build and run
#   scripts/test_sanitizers.sh -R merge   extra arguments go to ctest
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
jobs=$(nproc 2>/dev/null || echo 2)
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build build-asan -j"$jobs"
built=$(date +%s)

export LP_NUM_THREADS=1
supp="$(pwd)/tests/sanitizers"
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:detect_stack_use_after_return=0:strict_string_checks=1:check_initialization_order=1"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$supp/ubsan.supp"
exclude=${ARMSTUDY_SANITIZE_EXCLUDE:-"BrowserReport|e2e.fault_injection"}
status=0
ctest --test-dir build-asan --output-on-failure -j"$jobs" --timeout 1800 -E "$exclude" "$@" || status=$?
end=$(date +%s)
echo "sanitizers: build $((built - start)) s, tests $((end - built)) s (excluded: $exclude)"
exit $status
