#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# The test suite built with AddressSanitizer and UndefinedBehaviorSanitizer (gcc's, in a
# second build folder, build-asan/) and run with CTest: any memory error, leak or
# undefined behaviour fails the test that triggers it. scripts/test.sh runs it after the
# ordinary suite.
#
# By default (and in CI, through scripts/test.sh) the quick tier (`ctest -L quick`: every
# GoogleTest of core, studies, cases, scene, report, cli and e2e but the few in
# tests/slow_tests.txt, so every solver runs instrumented on the tests' small inputs) and
# e2e.interrupt (the fork/exec code of the browser with a stand-in). Left out: the e2e
# folder's whole-run suites (below: Diff, ForeignOutput, OutputSafety, ... each runs armstudy
# on whole rendered cases to check the files a run leaves), the browser
# tests (headless Chromium prints the bundled reports; minutes under ASan), the
# fault-injection and package tests (strace watches the run; LeakSanitizer cannot run under
# ptrace), the independent placement checks (their armstudy part is the placement solver,
# whose quick tests run here; 42 s in Release), the exports' and viewer's client tests (their armstudy part is every bundled case,
# as the browser tests'; minutes under ASan), the sweep scale-out tests and the live Slurm and ssh ones (their armstudy part is
# the sweep code the e2e tests cover). ARMSTUDY_SANITIZE_ALL=1 runs every test but the
# browser, fault-injection and package ones.
#
# The code under test (the libraries, armstudy) is built -O1 -g1 (line tables for the
# reports' stack traces; about half the compile time of -O2 -g), the tests' own code -O0
# (ARMSTUDY_TEST_COMPILE_OPTIONS, instrumented alike), with Ninja; the benchmarks are not
# built. From a fresh tree without ccache (CCACHE_DISABLE=1) the build compiles for 789 CPU-s
# (1549 s wall at load 6-11 on the shared 2-core machine, niced); before (tests -O1, 20 test
# files outside the unity batches, test objects waiting for armstudy; measured with Ninja)
# 1064 CPU-s (2158 s at load 7-20), and 533 s on two quiet cores (Makefiles), so by CPU an
# estimated 400 s now (not measured on a quiet machine). The tests' -O0 does not slow the
# run: 464 CPU-s (1110 s at load 6-11) against 466 (1127 s at load 6-8).
#
# Leaks in libraries armstudy uses (fontconfig, libltdl, OSMesa) are suppressed in
# tests/sanitizers/lsan.supp; everything in armstudy's own code fails the test.
#
#   scripts/test_sanitizers.sh            configure, build and run
#   scripts/test_sanitizers.sh -R merge   extra arguments go to ctest
#
# ARMSTUDY_SANITIZER_PHASE=build only configures and builds, =test only runs the tests of an
# earlier build. scripts/test.sh runs the whole tier (build, then tests) in the background
# beside the Release suite.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
jobs=$(nproc 2>/dev/null || echo 2)
flags="-O1 -g1 -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
# Ninja (scripts/packages.txt) for a new build-asan/; a folder made earlier keeps its generator
generator=()
if command -v ninja >/dev/null && { [ ! -f build-asan/CMakeCache.txt ] ||
  grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' build-asan/CMakeCache.txt; }; then
  generator=(-G Ninja)
fi
phase=${ARMSTUDY_SANITIZER_PHASE:-all}
case "$phase" in all | build | test) ;; *) echo "ARMSTUDY_SANITIZER_PHASE: all, build or test, not '$phase'" >&2; exit 2 ;; esac
if [ "$phase" != test ]; then
  cmake "${generator[@]}" -S . -B build-asan -DCMAKE_BUILD_TYPE=None -DARMSTUDY_BUILD_BENCH=OFF "${launcher[@]}" \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" -DARMSTUDY_TEST_COMPILE_OPTIONS=-O0 \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
  cmake --build build-asan -j"$jobs"
  echo "sanitizers: built in $(($(date +%s) - start)) s"
  [ "$phase" = build ] && exit 0
fi
if [ "${ARMSTUDY_SANITIZE_ALL:-0}" = 1 ]; then
  exclude="BrowserReport|e2e.fault_injection|install.debian_package"
  select=()
else
  exclude="BrowserReport"
  # every test of tests/slow_tests.txt is left out, whatever its label (the e2e folder's
  # slow tests carry the label e2e, not quick: four of them, each a whole case or several,
  # ran here instrumented until the list was read): their code runs here through the
  # quick tests beside them (e.g. the throwing sensitivity cross-check solves the bundled
  # throw 11 times, over 10 min under ASan; the throwing tests run here)
  slow=$(grep -v -e '^#' -e '^[[:space:]]*$' tests/slow_tests.txt | sed 's/^[[:space:]]*//; s/[[:space:]]*$//; s/.*/^&$/' | paste -sd'|')
  # the e2e folder's whole-run suites: each runs armstudy on whole cases (rendered, several
  # times over) to check the files a run leaves, the figures it prints and how it skips;
  # their armstudy code runs instrumented here through the unit tests of the same code and
  # the e2e suites that stay (hostile and untrusted input, merge, diff's tolerances, the
  # command line); 509 of the tier's 1248 test-seconds (build-asan at f683386, load 4-7)
  whole_runs="^(Diff|ForeignOutput|OutputSafety|ResultsNumbers|PrintedPlacements|NeverHang|Sensitivity)\\."
  whole_runs+="|^SourceComparison\\.(EveryCase|EveryReason|EachPrinted|TheThesis|TheAnyNumber|ADifference)"
  select=(-L "^quick$|^e2e$" -E "$exclude|$slow|$whole_runs|^guard\.|^install\.|^e2e\.(sweep_scale_out|slurm_cluster|ssh_parallel|fault_injection|export_clients|simulate_viewer|check_placement_energy|check_placement_limits)$")
fi
built=$(date +%s)

export LP_NUM_THREADS=1
supp="$(pwd)/tests/sanitizers"
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:detect_stack_use_after_return=0:strict_string_checks=1:check_initialization_order=1"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$supp/ubsan.supp"
status=0
if [ ${#select[@]} -eq 0 ]; then select=(-E "$exclude"); fi
# the GoogleTests batched, several per process (scripts/run_gtest_batches.py: an instrumented
# process costs about 0.45 CPU-s to start and end, 200 of the tier's CPU-s when each test had
# its own); ARMSTUDY_SANITIZER_BATCHES=0 runs each test in its own process through CTest
if [ "${ARMSTUDY_SANITIZER_BATCHES:-1}" != 0 ]; then
  python3 scripts/run_gtest_batches.py build-asan "$jobs" 900 "${select[@]}" "$@" || status=$?
else
  ctest --test-dir build-asan --output-on-failure -j"$jobs" --timeout 900 "${select[@]}" "$@" || status=$?
fi
end=$(date +%s)
if [ "$phase" = test ]; then
  echo "sanitizers: tests $((end - built)) s (excluded: $exclude)"
else
  echo "sanitizers: build $((built - start)) s, tests $((end - built)) s (excluded: $exclude)"
fi
exit $status
