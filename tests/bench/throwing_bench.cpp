// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Speed of the tray-arm simulations: RK4 steps per second of the planning model (one
// evaluation of an IDP candidate; the Planner one evaluation at a time, the reference, beside
// the simulation kernel, one profile or several at once in its lanes), the open-loop DOPRI5
// replay, one IDP iteration on both cores, the time to a converged IDP (one seed from the
// bundled case's feasible reference, and the 4 seeds on one or both cores, one after the
// other or side by side; also without the early stop of infeasible candidates, the
// reference it must equal), one SLSQP central-difference gradient (the point and its 60
// neighbours, each simulated from t = 0 or resumed from the point's stage checkpoints), the
// bundled throw solved whole (16 stages alone, and with its control grids), and the pendulum
// study.
#include <benchmark/benchmark.h>

#include "studies/pendulum/solve.hpp"
#include "studies/throwing/grid_sequence.hpp"
#if ARMSTUDY_WITH_IPOPT
#include "studies/throwing/ipopt_solve.hpp"
#endif
#include "studies/throwing/idp.hpp"
#include "studies/throwing/nlopt_solve.hpp"
#include "studies/throwing/simulate_kernel.hpp"
#include "studies/throwing/solve.hpp"
#include "studies/throwing/throw_gradient.hpp"

namespace {
using namespace armstudy::studies;

struct Fixture {
  ThrowingSpec spec;
  ThrowSetup setup;
  VelocityProfile profile;
  Fixture() {
    setup = make_throw_setup(spec);
    profile = eq8_profile(spec.start, Eigen::Vector2d::Zero(), spec.release, spec.release_rate,
                          spec.tf, spec.stages);
  }
};

// one candidate of the default case: 16 stages x 20 (80) RK4 steps; second argument 1: the
// same simulation through the generic chain (the reference of the one-pass tray dynamics);
// third argument ThrowSetup::kernel_lanes: 0 the Planner one evaluation at a time (the
// reference of the kernel), 1 the kernel (simulate_kernel.hpp)
void BM_ThrowSimulateProfile(benchmark::State& state) {
  Fixture f;
  f.setup.steps_per_stage = static_cast<int>(state.range(0));
  f.setup.generic_dynamics = state.range(1) == 1;
  f.setup.kernel_lanes = static_cast<int>(state.range(2));
  const long steps = static_cast<long>(f.setup.steps_per_stage) * f.profile.stages();
  for (auto _ : state) benchmark::DoNotOptimize(simulate_profile(f.setup, f.profile).energy);
  state.counters["rk4_steps_per_s"] = benchmark::Counter(
      static_cast<double>(steps) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ThrowSimulateProfile)
    ->Args({20, 0, 0})
    ->Args({20, 0, 1})
    ->Args({20, 1, 0})
    ->Args({80, 0, 0})
    ->Args({80, 0, 1})
    ->Args({80, 1, 0})
    ->Unit(benchmark::kMillisecond);

// w candidates of the default case (eq. 8 and moves of it) at once in the kernel's lanes
// (argument w = 1 .. 5; 1: one candidate); the rate counts every candidate's steps
void BM_ThrowSimulateLanes(benchmark::State& state) {
  Fixture f;
  const int w = static_cast<int>(state.range(0));
  std::vector<VelocityProfile> ps(w, f.profile);
  for (int i = 1; i < w; ++i) {
    ps[i].v(0, 3 + i) += 0.1 * i;
    project_displacement(ps[i], f.spec.release - f.spec.start);
  }
  std::vector<const VelocityProfile*> group;
  for (const VelocityProfile& p : ps) group.push_back(&p);
  std::vector<ProfileEvaluation> evs(w);
  const long steps = static_cast<long>(w) * f.setup.steps_per_stage * f.profile.stages();
  for (auto _ : state) {
    simulate_kernel_lanes(f.setup, group, w, 0.0, false, evs.data());
    benchmark::DoNotOptimize(evs.back().energy);
  }
  state.counters["rk4_steps_per_s"] = benchmark::Counter(
      static_cast<double>(steps) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ThrowSimulateLanes)->DenseRange(1, 5)->Unit(benchmark::kMillisecond);

void BM_ThrowReplayVoltages(benchmark::State& state) {
  Fixture f;
  std::vector<ThrowSample> samples;
  simulate_profile(f.setup, f.profile, &samples);
  const VoltageHistory vh = voltage_history(samples);
  armstudy::core::JointVector q0(4);
  q0 << f.spec.start, 0.0, 0.0;
  long steps = 0;
  for (auto _ : state) {
    const ReplayResult r = replay_voltages(f.setup, vh, q0, armstudy::core::JointVector::Zero(4),
                                           {f.spec.tf}, 1e-10, 1e-12);
    steps += r.steps;
  }
  state.counters["dopri5_steps_per_s"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ThrowReplayVoltages)->Unit(benchmark::kMillisecond);

// one IDP iteration (15 stage nodes x 5 candidates) on 1 and 2 threads; second argument 1:
// through the generic chain; third argument ThrowSetup::kernel_lanes (0: the Planner, 1: the
// kernel one candidate at a time, 2 to 5: that many at once)
void BM_IdpIteration(benchmark::State& state) {
  Fixture f;
  f.setup.generic_dynamics = state.range(1) == 1;
  f.setup.kernel_lanes = static_cast<int>(state.range(2));
  IdpSettings s;
  s.iterations = 1;
  s.max_passes = 1;
  s.threads = static_cast<int>(state.range(0));
  const Eigen::Vector2d delta = f.spec.release - f.spec.start;
  long evals = 0;
  for (auto _ : state) evals += run_idp(f.setup, f.profile, delta, s).evaluations;
  state.counters["simulations_per_s"] =
      benchmark::Counter(static_cast<double>(evals), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_IdpIteration)
    ->Args({1, 0, 0})
    ->Args({1, 0, 1})
    ->Args({1, 0, 2})
    ->Args({1, 0, 4})
    ->Args({1, 0, 5})
    ->Args({1, 1, 0})
    ->Args({2, 0, 0})
    ->Args({2, 0, 2})
    ->Args({2, 0, 4})
    ->Args({2, 0, 5})
    ->Args({2, 1, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// time to a converged IDP on the bundled case (default spec): from its repaired reference
// (computed once, outside the timing), one seed on one core, or all seeds on one or both
// cores; arguments: threads, 1 (0: every candidate simulated to the end, no early stop),
// ThrowSetup::kernel_lanes (0: the Planner, 2 to 5: the kernel, that many candidates at once),
// seeds (1 or the case's 4), 1 (0: a thread's seeds one after the other, not side by side)
void BM_IdpConverged(benchmark::State& state) {
  Fixture f;
  f.setup.kernel_lanes = static_cast<int>(state.range(2));
  const Eigen::Vector2d delta = f.spec.release - f.spec.start;
  NloptSettings ns = f.spec.nlopt;
  ns.backoff = f.spec.backoff;
  const NloptOutcome rep = run_nlopt(f.setup, f.profile, delta, ns, Objective::kViolation);
  IdpSettings s = f.spec.idp;
  s.backoff = f.spec.backoff;
  s.threads = static_cast<int>(state.range(0));
  s.stop_infeasible_candidates = state.range(1) == 1;
  s.seeds = static_cast<int>(state.range(3));
  s.seeds_side_by_side = state.range(4) == 1;
  long evals = 0;
  int converged = 0, runs = 0;
  for (auto _ : state) {
    for (const IdpResult& r : run_idp_seeds(f.setup, rep.best, delta, s)) {
      evals += r.evaluations;
      converged += r.converged;
      ++runs;
    }
  }
  state.counters["simulations_per_s"] =
      benchmark::Counter(static_cast<double>(evals), benchmark::Counter::kIsRate);
  state.counters["seeds"] = s.seeds;
  state.counters["converged_fraction"] = runs ? static_cast<double>(converged) / runs : 0.0;
}
BENCHMARK(BM_IdpConverged)
    ->Args({1, 0, 0, 1, 1})
    ->Args({1, 1, 0, 1, 1})
    ->Args({1, 1, 4, 1, 1})
    ->Args({1, 1, 5, 1, 1})
    ->Args({1, 1, 0, 4, 1})
    ->Args({1, 1, 4, 4, 0})
    ->Args({1, 1, 4, 4, 1})
    ->Args({2, 1, 0, 4, 1})
    ->Args({2, 1, 4, 4, 0})
    ->Args({2, 1, 4, 4, 1})
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

// one central-difference gradient of SLSQP on one core (nlopt_solve.cpp's compute): the
// default case's eq. 8 profile and its 2 x 30 neighbours (fd step 1e-5 rad/s); argument 0:
// every neighbour simulated from t = 0 (evaluate_profiles), 1: resumed from the point's
// stage checkpoints (evaluate_neighbours), the same evaluations bit for bit; second argument
// ThrowSetup::kernel_lanes (0: the Planner, 2 or 4: the kernel, that many neighbours at once)
void BM_SlsqpGradient(benchmark::State& state) {
  Fixture f;
  f.setup.kernel_lanes = static_cast<int>(state.range(1));
  std::vector<VelocityProfile> ps{f.profile};
  std::vector<int> first{0};
  for (int k = 1; k < f.profile.stages(); ++k)
    for (int j = 0; j < 2; ++j)
      for (double step : {1e-5, -1e-5}) {
        VelocityProfile p = f.profile;
        p.v(j, k) += step;
        ps.push_back(p);
        first.push_back(k - 1);
      }
  const bool resume = state.range(0) == 1;
  long sims = 0;
  for (auto _ : state) {
    const auto evs = resume ? evaluate_neighbours(f.setup, ps, first, 1, 0.02)
                            : evaluate_profiles(f.setup, ps, 1, 0.02);
    benchmark::DoNotOptimize(evs.back().energy);
    sims += static_cast<long>(evs.size());
  }
  state.counters["simulations_per_s"] =
      benchmark::Counter(static_cast<double>(sims), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SlsqpGradient)
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({1, 2})
    ->Args({1, 4})
    ->Unit(benchmark::kMillisecond);

// one gradient of the energy and every constraint value on the bundled case's eq. 8 profile
// on P stages (first argument; the RK4 step kept at 2.5 ms, grid_setup), on one core;
// second argument: 0 central differences as SLSQP takes them (evaluate_neighbours, resumed,
// the kernel 4 lanes at once: 2n + 1 simulations), 1 the exact derivatives
// (throw_gradient.hpp), 2 one simulation alone (the kernel), the unit of the other two
void BM_ThrowGradient(benchmark::State& state) {
  Fixture f;
  const int P = static_cast<int>(state.range(0));
  const int mode = static_cast<int>(state.range(1));
  const ThrowSetup setup = grid_setup(f.setup, f.profile.stages(), P);
  const VelocityProfile profile = eq8_profile(f.spec.start, Eigen::Vector2d::Zero(), f.spec.release,
                                              f.spec.release_rate, f.spec.tf, P);
  std::vector<VelocityProfile> ps{profile};
  std::vector<int> first{0};
  for (int k = 1; k < P && mode == 0; ++k)
    for (int j = 0; j < 2; ++j)
      for (double step : {1e-5, -1e-5}) {
        VelocityProfile p = profile;
        p.v(j, k) += step;
        ps.push_back(p);
        first.push_back(k - 1);
      }
  for (auto _ : state) {
    if (mode == 0) {
      const auto evs = evaluate_neighbours(setup, ps, first, 1, 0.02);
      benchmark::DoNotOptimize(evs.back().energy);
    } else if (mode == 1) {
      const ThrowDerivatives d = throw_derivatives(setup, profile, 0.02);
      benchmark::DoNotOptimize(d.energy_gradient[0]);
    } else {
      benchmark::DoNotOptimize(simulate_profile(setup, profile, nullptr, 0.02).energy);
    }
  }
  state.counters["parameters"] = 2.0 * (P - 1);
}
BENCHMARK(BM_ThrowGradient)->ArgsProduct({{16, 64, 256}, {0, 1, 2}})->Unit(benchmark::kMillisecond);

// the bundled throwing case solved whole (ThrowingSpec's defaults are the bundled case's):
// IDP, SLSQP from every start on 16 stages, then the control grids (32, 64 stages; argument:
// grid.refinements, 0 the first grid alone; second: nlopt.exact_gradient). CPU time of the
// process (both threads): the budget of the converged throw is 60 s of CPU on the 2-core CI
// machine
void BM_ThrowingSolved(benchmark::State& state) {
  ThrowingSpec spec;
  spec.grid.refinements = static_cast<int>(state.range(0));
  spec.nlopt.exact_gradient = state.range(1) == 1;
  double energy = 0;
  long sims = 0, grids = 0;
  for (auto _ : state) {
    const ThrowingResult r = solve_throwing(spec);
    energy = r.nlopt.evaluation.energy;
    grids = static_cast<long>(r.grids.size());
    sims = 0;
    for (const auto& g : r.grids) sims += g.simulations;
  }
  state.counters["energy_J"] = energy;
  state.counters["slsqp_simulations"] = static_cast<double>(sims);
  state.counters["grids"] = static_cast<double>(grids);
}
BENCHMARK(BM_ThrowingSolved)
    ->Args({0, 0})
    ->Args({2, 0})
    ->Args({0, 1})
    ->Args({2, 1})
    ->Args({3, 1})
    ->Args({4, 1})
    ->Iterations(1)
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kSecond);

// one fine-grid solve of the bundled throw, the two optimisers on the same start: the 32-stage
// SLSQP answer (exact gradients, made once, outside the timing) prolonged to 64 stages, the RK4
// step kept at 2.5 ms; argument 0: SLSQP with exact gradients (run_nlopt), 1: IPOPT
// (run_ipopt, built with ARMSTUDY_WITH_IPOPT only). Process CPU time, one run
void BM_ThrowFineGridSolve(benchmark::State& state) {
  ThrowingSpec spec;
  spec.nlopt.exact_gradient = true;
  spec.grid.refinements = 1;
  static const VelocityProfile coarse = solve_throwing(spec).nlopt.profile;
  const ThrowSetup fine = grid_setup(make_throw_setup(spec), spec.stages, 2 * coarse.stages());
  const VelocityProfile start = prolong_profile(coarse, 2);
  const Eigen::Vector2d delta = spec.release - spec.start;
  NloptOutcome o;
  for (auto _ : state) {
#if ARMSTUDY_WITH_IPOPT
    o = state.range(0) == 1 ? run_ipopt(fine, start, delta, spec.nlopt)
                            : run_nlopt(fine, start, delta, spec.nlopt);
#else
    o = run_nlopt(fine, start, delta, spec.nlopt);
#endif
  }
  state.counters["stages"] = start.stages();
  state.counters["energy_J"] = o.evaluation.energy;
  state.counters["feasible"] = o.feasible ? 1 : 0;
  state.counters["converged"] = o.converged ? 1 : 0;
  state.counters["simulations"] = static_cast<double>(o.simulations);
}
BENCHMARK(BM_ThrowFineGridSolve)
    ->Arg(0)
#if ARMSTUDY_WITH_IPOPT
    ->Arg(1)
#endif
    ->Iterations(1)
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kSecond);

void BM_PendulumTwoSeconds(benchmark::State& state) {
  const PendulumSpec spec = default_pendulum_spec();
  long steps = 0;
  for (auto _ : state) steps += solve_pendulum(spec).steps_accepted;
  state.counters["dopri5_steps_per_s"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PendulumTwoSeconds)->Unit(benchmark::kMillisecond);

}  // namespace
