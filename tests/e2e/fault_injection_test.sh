#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
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
# Beside the case, the output folder holds a user's folder and file and a link to an outside
# folder holding *.part-N files and .armstudy-* folders: after every kill and the next run,
# each of them is as it was, byte for byte.
#
# usage: fault_injection_test.sh SOURCE_DIR ARMSTUDY
set -euo pipefail
src=$1
bin=$2
command -v strace >/dev/null || { echo "strace is missing (scripts/packages.txt)"; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/armstudy_faults.XXXXXX")
trap 'rm -rf "$work"' EXIT
export LP_NUM_THREADS=1
# one checker for every state (crash_check.py --serve): a Python start per check took a
# third of the test's time
coproc CHECKER { python3 "$src/tests/e2e/crash_check.py" --serve; }
# sets $state to what is wrong with OUT's case folder crash-case ("" when complete)
check() {  # OUT SHA_OLD SHA_NEW [--no-hidden] [--aside-ok]
  local IFS=$'\t' line
  printf '%s\n' "$1"$'\t'crash-case$'\t'"${*:2}" >&"${CHECKER[1]}"
  state=""
  while true; do
    IFS= read -r line <&"${CHECKER[0]}" || { echo "FAIL: crash_check.py stopped"; exit 1; }
    [ "$line" = . ] && break
    state+="$line"$'\n'
  done
}

# the case (a placement study on the coarsest grid that still solves: a run takes about
# 0.1 s of CPU, mostly armstudy's start, and writes 17 files) and a second case whose run is
# "the next run"
cat > "$work/case.yaml" <<'EOF'
study: placement
name: crash-case
placement:
  length_fraction: 0.8
  programs: [cycloidal]
  configurations: [1]
  nx_s: 3
  phi_step_deg: 30
  samples: 51
  refine: false
  threads: 1
  map: {nx: 2, ny: 2}
EOF
sed 's/^name: .*/name: next-run/' "$work/case.yaml" > "$work/next.yaml"
"$bin" run --no-render --out "$work/pristine" "$work/case.yaml" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }

# what is not armstudy's: a user's folder and file beside the cases, and a link in the
# output folder to an outside folder holding what looks like killed runs' leftovers
# (*.part-N files, stale .armstudy-* scratch folders, one with a "report" to put back)
mkdir -p "$work/pristine/user-data/sub" "$work/outside/.armstudy-host-1-0badc0de/old/crash-case" \
  "$work/outside/.armstudy-host-2-0badc0de.removing"
echo "a user's notes" > "$work/pristine/user-data/notes.txt"
echo "hidden" > "$work/pristine/user-data/.config"
echo "data" > "$work/pristine/user-data/sub/data.part-1-2"
echo "beside the cases" > "$work/pristine/notes.txt"
echo "{}" > "$work/outside/.armstudy-host-1-0badc0de/old/crash-case/results.json"
echo "a download" > "$work/outside/video.part-1"
echo "a user's file" > "$work/outside/summary.md.part-1-2"
find "$work/outside" "$work/pristine/user-data" -exec touch -h -d '1 hour ago' {} +
ln -s "$work/outside" "$work/pristine/outside-link"
# every entry of the user's (links not followed) with its type and checksum
user_files() {  # OUT
  (cd "$1" && find user-data notes.txt outside-link "$work/outside" -printf '%p %y %l\n' |
     sort && find user-data notes.txt "$work/outside" -type f -print0 | sort -z |
     xargs -0 sha256sum)
}
users=$(user_files "$work/pristine")
# "" when the user's files are as they were, else what changed
user_changes() {  # OUT
  diff <(echo "$users") <(user_files "$1") || true
}
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
  check "$out" "$sha_old" "$sha_new" --no-hidden
  state+=$(user_changes "$out")
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
  local changed
  changed=$(user_changes "$out")
  if [ -n "$changed" ]; then
    echo "FAIL ($mode, kill at $sc #$n): the user's files changed:"; echo "$changed"
    failures=$((failures + 1))
    return
  fi
  local aside=()
  [ "$mode" = two-renames ] && aside=(--aside-ok)
  check "$out" "$sha_old" "$sha_new" "${aside[@]}"
  if [ -n "$state" ]; then
    echo "FAIL ($mode, kill at $sc #$n) right after the kill:"; echo "$state"
    failures=$((failures + 1))
    return
  fi
  if ! "$bin" run --no-render --out "$out" "$work/next.yaml" > "$work/next.log" 2>&1; then
    echo "FAIL ($mode, kill at $sc #$n): the next run failed:"; cat "$work/next.log"
    failures=$((failures + 1))
    return
  fi
  check "$out" "$sha_old" "$sha_new" --no-hidden
  if [ -n "$state" ]; then
    echo "FAIL ($mode, kill at $sc #$n) after the next run:"; echo "$state"; cat "$work/next.log"
    failures=$((failures + 1))
  elif changed=$(user_changes "$out") && [ -n "$changed" ]; then
    echo "FAIL ($mode, kill at $sc #$n): the next run changed the user's files:"; echo "$changed"
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
# the earlier report really was replaced when nothing was killed, the user's files kept
check "$work/count" "$sha_new" "$sha_new" --no-hidden
[ -z "$state" ] || { echo "FAIL: the uninterrupted run:"; echo "$state"; exit 1; }
[ -z "$(user_changes "$work/count")" ] || { echo "FAIL: a run changed the user's files"; user_changes "$work/count"; exit 1; }
echo "fault injection: $runs killed runs, $failures failure(s)"
for sc in ${calls//,/ }; do printf '  %s: %s\n' "$sc" "$(targets "$sc" | wc -l)"; done
[ "$failures" = 0 ]
