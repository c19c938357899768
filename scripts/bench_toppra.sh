#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# Optional benchmark: armstudy's exact time-optimal solver beside TOPP-RA's C++ core (its
# Seidel LP solver) on the anchor problem (scripts/toppra_anchor.cpp describes it), in the
# same run. TOPP-RA is not a dependency of armstudy: build it yourself, outside this
# repository, with Eigen only, e.g.
#   git clone https://github.com/hungpham2511/toppra && cmake -S toppra/cpp -B toppra-build \
#     -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTS=OFF -DPYTHON_BINDINGS=OFF -DTOPPRA_WARN_ON=OFF
#   cmake --build toppra-build
#
# usage: scripts/bench_toppra.sh TOPPRA_BUILD_DIR [ARMSTUDY_BUILD_DIR (build)] [ROUNDS (3)]
# Each round runs TOPP-RA (median of 200 solves), armstudy's benchmarks BM_TimeOptimalAnchor*
# (tests/bench/time_optimal_anchor_bench.cpp) at 1000 intervals and TOPP-RA again, and prints
# the durations and the ratios of the solve times to the mean of TOPP-RA's two medians, with
# the machine's load.
set -euo pipefail
toppra_build=$(cd "${1:?usage: $0 TOPPRA_BUILD_DIR [ARMSTUDY_BUILD_DIR] [ROUNDS]}" && pwd)
here=$(cd "$(dirname "$0")/.." && pwd)
build=${2:-$here/build}
rounds=${3:-3}
src=$(sed -n 's/^toppra_SOURCE_DIR:STATIC=//p' "$toppra_build/CMakeCache.txt")
lib=$(find "$toppra_build" -name 'libtoppra.so' -o -name 'libtoppra.a' | head -1)
[ -n "$src" ] && [ -n "$lib" ] || { echo "$toppra_build: not a TOPP-RA build (no toppra_SOURCE_DIR or libtoppra)" >&2; exit 2; }
[ -x "$build/tests/armstudy_bench" ] || { echo "$build/tests/armstudy_bench missing: build armstudy first" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
c++ -O3 -DNDEBUG -std=c++17 -I "$src/src" -I "$(dirname "$lib")" -isystem /usr/include/eigen3 \
  "$here/scripts/toppra_anchor.cpp" -o "$work/toppra_anchor" "$lib" -Wl,-rpath,"$(dirname "$lib")"
for r in $(seq "$rounds"); do
  # TOPP-RA just before and just after armstudy's benchmarks: the ratio is taken to the mean
  # of its two medians, so that the machine's drift over the round falls on both sides
  echo "round $r: $(uptime | sed 's/.*load/load/')"
  t1=$("$work/toppra_anchor" 1000 200)
  a=$("$build/tests/armstudy_bench" --benchmark_filter='BM_TimeOptimalAnchor' \
        --benchmark_format=csv 2>/dev/null | grep '^"BM_TimeOptimalAnchor')
  t2=$("$work/toppra_anchor" 1000 200)
  echo "  before: $t1"
  echo "  after:  $t2"
  echo "$a" | while IFS=, read -r name iters real cpu unit rest; do
    echo "  armstudy $name real_${unit} $real cpu_${unit} $cpu"
  done
  tm=$(python3 -c "import sys; print((float(sys.argv[1]) + float(sys.argv[2])) / 2)" \
        "$(echo "$t1" | sed 's/.* median_ms \([0-9.]*\).*/\1/')" \
        "$(echo "$t2" | sed 's/.* median_ms \([0-9.]*\).*/\1/')")
  tc=$(python3 -c "import sys; print((float(sys.argv[1]) + float(sys.argv[2])) / 2)" \
        "$(echo "$t1" | sed 's/.*cpu_median_ms \([0-9.]*\).*/\1/')" \
        "$(echo "$t2" | sed 's/.*cpu_median_ms \([0-9.]*\).*/\1/')")
  echo "$a" | while IFS=, read -r name iters real cpu unit rest; do
    python3 -c "print('  TOPP-RA / armstudy solve time, $name: wall %.2fx, CPU %.2fx' % ($tm / $real, $tc / $cpu))"
  done
done
