// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Speed of the time-optimal solvers on the bundled source case (time-optimal-source.yaml:
// the default arm on a 0.81 m line): the exact reachability solver on 1000 grid points
// (target < 5 ms), DP with N = 10 and 200 velocity levels (target < 50 ms), the rows of the
// DP convergence table (N = 50, 100, 200 with 20 N levels) by solve_dp and by the plain
// recursion it replaces (solve_dp_reference, the same answers), the whole table as the study
// runs it (two threads: wall time), Box's Complex method on the same 10 segments, and the
// whole study with its dense re-checks.
#include <benchmark/benchmark.h>

#include <algorithm>

#include "scene/study_replays.hpp"
#include "studies/time_optimal/profile.hpp"
#include "studies/time_optimal/solve.hpp"
#include "studies/time_optimal/solvers.hpp"

namespace {
using namespace armstudy::studies::time_optimal;

Spec source_spec() {
  Spec spec;
  spec.chain = default_arm();
  spec.path.kind = PathKind::kLine;
  spec.path.points = {{0.3, 0.1}, {-0.1, 0.8}};
  return spec;
}

Problem problem(const Spec& spec) {
  return Problem{spec.chain, PathGeometry(spec.path), spec.configuration,
                 Limits{spec.velocity_limit, spec.torque_limit, spec.acceleration_limit}};
}

void BM_TimeOptimalExact(benchmark::State& state) {
  const Spec spec = source_spec();
  const Problem pb = problem(spec);
  const std::vector<double> grid = make_nodes(pb.path, static_cast<int>(state.range(0)) - 1);
  for (auto _ : state) benchmark::DoNotOptimize(solve_exact(pb, grid, 2).duration);
  state.SetLabel(std::to_string(state.range(0)) + " grid points, 3 checks per interval");
}
BENCHMARK(BM_TimeOptimalExact)->Arg(1000)->Arg(4000)->Unit(benchmark::kMillisecond);

void BM_TimeOptimalDp(benchmark::State& state) {
  const Spec spec = source_spec();
  const Problem pb = problem(spec);
  long evaluations = 0;
  for (auto _ : state) {
    const SolverOutput o = solve_dp(pb, static_cast<int>(state.range(0)),
                                    static_cast<int>(state.range(1)), 8, DpState::kPathSpeed);
    evaluations = o.evaluations;
    benchmark::DoNotOptimize(o.duration);
  }
  state.counters["transitions"] = static_cast<double>(evaluations);
}
BENCHMARK(BM_TimeOptimalDp)->Args({10, 200})->Args({50, 1000})->Unit(benchmark::kMillisecond);

// one row of the study's DP convergence table on the source case, as solve() runs it:
// N segments, levels growing as 20 N (200 x N / 10), max(2, 80 / N) checks per segment
void BM_TimeOptimalDpTableRow(benchmark::State& state) {
  const Spec spec = source_spec();
  const Problem pb = problem(spec);
  const int segments = static_cast<int>(state.range(0));
  const int levels = 20 * segments, checks = std::max(2, 80 / segments);
  long evaluations = 0;
  for (auto _ : state) {
    const SolverOutput o = solve_dp(pb, segments, levels, checks, DpState::kPathSpeed);
    evaluations = o.evaluations;
    benchmark::DoNotOptimize(o.duration);
  }
  state.counters["transitions"] = static_cast<double>(evaluations);
}
BENCHMARK(BM_TimeOptimalDpTableRow)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMillisecond);

// the same rows by the plain recursion (solve_dp_reference: core's staged DP, the cost of
// every transition in the bands evaluated), the same answers: the pruning's gain in one run
void BM_TimeOptimalDpTableRowReference(benchmark::State& state) {
  const Spec spec = source_spec();
  const Problem pb = problem(spec);
  const int segments = static_cast<int>(state.range(0));
  const int levels = 20 * segments, checks = std::max(2, 80 / segments);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        solve_dp_reference(pb, segments, levels, checks, DpState::kPathSpeed).duration);
}
BENCHMARK(BM_TimeOptimalDpTableRowReference)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// the study with its DP convergence table (N = 10, 20, 50, 100, 200; rows on two threads)
// and nothing else but the exact solve it compares with: DP states and Complex off
void BM_TimeOptimalDpTable(benchmark::State& state) {
  Spec spec = source_spec();
  spec.dp.states = {};
  spec.complex.enabled = false;
  spec.dp.convergence_segments = {10, 20, 50, 100, 200};
  for (auto _ : state) benchmark::DoNotOptimize(solve(spec).status);
}
BENCHMARK(BM_TimeOptimalDpTable)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_TimeOptimalDpJoint1(benchmark::State& state) {
  const Spec spec = source_spec();
  const Problem pb = problem(spec);
  for (auto _ : state)
    benchmark::DoNotOptimize(solve_dp(pb, 10, 200, 8, DpState::kJoint1Velocity).duration);
}
BENCHMARK(BM_TimeOptimalDpJoint1)->Unit(benchmark::kMillisecond);

void BM_TimeOptimalComplex(benchmark::State& state) {
  const Spec spec = source_spec();
  const Problem pb = problem(spec);
  for (auto _ : state) benchmark::DoNotOptimize(solve_complex(pb, 10, 8, spec.complex).duration);
}
BENCHMARK(BM_TimeOptimalComplex)->Unit(benchmark::kMillisecond);

// the study without the convergence table: every solver and the dense re-checks
void BM_TimeOptimalStudy(benchmark::State& state) {
  Spec spec = source_spec();
  spec.dp.convergence_segments = {};
  for (auto _ : state) benchmark::DoNotOptimize(solve(spec).status);
}
BENCHMARK(BM_TimeOptimalStudy)->Unit(benchmark::kMillisecond);

// MuJoCo's dynamic replay of the exact solution: 2000 RK4 steps at h and 1000 at 2 h, the
// step-mean torques from the plan (scene/dynamic_replay.hpp)
void BM_TimeOptimalMujocoReplay(benchmark::State& state) {
  Spec spec = source_spec();
  spec.dp.states = {};
  spec.dp.convergence_segments = {};
  spec.complex.enabled = false;
  const Result r = solve(spec);
  for (auto _ : state)
    benchmark::DoNotOptimize(armstudy::scene::replay_time_optimal(spec, r).max_deviation);
}
BENCHMARK(BM_TimeOptimalMujocoReplay)->Unit(benchmark::kMillisecond);

}  // namespace
