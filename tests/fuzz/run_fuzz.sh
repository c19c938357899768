#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# Builds the libFuzzer targets with clang (ASan + UBSan; only the loaders and readers, see
# CMakeLists.txt here) and runs each for a bounded time: case_loader_fuzz (which also reads
# each input as a report template of an ARMSTUDY_TEMPLATE_DIR folder) seeded with the
# bad-input corpus, the crash corpus, the bundled and test cases and sweeps, and the bundled
# and broken templates (tests/fuzz/templates);
# results_reader_fuzz seeded with the results.json and tolerances seeds, the crash corpus
# and the bundled CI tolerances. Exit 0: ran clean; 77: skipped (no clang with libFuzzer);
# else a finding (the crashing input is left in BUILD/artifacts/).
# usage: run_fuzz.sh SOURCE_DIR BUILD_DIR [SECONDS per target]
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
start=$(date +%s)
cmake --build "$build" -j2 >/dev/null
echo "fuzz: built the fuzz targets in $(($(date +%s) - start)) s"

# fuzz TARGET SEEDS...: a fresh working corpus (libFuzzer adds to the first folder) from the
# seeds, then TARGET for $seconds
fuzz() {
  local target=$1 corpus="$build/corpus-$1" artifacts="$build/artifacts/" start
  shift
  rm -rf "$corpus"
  mkdir -p "$corpus" "$artifacts"
  echo "fuzz: running $build/$target for ${seconds} s, seeded with $*"
  start=$(date +%s)
  "$build/$target" -max_total_time="$seconds" -timeout=100 -rss_limit_mb=3072 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix="$artifacts" "$corpus" "$@" \
    2>"$build/$target.log" || {
    tail -60 "$build/$target.log"
    echo "fuzz: $target FOUND a problem; the input is in $artifacts"
    exit 1
  }
  grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|^#[0-9]+ *DONE" "$build/$target.log" || true
  echo "fuzz: $target ran clean for $(($(date +%s) - start)) s"
}
fuzz case_loader_fuzz "$src/tests/cases/bad" "$src/tests/fuzz/corpus" "$src/reports/cases" \
  "$src/reports/sweeps" "$src/tests/sweeps" "$src/templates" "$src/tests/fuzz/templates"
fuzz results_reader_fuzz "$src/tests/fuzz/seeds" "$src/tests/fuzz/corpus" "$src/examples/ci"
