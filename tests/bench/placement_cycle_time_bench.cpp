// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The placement study's cycle-time objective on example 3's line (L = 0.5 Lmax,
// the thesis's arm, configuration 1) under |qd| <= (3, 4) rad/s, |tau| <= (20, 8) N m:
//   BM_CycleTimeMapNode/<grid points>: one map node, the exact solver once on that grid
//     (cycle_time_on_grid): the cost per placement per core;
//   BM_CycleTimeMap/<nx>/<threads>: the whole map of nx x nx/2 root locations (the
//     admissible ones solved, 100 grid points each) on that many threads; the counter
//     placements_per_s is admissible nodes per wall second;
//   BM_CycleTimeConverged: the time-optimal study at one placement (1000 points, its
//     re-check and extrapolation): the refined optimum's last step;
//   BM_CycleTimeFastEnergy: the fastest motion's energy at one placement (the exact solver
//     on 1000 and 1999 points, the energy of each profile): what each optimum adds.
// Measured, never asserted.
#include <benchmark/benchmark.h>

#include "studies/placement/cycle_time_map.hpp"
#include "studies/placement/geometry.hpp"
#include "testing/arms.hpp"

namespace {
using namespace armstudy::studies::placement;

Spec bench_spec(int nx, int threads) {
  Spec s;
  s.chain = armstudy::testing::thesis_arm();
  s.length = 0.5 * annulus(0.4, 0.2).lmax;
  s.map_nx = nx;
  s.map_ny = nx / 2;
  s.threads = threads;
  CycleTimeSpec ct;
  ct.velocity_limit = armstudy::studies::time_optimal::joint_pair(3.0, 4.0);
  ct.torque_limit = armstudy::studies::time_optimal::joint_pair(20.0, 8.0);
  s.cycle_time = ct;
  return s;
}

// an admissible placement near the middle of the map's region
constexpr double kXs = 0.45, kPhi = 2.2;

void BM_CycleTimeMapNode(benchmark::State& state) {
  const Spec s = bench_spec(40, 1);
  double t = 0;
  for (auto _ : state) t = cycle_time_on_grid(s, 1, kXs, kPhi, int(state.range(0)));
  state.counters["time_s"] = t;
}
BENCHMARK(BM_CycleTimeMapNode)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond);

void BM_CycleTimeMap(benchmark::State& state) {
  const Spec s = bench_spec(int(state.range(0)), int(state.range(1)));
  int solved = 0;
  for (auto _ : state) solved = cycle_time_map(s, 1).solved;
  state.counters["nodes_solved"] = solved;
  state.counters["placements_per_s"] =
      benchmark::Counter(double(solved), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_CycleTimeMap)
    ->Args({40, 1})
    ->Args({80, 1})
    ->Args({80, 2})
    ->Args({200, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_CycleTimeConverged(benchmark::State& state) {
  const Spec s = bench_spec(40, 1);
  double t = 0;
  for (auto _ : state) t = converged_cycle_time(s, 1, kXs, kPhi).duration;
  state.counters["duration_s"] = t;
}
BENCHMARK(BM_CycleTimeConverged)->Unit(benchmark::kMillisecond);

void BM_CycleTimeFastEnergy(benchmark::State& state) {
  const Spec s = bench_spec(40, 1);
  double e = 0;
  for (auto _ : state) e = fastest_motion_energy(s, 1, kXs, kPhi).energy;
  state.counters["energy_J"] = e;
}
BENCHMARK(BM_CycleTimeFastEnergy)->Unit(benchmark::kMillisecond);

}  // namespace
