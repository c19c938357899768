// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Every check of every pipeline (app/*_pipeline.cpp) held on both sides of its limit: a
// measured value just inside the limit passes and one just outside fails, and the check
// reports the value its contract names (the check functions of app/study_checks.hpp,
// studies/placement/checks.hpp and printed_limits.hpp, studies/time_optimal/solve.hpp and
// scene/mujoco_check.hpp, scene/dynamic_replay.hpp). The limits are set here, not taken from
// a bundled case, so that the tests hold the contract (value against limit) whatever the
// cases' tolerances become.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "app/study_checks.hpp"
#include "scene/dynamic_replay.hpp"
#include "scene/mujoco_check.hpp"
#include "studies/placement/candidate.hpp"
#include "studies/placement/checks.hpp"
#include "studies/placement/printed_limits.hpp"
#include "studies/time_optimal/solve.hpp"

namespace armstudy {
namespace {
using studies::Check;

// the one check called `name` of `checks` (a missing one fails the test and returns a dummy)
Check verdict_named(const std::vector<Check>& checks, const std::string& name) {
  int found = 0;
  Check out;
  for (const Check& c : checks)
    if (c.name == name) {
      out = c;
      ++found;
    }
  EXPECT_EQ(found, 1) << name;
  if (found != 1) out.passed = !out.passed;  // (never mistaken for a verdict)
  return out;
}

// the verdict, the reported value and the limit of a check
void expect_verdict(const Check& c, bool passed, double value, double limit) {
  EXPECT_EQ(c.passed, passed) << c.name << ": value " << c.value << ", limit " << c.tolerance;
  EXPECT_NEAR(c.value, value, 1e-12 * std::max(1.0, std::abs(value))) << c.name;
  EXPECT_EQ(c.tolerance, limit) << c.name;
}

// ---------------------------------------------------------------- pendulum

TEST(CheckVerdict, PendulumEnergyDriftAgainstTheCasesTolerance) {
  studies::PendulumSpec spec;
  spec.drift_tolerance = 3.7e-9;
  studies::PendulumResult r;
  r.status = studies::Status::kSolved;
  for (const double drift : {3.6999e-9, 3.7001e-9}) {
    r.energy_drift_rel = drift;
    expect_verdict(verdict_named(app::pendulum_checks(spec, r), "pendulum_energy_drift"),
                   drift < spec.drift_tolerance, drift, spec.drift_tolerance);
  }
}

// ---------------------------------------------------------------- throwing

// a throw with IDP as the answer whose re-checked optimum keeps every limit by far; the
// limits differ from the defaults, so that a check reading a default fails
struct VerdictThrowFixture {
  studies::ThrowingSpec spec;
  studies::ThrowingResult r;
  VerdictThrowFixture() {
    spec.contact_margin = 0.031;
    spec.friction_coefficient = 0.43;
    spec.tray_width = 1.9;
    spec.voltage_max = 21.5;
    spec.current_max = 7.3;
    spec.power_max = 47.0;
    spec.release_tolerance = 0.013;
    spec.replay_tolerance = 1.7e-3;
    r.answer = "idp";
    r.idp.series.t = {0.0, 0.1};
    r.idp_converged = true;
    auto& e = r.idp_check.evaluation;
    e.min_normal_force = 1.0;
    e.max_friction_ratio = 0.1;
    e.max_abs_theta4 = 0.1;
    e.max_voltage = 5;
    e.max_current = 1;
    e.max_power = 5;
    r.idp_check.release_error = 1e-4;
    r.replay_error = 1e-5;
    r.rk4_energy_error = 1e-6;
  }
  std::vector<Check> checks() const { return app::throwing_checks(spec, r); }
};

TEST(CheckVerdict, ThrowingContactNeedsTheMarginNotJustAPositiveNormalForce) {
  VerdictThrowFixture f;
  const double m = f.spec.contact_margin;
  for (const double n : {m + 1e-6, m - 1e-6, 0.5 * m}) {
    f.r.idp_check.evaluation.min_normal_force = n;
    // a force above 0 but below the margin fails
    expect_verdict(verdict_named(f.checks(), "idp_contact"), n >= m, m - n, 0.0);
  }
}

TEST(CheckVerdict, ThrowingFrictionBallInTrayAndMotorLimits) {
  struct Limit {
    const char* name;
    double studies::ProfileEvaluation::*value;
    double limit;
  };
  VerdictThrowFixture base;
  const Limit limits[] = {
      {"idp_friction", &studies::ProfileEvaluation::max_friction_ratio,
       base.spec.friction_coefficient},
      {"idp_ball_in_tray", &studies::ProfileEvaluation::max_abs_theta4, base.spec.tray_width / 2},
      {"idp_voltage", &studies::ProfileEvaluation::max_voltage, base.spec.voltage_max},
      {"idp_current", &studies::ProfileEvaluation::max_current, base.spec.current_max},
      {"idp_power", &studies::ProfileEvaluation::max_power, base.spec.power_max}};
  for (const Limit& l : limits)
    for (const double factor : {1 - 1e-7, 1 + 1e-7}) {
      VerdictThrowFixture f;
      f.r.idp_check.evaluation.*l.value = l.limit * factor;
      expect_verdict(verdict_named(f.checks(), l.name), factor < 1, l.limit * factor, l.limit);
      // the others still pass: each check reads its own figure
      for (const Check& c : f.checks()) {
        if (c.name != l.name) {
          EXPECT_TRUE(c.passed) << l.name << " moved " << c.name;
        }
      }
    }
}

TEST(CheckVerdict, ThrowingReleaseReplayAndRk4Accuracy) {
  for (const double factor : {1 - 1e-7, 1 + 1e-7}) {
    VerdictThrowFixture f;
    f.r.idp_check.release_error = f.spec.release_tolerance * factor;
    f.r.replay_error = f.spec.replay_tolerance * factor;
    f.r.rk4_energy_error = 1e-3 * factor;
    const auto cs = f.checks();
    expect_verdict(verdict_named(cs, "idp_release_theta3"), factor < 1,
                   f.spec.release_tolerance * factor, f.spec.release_tolerance);
    expect_verdict(verdict_named(cs, "open_loop_replay"), factor < 1,
                   f.spec.replay_tolerance * factor, f.spec.replay_tolerance);
    expect_verdict(verdict_named(cs, "rk4_accuracy"), factor < 1, 1e-3 * factor, 1e-3);
  }
}

TEST(CheckVerdict, ThrowingConvergenceFailsUnlessTheCaseAllowsIt) {
  for (const bool allow : {false, true})
    for (const bool converged : {true, false}) {
      VerdictThrowFixture f;
      f.spec.allow_not_converged = allow;
      f.r.idp_converged = converged;
      expect_verdict(verdict_named(f.checks(), "idp_converged"), converged || allow,
                     converged ? 0.0 : 1.0, allow ? 1.0 : 0.0);
    }
}

TEST(CheckVerdict, ThrowingSlsqpAnswerIsCheckedOnItsOwnRecheck) {
  VerdictThrowFixture f;
  f.r.answer = "slsqp";
  f.r.nlopt_ran = true;
  f.r.nlopt_run.converged = true;
  f.r.nlopt_check = f.r.idp_check;
  f.r.idp_check.evaluation.max_power = 2 * f.spec.power_max;  // IDP only compared: unchecked
  f.r.nlopt_check.evaluation.min_normal_force = f.spec.contact_margin - 1e-6;
  const auto cs = f.checks();
  for (const Check& c : cs) EXPECT_NE(c.name.rfind("idp_", 0), 0u) << c.name;
  expect_verdict(verdict_named(cs, "slsqp_contact"), false, 1e-6, 0.0);
  expect_verdict(verdict_named(cs, "slsqp_power"), true, 5, f.spec.power_max);
  f.r.nlopt_run.converged = false;
  expect_verdict(verdict_named(f.checks(), "slsqp_converged"), false, 1.0, 0.0);
}

// ---------------------------------------------------------------- placement

namespace pl = studies::placement;

// a found optimum whose energy converged by quadrature, refined and clear of the margin
pl::ProgramConfig verdict_placed_optimum(double energy) {
  pl::ProgramConfig pc;
  pc.found = true;
  pc.refine_method = "COBYLA";
  pc.refine_converged = true;
  pc.refine_tolerance_rel = 1e-9;
  pl::Candidate& c = pc.refined;
  c.status = pl::CandidateStatus::kFeasible;
  c.boundary_distance = 0.05;
  c.metrics.energy = energy;
  c.convergence.checked = c.convergence.converged = c.convergence.peak_converged = true;
  c.convergence.quadrature = true;
  c.convergence.tolerance = 1e-3;
  c.convergence.energy = energy;
  c.convergence.energy_error = 1e-8 * energy;
  c.convergence.metrics.energy = energy;
  pc.grid = c;
  pc.grid.convergence.metrics.energy = energy * 1.01;  // the refinement gained 1 %
  return pc;
}

std::vector<Check> verdict_optima_checks(const pl::Spec& spec, const pl::ProgramConfig& pc) {
  pl::Result res;
  res.cases = {verdict_placed_optimum(2.0), pc};
  pl::check_optima(spec, res);
  return res.checks;
}

TEST(CheckVerdict, PlacementOptimaClearOfTheSingularityMargin) {
  pl::Spec spec;
  spec.singularity_margin = 0.023;
  for (const double excess : {-1e-13, 1e-11}) {  // kMarginTol is 1e-12 m
    pl::ProgramConfig pc = verdict_placed_optimum(3.0);
    pc.refined.boundary_distance = spec.singularity_margin - excess;
    expect_verdict(verdict_named(verdict_optima_checks(spec, pc), "optima_clear_of_singularities"),
                   excess <= pl::kMarginTol, std::max(excess, 0.0), pl::kMarginTol);
  }
}

TEST(CheckVerdict, PlacementRefinementConvergedAndNotWorse) {
  const pl::Spec spec;
  for (const double gain : {0.99e-7, 1.01e-7}) {
    pl::ProgramConfig pc = verdict_placed_optimum(3.0);
    pc.refine_tolerance_rel = gain;
    expect_verdict(verdict_named(verdict_optima_checks(spec, pc), "refinement_converged"),
                   gain <= 1e-7, gain, 1e-7);
  }
  pl::ProgramConfig stalled = verdict_placed_optimum(3.0);
  stalled.refine_converged = false;  // a refinement that did not converge is infinitely off
  EXPECT_FALSE(verdict_named(verdict_optima_checks(spec, stalled), "refinement_converged").passed);
  for (const double worse : {-1e-9, 1e-9}) {
    pl::ProgramConfig pc = verdict_placed_optimum(3.0);
    pc.grid.convergence.metrics.energy = 3.0 - worse;
    expect_verdict(verdict_named(verdict_optima_checks(spec, pc), "refinement_not_worse"),
                   worse <= 0, std::max(worse, 0.0), 0.0);
  }
}

TEST(CheckVerdict, PlacementOptimaEnergyConverged) {
  const pl::Spec spec;
  for (const double rel : {0.99e-4, 1.01e-4}) {
    pl::ProgramConfig pc = verdict_placed_optimum(3.0);
    pc.refined.convergence.energy_error = rel * 3.0;
    expect_verdict(verdict_named(verdict_optima_checks(spec, pc), "optima_energy_converged"),
                   rel <= 1e-4, rel, 1e-4);
  }
  pl::ProgramConfig withheld = verdict_placed_optimum(3.0);
  withheld.refined.convergence.energy_error = 0.1 * 3.0;  // beyond its quadrature tolerance
  EXPECT_FALSE(
      verdict_named(verdict_optima_checks(spec, withheld), "optima_energy_converged").passed);
}

TEST(CheckVerdict, PlacementEnergyConvergedWithTheSamples) {
  const pl::Spec spec;
  for (const double rel : {0.99e-4, 1.01e-4}) {
    pl::Result res;
    res.cases = {pl::ProgramConfig{}, verdict_placed_optimum(2.0)};  // the first found one counts
    res.convergence = {{51, 9.0, 0}, {3201, 2.0 / (1 + rel), 0}};
    pl::check_sample_convergence(spec, res);
    expect_verdict(verdict_named(res.checks, "energy_converged"), rel <= 1e-4, rel, 1e-4);
  }
}

TEST(CheckVerdict, PlacementSignedWorkOfTheCandidatesClearOfTheMargin) {
  pl::Spec spec;
  spec.singularity_margin = 0.02;
  pl::LineMetrics clear, inside_margin, singular;
  clear.energy = 4.0;
  inside_margin.energy = 4.0;
  inside_margin.signed_work = 1.0;  // inside the margin: not counted
  singular.energy = std::numeric_limits<double>::infinity();
  singular.signed_work = 1.0;
  for (const double rel : {0.99e-6, 1.01e-6}) {
    clear.signed_work = -rel * clear.energy;
    const Check c =
        pl::signed_work_check(spec, {{0.05, &clear}, {0.019, &inside_margin}, {0.05, &singular}});
    EXPECT_EQ(c.name, "signed_work_rest_to_rest");
    expect_verdict(c, rel <= 1e-6, rel, 1e-6);
  }
}

TEST(CheckVerdict, PlacementActuatorLimitsAtThePrintedSamples) {
  pl::Spec spec;
  spec.torque_limit = std::array<double, 2>{3.0, 2.0};
  spec.power_limit = std::array<double, 2>{10.0, 7.0};
  for (const bool power : {false, true})
    for (const double excess : {0.9e-12, 1.1e-12}) {
      pl::Result res;
      res.cases = {verdict_placed_optimum(2.0)};
      pl::LineMetrics& m = res.cases[0].refined.convergence.metrics;
      m.peak_torque[0] = 1.0;
      m.peak_power[0] = 1.0;
      m.peak_torque[1] = power ? 1.0 : 2.0 * (1 + excess);  // the elbow's
      m.peak_power[1] = power ? 7.0 * (1 + excess) : 1.0;
      const std::optional<Check> c = pl::printed_limits_check(spec, res);
      ASSERT_TRUE(c.has_value());
      EXPECT_EQ(c->name, "limits_at_printed_samples");
      // the peaks are refined between the samples, so the limit holds to 1e-12 relative
      expect_verdict(*c, excess <= 1e-12, excess, 1e-12);
    }
  EXPECT_FALSE(pl::printed_limits_check(pl::Spec{}, pl::Result{}).has_value());  // no limits
}

// ---------------------------------------------------------------- time-optimal

namespace to = studies::time_optimal;

to::SolverResult verdict_solver(const std::string& name, double duration, double worst) {
  to::SolverResult s;
  s.name = name;
  s.solved = true;
  s.duration = duration;
  s.violation.worst = worst;
  return s;
}

to::Result verdict_time_optimal_result() {
  to::Result r;
  r.status = studies::Status::kSolved;
  r.solvers = {verdict_solver("exact", 1.0, 0.0), verdict_solver("dp", 1.1, 0.0)};
  return r;
}

TEST(CheckVerdict, TimeOptimalExactNeverSlowerThanACoarseSolver) {
  for (const double slower : {0.9e-9, 1.1e-9}) {
    to::Result r = verdict_time_optimal_result();
    r.solvers[1].duration = 1.0 / (1 + slower);  // exact / dp - 1 = slower
    expect_verdict(verdict_named(to::checks(r), "exact_not_slower_than_dp"), slower <= 1e-9, slower,
                   1e-9);
  }
}

TEST(CheckVerdict, TimeOptimalEachSolverMeetsTheLimits) {
  // DP as fast as the exact solver: no discretisation error widens the fixed tolerances
  for (const double f : {1 - 1e-6, 1 + 1e-6}) {
    to::Result r = verdict_time_optimal_result();
    r.solvers[1].duration = 1.0;
    r.solvers[0].violation.worst = to::kExactTolerance * f;
    r.solvers[1].violation.worst = to::kCoarseViolationTolerance * f;
    const auto cs = to::checks(r);
    expect_verdict(verdict_named(cs, "exact_meets_limits"), f < 1, to::kExactTolerance * f,
                   to::kExactTolerance);
    expect_verdict(verdict_named(cs, "dp_meets_limits"), f < 1, to::kCoarseViolationTolerance * f,
                   to::kCoarseViolationTolerance);
  }
  // DP 10 % slower than the exact duration: its own error (0.1) is its tolerance
  for (const double f : {1 - 1e-6, 1 + 1e-6}) {
    to::Result r = verdict_time_optimal_result();
    r.solvers[1].violation.worst = 0.1 * f;
    const auto cs = to::checks(r);
    const Check& c = verdict_named(cs, "dp_meets_limits");
    EXPECT_EQ(c.passed, f < 1) << c.name << ": value " << c.value << ", limit " << c.tolerance;
    EXPECT_NEAR(c.tolerance, 0.1, 1e-12);
  }
}

TEST(CheckVerdict, TimeOptimalGridConvergedAgainstTheCasesTolerance) {
  for (const double f : {1 - 1e-6, 1 + 1e-6}) {
    to::Result r = verdict_time_optimal_result();
    r.grid.computed = true;
    r.grid.tolerance = 3.3e-5;
    r.grid.change = 3.3e-5 * f;
    expect_verdict(verdict_named(to::checks(r), "exact_grid_converged"), f < 1, 3.3e-5 * f, 3.3e-5);
  }
}

TEST(CheckVerdict, TimeOptimalExactNeverSlowerThanTheDpTable) {
  for (const double slower : {0.9e-9, 1.1e-9}) {
    to::Result r = verdict_time_optimal_result();
    to::ConvergenceRow fast, unsolved;
    fast.solved = true;
    fast.excess = 1 / (1 + slower) - 1;  // DP / exact - 1: the DP faster by `slower`
    unsolved.excess = -0.5;              // an unsolved row is not compared
    r.convergence = {unsolved, fast};
    expect_verdict(verdict_named(to::checks(r), "exact_not_slower_than_dp_table"), slower <= 1e-9,
                   slower, 1e-9);
  }
}

// ---------------------------------------------------------------- MuJoCo's checks

TEST(CheckVerdict, MujocoInverseDynamicsAndPassiveAccelerations) {
  for (const double f : {1 - 1e-6, 1 + 1e-6}) {
    scene::MujocoAgreement a;
    a.torque_rel = 2e-7 * f;
    a.acceleration_rel = 2e-7 * (2 - f);  // the other side of the limit
    const auto cs = scene::mujoco_checks(a, true, 2e-7);
    expect_verdict(verdict_named(cs, "mujoco_inverse_dynamics"), f < 1, 2e-7 * f, 2e-7);
    expect_verdict(verdict_named(cs, "mujoco_passive_accelerations"), f > 1, 2e-7 * (2 - f), 2e-7);
  }
  EXPECT_EQ(scene::mujoco_checks({}, false, 1e-6).size(), 1u);  // no passive joints
}

TEST(CheckVerdict, MujocoDynamicReplayDeviationAgainstItsStepBound) {
  for (const double f : {1 - 1e-6, 1 + 1e-6}) {
    scene::DynamicReplay r;
    r.tolerance = 4.2e-5;
    r.max_deviation = 4.2e-5 * f;
    expect_verdict(scene::replay_check(r, "mujoco_dynamic_replay", "a motion"), f < 1, 4.2e-5 * f,
                   4.2e-5);
  }
}

}  // namespace
}  // namespace armstudy
