#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# Sweep throughput benchmark and the 200-case scale run: the bundled sweep
# (reports/sweeps/placement-link-ratio.yaml) without rendering, run (a) once with --jobs J,
# (b) as N shards one after the other, each with --jobs J, then both merged. Prints cases
# per second and the overhead of sharding and merging as ratios measured in this one run
# (machines are shared and noisy: compare the ratios, not the absolute figures across
# runs). At this scale it also checks what the e2e test (tests/e2e/sweep_scale_out_test.sh,
# 24 cases) checks on a small sweep: all 200 cases expand (and again write nothing), both
# ways merge into identical tables with a row per case, the index lists every case, the
# summary stays under 1 MiB and every results.json validates against the schema. Exit 1
# when a check fails.
# usage: scripts/bench_sweep.sh [ARMSTUDY (build/armstudy)] [JOBS (2)] [SHARDS (4)]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
armstudy=${1:-$here/build/armstudy}
jobs=${2:-2}
shards=${3:-4}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
now() { date +%s.%N; }
calc() { awk "BEGIN { print $1 }"; }

fail() { echo "FAIL: $*"; exit 1; }
sweep=$here/reports/sweeps/placement-link-ratio.yaml
"$armstudy" sweep expand "$sweep" --out "$work/cases" 2>/dev/null
n=$(ls "$work/cases"/*.yaml | wc -l)
[ "$n" -ge 200 ] || fail "the bundled sweep has $n cases; expected at least 200"
"$armstudy" sweep expand "$sweep" --out "$work/cases" 2>"$work/expand2.log"
grep -q ", 0 file(s) written" "$work/expand2.log" || fail "re-expansion rewrote files: $(cat "$work/expand2.log")"
echo "machine: $(nproc) core(s), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "sweep: $n placement cases, --no-render, --jobs $jobs"

t0=$(now)
"$armstudy" run "$work/cases" --no-render --jobs "$jobs" --out "$work/one" 2>/dev/null
t1=$(now)
"$armstudy" merge "$work/one" 2>/dev/null
for ((i = 0; i < shards; i++)); do
  "$armstudy" run "$work/cases" --no-render --jobs "$jobs" --out "$work/sharded" --shard "$i/$shards" 2>/dev/null
done
t2=$(now)
"$armstudy" merge "$work/sharded" 2>/dev/null
t3=$(now)
for f in sweep.csv sweep.json; do
  cmp -s "$work/one/$f" "$work/sharded/$f" || fail "$f of the shards differs from the unsharded run"
done
[ "$(($(wc -l <"$work/one/sweep.csv") - 1))" -eq "$n" ] || fail "sweep.csv rows != $n"
[ "$(grep -c '<td class="name">' "$work/one/index.html")" -eq "$n" ] || fail "index.html does not list the $n cases"
[ "$(stat -c %s "$work/one/summary.md")" -lt $((1 << 20)) ] || fail "summary.md is 1 MiB or more"
/usr/bin/python3 "$here/scripts/validate_results.py" "$here/results.schema.json" "$work/one" >/dev/null ||
  fail "a results.json does not validate against the schema"

one=$(calc "$t1 - $t0"); sharded=$(calc "$t2 - $t1"); merge=$(calc "$t3 - $t2")
printf 'unsharded run:      %7.2f s  %7.1f cases/s\n' "$one" "$(calc "$n / $one")"
printf '%d shards in turn:   %7.2f s  %7.1f cases/s  (%.3f x the unsharded time)\n' "$shards" "$sharded" \
  "$(calc "$n / $sharded")" "$(calc "$sharded / $one")"
printf 'merge (%d cases):   %7.2f s  (%.3f x the unsharded run)\n' "$n" "$merge" "$(calc "$merge / $one")"
echo "checks: $n cases expanded stably, identical tables both ways, index, summary and schema"
