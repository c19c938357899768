// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Placement study speed: closed-form candidate evaluation (IK + velocities + accelerations
// + torques + power) in trajectory samples per second on 1 and 2 threads, the constrained
// refinement of one optimum, and the
// end-to-end time of the five bundled thesis examples (search, refinement, maps; no
// rendering), as `armstudy run --no-render` does them.
#include <benchmark/benchmark.h>

#include <ctime>
#include <filesystem>
#include <random>
#include <thread>

#include "app/pipeline.hpp"
#include "studies/placement/geometry.hpp"
#include "studies/placement/refine.hpp"
#include "studies/placement/solve.hpp"
#include "testing/arms.hpp"

namespace armstudy::studies::placement {
namespace {

// reachable lines of a 0.4 Lmax task, as the sweep sees them
std::vector<Line> lines(double L, int count) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> xs(0.2, 0.6), ph(0.0, core::kPi);
  std::vector<Line> out;
  while (int(out.size()) < count) {
    const Line l = thesis_line(xs(rng), ph(rng));
    if (check_line(0.4, 0.2, l, L).boundary_distance >= 0.01) out.push_back(l);
  }
  return out;
}

// second argument 1: the scalar reference (one arm2_sample at a time) instead of the
// structure-of-arrays evaluator
void BM_PlacementEvaluatorSamples(benchmark::State& state) {
  const int threads = int(state.range(0));
  const auto eval = state.range(1) == 1 ? &evaluate_line_scalar : &evaluate_line;
  const Arm2 arm = make_arm2(testing::thesis_arm());
  const double L = 0.4 * annulus(0.4, 0.2).lmax;
  const ProgramTable table = make_program_table(core::MotionProgram::kCycloidal, 1.0, L, 401);
  const std::vector<Line> ls = lines(L, 512);
  long samples = 0;
  // process CPU time too: on a shared machine samples per CPU second is what a core does
  timespec c0{}, c1{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c0);
  for (auto _ : state) {
    // every thread evaluates its share of the batch, both configurations
    std::vector<std::thread> pool;
    std::vector<double> sink(threads, 0.0);
    for (int t = 0; t < threads; ++t) {
      pool.emplace_back([&, t] {
        for (size_t i = size_t(t); i < ls.size(); i += size_t(threads)) {
          sink[t] += eval(arm, table, ls[i], 1).energy;
          sink[t] += eval(arm, table, ls[i], 2).energy;
        }
      });
    }
    for (auto& p : pool) p.join();
    benchmark::DoNotOptimize(sink.data());
    samples += long(ls.size()) * 2 * table.size();
  }
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c1);
  const double cpu = double(c1.tv_sec - c0.tv_sec) + 1e-9 * double(c1.tv_nsec - c0.tv_nsec);
  state.counters["samples_per_cpu_s"] = double(samples) / cpu;
  state.counters["samples_per_s"] =
      benchmark::Counter(double(samples), benchmark::Counter::kIsRate);
  state.counters["samples_per_s_per_thread"] =
      benchmark::Counter(double(samples) / threads, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PlacementEvaluatorSamples)
    ->Args({1, 0})
    ->Args({1, 1})
    ->Args({2, 0})
    ->Args({2, 1})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// the constrained refinement of one optimum (refine.hpp) from a nearby start: on the inner
// circle's clearance margin (0.5 Lmax, arg 0) and interior (0.2 Lmax, arg 1)
void BM_PlacementConstrainedRefinement(benchmark::State& state) {
  const bool interior = state.range(0) == 1;
  Spec spec;
  spec.chain = testing::thesis_arm();
  spec.length = (interior ? 0.2 : 0.5) * annulus(0.4, 0.2).lmax;
  const Arm2 arm = make_arm2(spec.chain);
  const ProgramTable table =
      make_program_table(core::MotionProgram::kCycloidal, 1.0, spec.length, 401);
  const double x0 = interior ? 0.52 : 0.216, p0 = (interior ? 168.0 : 99.0) * core::kPi / 180;
  const Candidate start = evaluate_candidate(spec, arm, table, 1, x0, p0);
  long evaluations = 0;
  for (auto _ : state) {
    const Refinement r = refine_constrained(spec, arm, table, 1, start, 0.008, 0.0265);
    benchmark::DoNotOptimize(r.best.metrics.energy);
    evaluations += r.evaluations;
  }
  state.counters["evaluations"] =
      benchmark::Counter(double(evaluations), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_PlacementConstrainedRefinement)
    ->Arg(0)
    ->Arg(1)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// the source tree (the benchmark executable gets no ARMSTUDY_SOURCE_DIR): three levels up
std::filesystem::path source_dir() {
  return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path();
}

void BM_PlacementFiveBundledExamples(benchmark::State& state) {
  for (auto _ : state) {
    for (int n = 1; n <= 5; ++n) {
      app::LoadedCase c = app::load_case(
          (source_dir() / ("reports/cases/placement-example-" + std::to_string(n) + ".yaml"))
              .string());
      c.run->solve({});
      benchmark::DoNotOptimize(c.run->results().dump().size());
    }
  }
}
BENCHMARK(BM_PlacementFiveBundledExamples)->UseRealTime()->Unit(benchmark::kSecond)->Iterations(3);

}  // namespace
}  // namespace armstudy::studies::placement
