// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Loading hostile case text: the file checks (UTF-8, structure, alias expansion) and the
// duplicate/unknown key checks are linear in the number of keys (they were quadratic:
// 40 000 keys took 5 s, 80 000 took 18 s).
#include <benchmark/benchmark.h>

#include <string>

#include "cases/yaml_reader.hpp"

namespace {
using namespace armstudy::cases;

std::string keys_text(int n) {
  std::string text;
  for (int i = 0; i < n; ++i) text += "k" + std::to_string(i) + ": 1\n";
  return text;
}

// parse, check and judge every key of one mapping of n unknown keys
void BM_UnknownKeyChecks(benchmark::State& state) {
  const std::string text = keys_text(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Diagnostics d("f.yaml");
    const auto root = parse_text(text, d);
    Map m(*root, d, "");
    m.get("study");
    m.finish();
    benchmark::DoNotOptimize(d.count());
  }
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_UnknownKeyChecks)
    ->Arg(10000)
    ->Arg(40000)
    ->Arg(80000)
    ->Complexity()
    ->Unit(benchmark::kMillisecond);

// the structure check of an alias bomb stops at the node limit, whatever its expansion
void BM_AliasBombRefused(benchmark::State& state) {
  std::string text = "a: &a [x, x, x, x, x, x, x, x, x, x]\n";
  std::string prev = "a";
  for (const char* l : {"b", "c", "d", "e", "f", "g", "h", "i"}) {
    text += std::string(l) + ": &" + l + " [";
    for (int i = 0; i < 10; ++i) text += (i ? ", *" : "*") + prev;
    text += "]\n";
    prev = l;
  }
  for (auto _ : state) {
    Diagnostics d("f.yaml");
    benchmark::DoNotOptimize(check_yaml_source(text, d));
  }
}
BENCHMARK(BM_AliasBombRefused)->Unit(benchmark::kMicrosecond);

}  // namespace
