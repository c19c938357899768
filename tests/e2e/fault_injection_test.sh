#!/usr/bin/env bash
# Crash safety: a run killed (SIGKILL, strace's fault injection) at each of its renames,
# file writes, unlinks and folder creations and removals must never cost the earlier
# report: after each kill, the next run finds the case's report complete, the earlier one
# or the new one, and nothing half-written or hidden is left. Run twice: with the folder
# swap in one step (renameat2 RENAME_EXCHANGE) and with the two-rename swap that file
# systems without it (NFS) get, forced by making renameat2 fail with EINVAL.
#
# The same for a full disk: at each of those writes, ENOSPC instead of the kill: the run
# exits 3 saying "No space left on device", and leaves no temporary file and the earlier
# report as it was.
#
# usage: fault_injection_test.sh SOURCE_DIR ARMSTUDY
set -euo pipefail
src=$1
bin=$2
command -v strace >/dev/null || { echo "strace is missing (scripts/packages.txt)"; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/armstudy_faults.XXXXXX")
trap 'rm -rf "$work"' EXIT
export LP_NUM_THREADS=1
check="python3 $src/tests/e2e/crash_check.py"

# the case (a placement study on a coarse grid: a run takes about 0.05 s of CPU and writes
# 13 files) and a second case whose run is "the next run"
cat > "$work/case.yaml" <<'EOF'
study: placement
name: crash-case
placement:
  length_fraction: 0.8
  programs: [cycloidal]
  configurations: [1]
  nx_s: 4
  phi_step_deg: 15
  samples: 201
  refine: false
  threads: 1
  map: {nx: 4, ny: 3}
EOF
sed 's/^name: .*/name: next-run/' "$work/case.yaml" > "$work/next.yaml"
"$bin" run --no-render --out "$work/pristine" "$work/case.yaml" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
sha_old=$(sha256sum "$work/case.yaml" | cut -d' ' -f1)
echo "# changed: the new report differs from the earlier one" >> "$work/case.yaml"
sha_new=$(sha256sum "$work/case.yaml" | cut -d' ' -f1)

# the syscalls of one uninterrupted run, in order (-y: the file behind each descriptor)
calls=${ARMSTUDY_FAULT_CALLS:-"rename,renameat,renameat2,write,unlink,unlinkat,rmdir,mkdir,mkdirat"}
cp -a "$work/pristine" "$work/count"
strace -f -qq --seccomp-bpf -y -o "$work/trace" -e trace="$calls" \
  "$bin" run --no-render --out "$work/count" "$work/case.yaml" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
[ "$(cut -d' ' -f1 "$work/trace" | sort -u | wc -l)" = 1 ] || { echo "expected one thread"; exit 1; }

# the N of each syscall to kill at: every one, except writes to the terminal or log (only
# the writes into the output folder matter, and a kill at those is covered by the next)
targets() {  # syscall -> the invocation numbers to inject at
  awk -v sc="$1" -v dir="$work/count" '
    { sub(/^[0-9]+ +/, "") }
    index($0, sc "(") == 1 { n++; if (sc != "write" || index($0, dir)) print n }' "$work/trace"
}

runs=0
failures=0
# a full disk at write N: exit 3 saying why, nothing left behind, the earlier report as it was
full_disk() {  # N
  local n=$1 out="$work/out"
  rm -rf "$out"
  cp -a "$work/pristine" "$out"
  local code=0
  strace -f -qq --seccomp-bpf -o /dev/null -e trace=write -e inject=write:error=ENOSPC:when="$n" \
    "$bin" run --no-render --out "$out" "$work/case.yaml" > "$work/full.log" 2>&1 || code=$?
  runs=$((runs + 1))
  local state
  state=$($check "$out" crash-case "$sha_old" "$sha_new" --no-hidden || true)
  # a write into the case's scratch folder: the earlier report stays (a write after the
  # swap, of index.html, summary.md or junit.xml, fails with the new report in place)
  if [ $code != 3 ] || ! grep -q ": No space left on device" "$work/full.log" || [ -n "$state" ] ||
     { grep -q "ERROR: crash-case" "$work/full.log" &&
       ! cmp -s "$out/crash-case/results.json" "$work/pristine/crash-case/results.json"; }; then
    echo "FAIL (disk full at write #$n): exit $code"; echo "$state"; cat "$work/full.log"
    failures=$((failures + 1))
  fi
}

one() {  # mode syscall N
  local mode=$1 sc=$2 n=$3 out="$work/out"
  rm -rf "$out"
  cp -a "$work/pristine" "$out"
  local force=()
  [ "$mode" = two-renames ] && force=(-e inject=renameat2:error=EINVAL)
  # (in a subshell whose stderr is dropped: bash reports every killed child there; no
  # --seccomp-bpf: strace 6.1 then delivers no injected signal)
  local code=0
  (strace -f -qq -o /dev/null -e trace="$sc" "${force[@]}" -e inject="$sc":signal=SIGKILL:when="$n" \
    "$bin" run --no-render --out "$out" "$work/case.yaml" > "$work/killed.log" 2>&1; exit $?) 2>/dev/null || code=$?
  runs=$((runs + 1))
  if [ $code != 137 ]; then
    echo "FAIL ($mode, kill at $sc #$n): the run was not killed (exit $code)"; cat "$work/killed.log"
    failures=$((failures + 1))
    return
  fi
  # what the kill left: the run-level files complete; the report complete or, with the
  # two-rename swap, waiting in the scratch folder for the next run to put it back
  local state
  state=$($check "$out" crash-case "$sha_old" "$sha_new" || true)
  if [ -n "$state" ] && ! { [ "$mode" = two-renames ] && [ ! -e "$out/crash-case" ]; }; then
    echo "FAIL ($mode, kill at $sc #$n) right after the kill:"; echo "$state"
    failures=$((failures + 1))
    return
  fi
  if ! "$bin" run --no-render --out "$out" "$work/next.yaml" > "$work/next.log" 2>&1; then
    echo "FAIL ($mode, kill at $sc #$n): the next run failed:"; cat "$work/next.log"
    failures=$((failures + 1))
    return
  fi
  if ! state=$($check "$out" crash-case "$sha_old" "$sha_new" --no-hidden); then
    echo "FAIL ($mode, kill at $sc #$n) after the next run:"; echo "$state"; cat "$work/next.log"
    failures=$((failures + 1))
  fi
}

for mode in exchange two-renames; do
  for sc in ${calls//,/ }; do
    # the swap's way only matters from the swap on: writes (all before it, or of
    # run-level files after it) are killed in the first pass only
    [ "$mode" = two-renames ] && { [ "$sc" = renameat2 ] || [ "$sc" = write ]; } && continue
    for n in $(targets "$sc"); do one "$mode" "$sc" "$n"; done
  done
done
for n in $(targets write); do full_disk "$n"; done
# the earlier report really was replaced when nothing was killed
$check "$work/count" crash-case "$sha_new" "$sha_new" --no-hidden
echo "fault injection: $runs killed runs, $failures failure(s)"
for sc in ${calls//,/ }; do printf '  %s: %s\n' "$sc" "$(targets "$sc" | wc -l)"; done
[ "$failures" = 0 ]
