#!/usr/bin/env bash
# Sweep throughput benchmark: the bundled sweep (reports/sweeps/placement-link-ratio.yaml)
# without rendering, run (a) once with --jobs J, (b) as N shards one after the other, each
# with --jobs J, then merged. Prints cases per second and the overhead of sharding and
# merging as ratios measured in this one run (machines are shared and noisy: compare the
# ratios, not the absolute figures across runs).
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

"$armstudy" sweep expand "$here/reports/sweeps/placement-link-ratio.yaml" --out "$work/cases" 2>/dev/null
n=$(ls "$work/cases"/*.yaml | wc -l)
echo "machine: $(nproc) core(s), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "sweep: $n placement cases, --no-render, --jobs $jobs"

t0=$(now)
"$armstudy" run "$work/cases" --no-render --jobs "$jobs" --out "$work/one" 2>/dev/null
t1=$(now)
for ((i = 0; i < shards; i++)); do
  "$armstudy" run "$work/cases" --no-render --jobs "$jobs" --out "$work/sharded" --shard "$i/$shards" 2>/dev/null
done
t2=$(now)
"$armstudy" merge "$work/sharded" 2>/dev/null
t3=$(now)
cmp -s "$work/one/sweep.csv" "$work/sharded/sweep.csv" || { echo "sweep tables differ"; exit 1; }

one=$(calc "$t1 - $t0"); sharded=$(calc "$t2 - $t1"); merge=$(calc "$t3 - $t2")
printf 'unsharded run:      %7.2f s  %7.1f cases/s\n' "$one" "$(calc "$n / $one")"
printf '%d shards in turn:   %7.2f s  %7.1f cases/s  (%.3f x the unsharded time)\n' "$shards" "$sharded" \
  "$(calc "$n / $sharded")" "$(calc "$sharded / $one")"
printf 'merge (%d cases):   %7.2f s  (%.3f x the unsharded run)\n' "$n" "$merge" "$(calc "$merge / $one")"
