#!/usr/bin/env bash
# Builds the libFuzzer target of the case and sweep loaders with clang (ASan + UBSan) and
# runs it for a bounded time, seeded with the bad-input corpus and the bundled cases and
# sweeps. Exit 0: ran clean; 77: skipped (no clang with libFuzzer); else a finding (the
# crashing input is left in BUILD/artifacts/).
# usage: run_fuzz.sh SOURCE_DIR BUILD_DIR [SECONDS]
set -euo pipefail
src=$1 build=$2 seconds=${3:-60}

if ! command -v clang++ >/dev/null; then
  echo "fuzz: skipped: clang++ is not installed (apt-get install clang libclang-rt-14-dev)"
  exit 77
fi
probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
printf 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }\n' > "$probe/p.cpp"
if ! clang++ -fsanitize=fuzzer,address,undefined "$probe/p.cpp" -o "$probe/p" 2>"$probe/err"; then
  echo "fuzz: skipped: clang++ cannot build with -fsanitize=fuzzer (install libclang-rt-14-dev):"
  head -3 "$probe/err"
  exit 77
fi

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$src/tests/fuzz" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ "${launcher[@]}" >/dev/null
cmake --build "$build" -j2 >/dev/null

# a fresh working corpus (libFuzzer adds to the first folder) from the seeds
corpus="$build/corpus" artifacts="$build/artifacts/"
mkdir -p "$corpus" "$artifacts"
seeds=("$src/tests/cases/bad" "$src/reports/cases" "$src/reports/sweeps")
echo "fuzz: running $build/case_loader_fuzz for ${seconds} s, seeded with ${seeds[*]}"
start=$(date +%s)
"$build/case_loader_fuzz" -max_total_time="$seconds" -timeout=100 -rss_limit_mb=3072 \
  -max_len=65536 -print_final_stats=1 -artifact_prefix="$artifacts" "$corpus" "${seeds[@]}" \
  2>"$build/fuzz.log" || {
  tail -60 "$build/fuzz.log"
  echo "fuzz: FOUND a problem; the input is in $artifacts"
  exit 1
}
grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|^#[0-9]+ *DONE" "$build/fuzz.log" || true
echo "fuzz: ran clean for $(( $(date +%s) - start )) s"
