# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# Shared by slurm_cluster_test.sh and ssh_parallel_test.sh (sourced, not run): the root
# check, the temporary folder, the case subset with its unsharded reference run, and the
# check that nothing was written outside the temporary folder.
# The sourcing script sets src and armstudy, calls need_root, then make_work (sets work).

export LP_NUM_THREADS=1
fail() { echo "FAIL: $*" >&2; exit 1; }
now() { date +%s.%N; }
calc() { awk "BEGIN { print $1 }"; }

# The daemons (munged, slurmctld, slurmd, sshd) run as root with their state in the
# temporary folder; without root the test cannot start them and says so (CTest: skipped).
need_root() {
  if [ "$(id -u)" -ne 0 ]; then
    echo "SKIP: $1 needs root to start its daemons (CI runs as root); not run here"
    exit 77
  fi
  local cmd
  for cmd in "${@:2}"; do
    command -v "$cmd" >/dev/null || fail "$cmd not found: install scripts/packages.txt (scripts/setup.sh)"
  done
}

# wait_for SECONDS WHAT COMMAND...: polls COMMAND every 0.5 s until it succeeds
wait_for() {
  local limit=$1 what=$2 start=$SECONDS
  shift 2
  until "$@" >/dev/null 2>&1; do
    [ $((SECONDS - start)) -lt "$limit" ] || return 1
    sleep 0.5
  done
  echo "  $what after $((SECONDS - start)) s"
}

# make_work: the temporary folder $work, with the marker for check_no_leaks; it is 0711
# because munged wants every folder above its socket searchable by all its clients
make_work() {
  work=$(mktemp -d)
  chmod 711 "$work"
  touch "$work/.started"
  export PARALLEL_HOME=$work/parallel TMPDIR=$work  # GNU Parallel's files stay in here
}

# make_cases COUNT: the tests' sweep (tests/sweeps/placement-small.yaml, 24 cases)
# expanded into $work/all, every k-th case (sorted by name) copied into $work/sweep-cases
# so that COUNT cases spread over the whole sweep, and the unsharded reference run of them
# in $work/one (merged). Sets local_seconds.
make_cases() {
  local count=$1 sweep="$src/tests/sweeps/placement-small.yaml"
  "$armstudy" sweep expand "$sweep" --out "$work/all" 2>"$work/expand.log" || { cat "$work/expand.log"; fail "expand"; }
  local files=("$work/all"/*.yaml)
  local n=${#files[@]} step i
  [ "$n" -ge "$count" ] || fail "the tests' sweep has $n cases; expected at least $count"
  step=$((n / count))
  mkdir "$work/sweep-cases"
  for ((i = 0; i < count; i++)); do cp "${files[$((i * step))]}" "$work/sweep-cases/"; done
  local_run one
  local_seconds=$seconds
  [ "$(($(wc -l <"$work/one/sweep.csv") - 1))" -eq "$count" ] || fail "the reference sweep.csv has not $count rows"
  printf '  unsharded local run of %d cases (--jobs 2) and merge: %.1f s\n' "$count" "$local_seconds"
}

# local_run NAME: the cases run unsharded on this machine with --jobs 2 into $work/NAME
# and merged; sets seconds (wall time)
local_run() {
  local t0 t1
  t0=$(now)
  "$armstudy" run "$work/sweep-cases" --no-render --jobs 2 --out "$work/$1" 2>"$work/$1.log" ||
    { tail "$work/$1.log"; fail "unsharded run"; }
  "$armstudy" merge "$work/$1" 2>"$work/merge-$1.log" || { cat "$work/merge-$1.log"; fail "merge"; }
  t1=$(now)
  seconds=$(calc "$t1 - $t0")
}

# overhead WAY SECONDS SHARDS: WAY's wall time against (a) the unsharded local run (--jobs
# 2) before it and once more after it (the machine may be shared: the two show how much
# its load drifted meanwhile) and (b) the same SHARDS run as local processes by GNU
# Parallel -j2 (what WAY does, without the scheduler or ssh)
overhead() {
  local_run one-again
  same_tables "$work/one-again"
  local mean t0 t1 sharded
  mean=$(calc "($local_seconds + $seconds) / 2")
  t0=$(now)
  parallel -j2 "$armstudy" run "$work/sweep-cases" --no-render --out "$work/par-local" --shard {}/"$3" \
    ::: $(seq 0 $(($3 - 1))) 2>"$work/par-local.log" && "$armstudy" merge "$work/par-local" 2>>"$work/par-local.log" ||
    { tail "$work/par-local.log"; fail "local GNU Parallel run"; }
  t1=$(now)
  same_tables "$work/par-local"
  sharded=$(calc "$t1 - $t0")
  printf 'throughput, %d cases: %s %.1f s (%.1f cases/s)\n' "$cases" "$1" "$2" "$(calc "$cases / $2")"
  printf '  %.2f x the unsharded local run + merge (%.1f s before, %.1f s after)\n' \
    "$(calc "$2 / $mean")" "$local_seconds" "$seconds"
  printf '  %.2f x its %d shards as local processes, GNU Parallel -j2, + merge (%.1f s)\n' \
    "$(calc "$2 / $sharded")" "$3" "$sharded"
}

# same_tables DIR: DIR's merged sweep tables equal the unsharded run's byte for byte
same_tables() {
  local f
  for f in sweep.csv sweep.json; do
    [ -s "$1/$f" ] || fail "$1 has no $f"
    cmp "$work/one/$f" "$1/$f" || fail "$f of $1 differs from the unsharded run"
  done
}

# check_no_leaks PATTERN: no file whose path matches PATTERN (grep -E) was created or
# changed outside the temporary folder since it was made (the daemons' default places
# under /etc, /run, /var and the home folder are where a stray file would land)
check_no_leaks() {
  local leaks
  leaks=$( (find /etc /run /var -xdev -newer "$work/.started"; find "$HOME" -maxdepth 2 -newer "$work/.started") 2>/dev/null | grep -E "$1" || true)
  [ -z "$leaks" ] || fail "files written outside the temporary folder: $leaks"
}
