#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# The tests' sweep (tests/sweeps/placement-small.yaml: the bundled sweep's two axes, 24
# cheap cases), expanded and run (a) in one run, (b) as 4 shards in a scrambled order with
# one shard killed after its first case and re-run, (c) by GNU Parallel with 2 jobs, (d)
# through the Slurm array script's body with the scheduler's variables set. Every way must
# merge into byte-identical sweep tables; every results.json must validate against the
# schema and a broken one must not. The bundled 200-case sweep is scripts/bench_sweep.sh's.
# usage: sweep_scale_out_test.sh SOURCE_DIR ARMSTUDY
set -euo pipefail
src=$1
armstudy=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export LP_NUM_THREADS=1
fail() { echo "FAIL: $*"; exit 1; }

sweep="$src/tests/sweeps/placement-small.yaml"
"$armstudy" sweep expand "$sweep" --out "$work/cases" 2>"$work/expand.log" || { cat "$work/expand.log"; fail "expand"; }
n=$(ls "$work/cases"/*.yaml | wc -l)
[ "$n" -eq 24 ] || fail "the tests' sweep has $n cases; expected 6 x 4 = 24"
# expanding again writes nothing new and names are content hashes: stable
"$armstudy" sweep expand "$sweep" --out "$work/cases" 2>"$work/expand2.log"
grep -q ", 0 file(s) written" "$work/expand2.log" || fail "re-expansion rewrote files: $(cat "$work/expand2.log")"
"$armstudy" list "$work/cases" >"$work/list1"
"$armstudy" list "$work/cases" >"$work/list2"
cmp -s "$work/list1" "$work/list2" || fail "list is not stable"
[ "$(wc -l <"$work/list1")" -eq "$n" ] || fail "list printed $(wc -l <"$work/list1") ids for $n cases"
sort -c "$work/list1" || fail "list is not sorted"

# (a) one unsharded run
"$armstudy" run "$work/cases" --no-render --jobs 2 --out "$work/one" 2>"$work/one.log" || { tail "$work/one.log"; fail "unsharded run"; }
"$armstudy" merge "$work/one" 2>"$work/merge-one.log" || { cat "$work/merge-one.log"; fail "merge"; }
[ -s "$work/one/sweep.csv" ] || fail "no sweep.csv"
[ "$(($(wc -l <"$work/one/sweep.csv") - 1))" -eq "$n" ] || fail "sweep.csv rows != $n"
# the sweep report plots the key figures over the sweep's axes; the index lists every case
[ -s "$work/one/sweep/index.html" ] || fail "no sweep report"
plots=$(ls "$work/one/sweep"/*.svg | wc -l)
[ "$plots" -ge 1 ] || fail "the sweep report has no plots"
grep -q "Key figures over arm.links\[2\].length" "$work/one/sweep/index.html" || fail "sweep report not over the L2 axis"
[ "$(grep -c '<td class="name">' "$work/one/index.html")" -eq "$n" ] || fail "index.html does not list the $n cases"
grep -q 'href="sweep/index.html"' "$work/one/index.html" || fail "index.html does not link the sweep report"

# (b) 4 shards in the order 2, 0, 3, then shard 1 killed (SIGKILL) after its first case
# and run again
for i in 2 0 3; do
  "$armstudy" run "$work/cases" --no-render --out "$work/sharded" --shard "$i/4" 2>>"$work/shards.log" ||
    { tail "$work/shards.log"; fail "shard $i/4"; }
done
per_shard=$(( $(ls "$work/sharded"/*/results.json | wc -l) / 3 ))
[ "$per_shard" -ge 3 ] || fail "a shard has $per_shard case(s); expected 24 / 4"
# (each case's "done:" line is on stdout, the progress on stderr: both into the log)
"$armstudy" run "$work/cases" --no-render --jobs 1 --out "$work/sharded" --shard 1/4 >"$work/killed.log" 2>&1 &
killed_pid=$!
until grep -qs '^done:' "$work/killed.log"; do
  kill -0 "$killed_pid" 2>/dev/null || { cat "$work/killed.log"; fail "shard 1/4 ended before its first case was done"; }
  sleep 0.01
done
kill -KILL "$killed_pid"
wait "$killed_pid" 2>/dev/null && fail "shard 1/4 was not killed: it had finished (cases too quick for this check)"
leftovers=$(find "$work/sharded" -maxdepth 1 -name '.armstudy-*' | wc -l)
[ "$leftovers" -ge 1 ] || fail "the killed shard left no scratch folder: it was not killed mid-run"
"$armstudy" run "$work/cases" --no-render --out "$work/sharded" --shard 1/4 2>"$work/rerun.log" ||
  { tail "$work/rerun.log"; fail "re-run of the killed shard"; }
grep -q "^removed [0-9]* temporary folder" "$work/rerun.log" || fail "the re-run did not remove the killed shard's scratch folder: $(cat "$work/rerun.log")"
skipped=$(grep -o '^skipped [0-9]*' "$work/rerun.log" | cut -d' ' -f2)
[ -n "$skipped" ] && [ "$skipped" -ge 1 ] && [ "$skipped" -lt "$per_shard" ] ||
  fail "the re-run skipped '${skipped}' of the killed shard's $per_shard cases; expected those it had finished"
"$armstudy" merge "$work/sharded" 2>"$work/merge-sharded.log" || { cat "$work/merge-sharded.log"; fail "merge of the shards"; }
for f in sweep.csv sweep.json; do
  cmp "$work/one/$f" "$work/sharded/$f" || fail "$f of the sharded run differs from the unsharded run"
done
# a re-run skips what exists
"$armstudy" run "$work/cases" --no-render --out "$work/sharded" --shard 0/4 2>"$work/skip.log"
grep -q "skipped" "$work/skip.log" || fail "a re-run did not skip finished cases: $(cat "$work/skip.log")"
left=$(find "$work/sharded" -maxdepth 1 -name ".armstudy-*" | wc -l)
[ "$left" -eq 0 ] || fail "$left scratch folder(s) of the killed shard remain after the re-run"
echo "killed shard left $leftovers scratch folder(s) and finished $skipped case(s); the re-run cleaned them and ran the rest"

# (c) GNU Parallel, 2 jobs on this machine (the one-liner of docs/scale-out.md)
parallel -j2 "$armstudy" run "$work/cases" --no-render --out "$work/par" --shard {}/2 ::: 0 1 2>"$work/par.log" ||
  { grep -v '^done:\|^  ' "$work/par.log" | tail -20; fail "GNU Parallel run"; }
"$armstudy" merge "$work/par" 2>"$work/par-merge.log" || { cat "$work/par-merge.log"; fail "merge of the GNU Parallel run"; }
cmp "$work/one/sweep.csv" "$work/par/sweep.csv" || fail "GNU Parallel run differs"

# (d) the Slurm array script's body, as the scheduler would run it for 2 tasks
for task in 0 1; do
  SLURM_ARRAY_TASK_ID=$task SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_COUNT=2 SLURM_CPUS_PER_TASK=1 \
    ARMSTUDY="$armstudy" bash "$src/examples/slurm/sweep.sbatch" "$work/cases" "$work/slurm" 2>>"$work/slurm.log"
done
ARMSTUDY="$armstudy" bash "$src/examples/slurm/merge.sbatch" "$work/slurm" 2>/dev/null
cmp "$work/one/sweep.csv" "$work/slurm/sweep.csv" || fail "Slurm run differs"

# summary.md and junit.xml agree with the checks in results.json
/usr/bin/python3 - "$work/one" <<'PY' || fail "summary/junit do not match results.json"
import json, pathlib, sys, xml.etree.ElementTree as ET
d = pathlib.Path(sys.argv[1])
results = [json.loads(p.read_text()) for p in sorted(d.glob("*/results.json"))]
expected = sum(1 + len(r["checks"]) for r in results)
root = ET.parse(d / "junit.xml").getroot()
cases = root.findall(".//testcase")
assert len(cases) == expected == int(root.get("tests")), (len(cases), expected)
fails = sum((r["status"] != "solved") + sum(not c["passed"] for c in r["checks"]) for r in results)
assert int(root.get("failures")) == fails == len(root.findall(".//failure"))
md = (d / "summary.md").read_text()
assert md.startswith(f"# armstudy: {len(results)} case(s)"), md[:80]
assert len(md.encode()) < 1 << 20
PY

# every results.json validates; a broken one does not
/usr/bin/python3 "$src/scripts/validate_results.py" "$src/results.schema.json" "$work/one" >/dev/null || fail "schema"
dirs=("$work/one"/placement-*/)  # no pipe: with pipefail, head closing early fails ls
one=${dirs[0]}
mkdir -p "$work/broken/x" && sed 's/"status": "solved"/"status": "maybe"/' "$one/results.json" >"$work/broken/x/results.json"
if /usr/bin/python3 "$src/scripts/validate_results.py" "$src/results.schema.json" "$work/broken" >/dev/null; then
  fail "a broken results.json validated"
fi
echo "sweep of $n cases: unsharded, 4 shards (one killed and re-run), GNU Parallel and Slurm give identical tables"
