// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Core inverse dynamics throughput (samples per second), 2-link and 4-link chains.
#include <benchmark/benchmark.h>

#include <random>

#include "core/dynamics.hpp"
#include "testing/arms.hpp"

namespace armstudy::core {
namespace {

void run_inverse_dynamics(benchmark::State& state, const PlanarChain& chain) {
  std::mt19937 rng(1);
  const int n = chain.num_links();
  std::vector<JointVector> q, qd, qdd;
  for (int i = 0; i < 256; ++i) {
    q.push_back(testing::random_joints(rng, n, 3));
    qd.push_back(testing::random_joints(rng, n, 3));
    qdd.push_back(testing::random_joints(rng, n, 3));
  }
  size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(inverse_dynamics(chain, q[k], qd[k], qdd[k]));
    k = (k + 1) & 255;
  }
  state.counters["samples_per_s"] =
      benchmark::Counter(state.iterations(), benchmark::Counter::kIsRate);
}

void BM_InverseDynamics2Link(benchmark::State& s) {
  run_inverse_dynamics(s, testing::thesis_arm());
}
void BM_InverseDynamics4Link(benchmark::State& s) { run_inverse_dynamics(s, testing::tray_arm()); }
BENCHMARK(BM_InverseDynamics2Link);
BENCHMARK(BM_InverseDynamics4Link);

}  // namespace
}  // namespace armstudy::core
