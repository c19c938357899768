// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// IDP (idp.hpp) and the SLSQP comparison (nlopt_solve.hpp) on a small instance of the
// throw (8 stages): both solve the constrained problem of docs/throwing.md; IDP compares by
// the feasibility rules and never accepts a worse profile, its answer does not depend on the
// thread count, its convergence is a stated criterion (a budget-cut run says so, a doubled
// budget does not move a converged answer), and the constrained optima keep the contact the
// unconstrained optimum loses, also when re-simulated with 4x the steps.
#include "studies/throwing/idp.hpp"

#include <gtest/gtest.h>

#include "studies/throwing/nlopt_solve.hpp"
#include "studies/throwing/solve.hpp"

namespace armstudy::studies {
namespace {

struct Small {
  ThrowingSpec spec;
  ThrowSetup setup;
  VelocityProfile initial;
  Eigen::Vector2d delta;
  // loose: the release and rating limits wide, so that eq. 8 is feasible and IDP starts
  // inside; else only the ratings (8 stages cannot keep 60 W), the release angle as it is
  explicit Small(bool loose = true) {
    spec.steps_per_stage = 8;
    spec.stages = 8;
    spec.power_max = 200;
    spec.current_max = 10;
    if (loose) spec.release_tolerance = 0.6;
    setup = make_throw_setup(spec);
    initial = eq8_profile(spec.start, Eigen::Vector2d::Zero(), spec.release, spec.release_rate,
                          spec.tf, spec.stages);
    delta = spec.release - spec.start;
  }
};

IdpSettings small_idp(int threads) {
  IdpSettings s;
  s.iterations = 4;
  s.max_passes = 12;
  s.tolerance = 3e-3;
  s.restore = 0.7;
  s.candidates = 5;
  s.threads = threads;
  return s;
}

TEST(Idp, FeasibilityRulesPreferFeasibleThenLowerEnergyThenLowerViolation) {
  ProfileEvaluation feasible_low, feasible_high, infeasible_low, infeasible_high, blown;
  feasible_low.feasible = feasible_high.feasible = true;
  feasible_low.energy = 1;
  feasible_high.energy = 2;
  infeasible_low.violation = 0.1;
  infeasible_high.violation = 0.5;
  infeasible_low.energy = infeasible_high.energy = 0.1;  // lower energy does not help
  blown.finite = false;
  EXPECT_TRUE(better_profile(feasible_low, feasible_high));
  EXPECT_FALSE(better_profile(feasible_high, feasible_low));
  EXPECT_TRUE(better_profile(feasible_high, infeasible_low));
  EXPECT_FALSE(better_profile(infeasible_low, feasible_high));
  EXPECT_TRUE(better_profile(infeasible_low, infeasible_high));
  EXPECT_TRUE(better_profile(infeasible_high, blown));
  EXPECT_FALSE(better_profile(blown, infeasible_high));
}

TEST(Idp, FromAFeasibleStartEveryBestIsFeasibleAndTheEnergyNeverRises) {
  Small sm;
  const IdpResult r = run_idp(sm.setup, sm.initial, sm.delta, small_idp(2));
  ASSERT_TRUE(r.initial_evaluation.feasible);
  double prev = r.initial_evaluation.energy;
  for (const auto& h : r.history) {
    EXPECT_EQ(h.violation, 0.0);
    EXPECT_LE(h.energy, prev);
    prev = h.energy;
  }
  EXPECT_LT(r.evaluation.energy, r.initial_evaluation.energy);
  EXPECT_EQ(r.evaluations, 1 + static_cast<long>(r.passes) * 4 * 7 * 5);
  // the best profile keeps the release angles and rates of the active joints
  EXPECT_LT((displacement(r.best) - sm.delta).norm(), 1e-12);
  EXPECT_EQ(r.best.v.col(8), sm.initial.v.col(8));
}

TEST(Idp, ConvergedRunIsUnchangedByADoubledBudget) {
  Small sm;
  const IdpResult a = run_idp(sm.setup, sm.initial, sm.delta, small_idp(2));
  ASSERT_TRUE(a.converged) << "passes " << a.passes << ", last gain " << a.last_gain;
  EXPECT_LT(a.last_gain, 3e-3);
  EXPECT_LT(a.passes, 12);
  IdpSettings twice = small_idp(2);
  twice.max_passes *= 2;
  const IdpResult b = run_idp(sm.setup, sm.initial, sm.delta, twice);
  ASSERT_TRUE(b.converged);
  EXPECT_LT(std::abs(a.evaluation.energy - b.evaluation.energy) / a.evaluation.energy, 3e-3);
}

TEST(Idp, RunCutShortByItsBudgetIsNotConverged) {
  Small sm;
  IdpSettings cut = small_idp(2);
  cut.max_passes = 1;
  const IdpResult r = run_idp(sm.setup, sm.initial, sm.delta, cut);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.passes, 1);
  EXPECT_GT(r.last_gain, 3e-3);  // still gaining when the budget ran out
}

TEST(Idp, SeedsDoNotDependOnTheThreadCount) {
  Small sm;
  IdpSettings s = small_idp(1);
  s.seeds = 3;
  s.max_passes = 2;
  const auto a = run_idp_seeds(sm.setup, sm.initial, sm.delta, s);
  s.threads = 2;
  const auto b = run_idp_seeds(sm.setup, sm.initial, sm.delta, s);
  ASSERT_EQ(a.size(), 3u);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].seed, s.seed + i);
    EXPECT_EQ(a[i].evaluation.energy, b[i].evaluation.energy);
    EXPECT_EQ(a[i].best.v, b[i].best.v);
  }
  EXPECT_NE(a[0].evaluation.energy, a[1].evaluation.energy);  // the seeds do differ
}

TEST(Idp, ParallelEvaluationEqualsSerial) {
  Small sm;
  std::vector<VelocityProfile> ps(7, sm.initial);
  for (int i = 0; i < 7; ++i) ps[i].v(0, 3) += 0.3 * i;
  const auto a = evaluate_profiles(sm.setup, ps, 1, 0.01);
  const auto b = evaluate_profiles(sm.setup, ps, 3, 0.01);
  for (int i = 0; i < 7; ++i) {
    EXPECT_EQ(a[i].energy, b[i].energy);
    EXPECT_EQ(a[i].violation, b[i].violation);
  }
}

TEST(Slsqp, BudgetCutRunIsNotConverged) {
  Small sm;
  NloptSettings ns;
  ns.max_evaluations = 3;
  const NloptOutcome r = run_nlopt(sm.setup, sm.initial, sm.delta, ns);
  EXPECT_EQ(r.return_code, "MAXEVAL_REACHED");
  EXPECT_FALSE(r.converged);
  EXPECT_TRUE(std::isfinite(r.last_gain));
}

TEST(Slsqp, RepairTurnsTheInfeasibleEq8StartFeasible) {
  Small sm(false);  // the real release limit: eq. 8 misses the release angle of the tray
  const ProfileEvaluation raw = simulate_profile(sm.setup, sm.initial, nullptr, 0.0);
  ASSERT_FALSE(raw.feasible);
  NloptSettings ns;
  const NloptOutcome r = run_nlopt(sm.setup, sm.initial, sm.delta, ns, Objective::kViolation);
  ASSERT_TRUE(r.feasible) << r.return_code;
  EXPECT_TRUE(simulate_profile(sm.setup, r.best, nullptr, ns.backoff).feasible);
  EXPECT_LT((displacement(r.best) - sm.delta).norm(), 1e-8);
}

// the unconstrained optimum (no contact, friction or rating limits) lets the tray pull the
// ball; both constrained optimisers keep the contact, also at 4x the steps
TEST(Constrained, OptimaKeepTheContactTheUnconstrainedOptimumLoses) {
  Small sm;
  ThrowSetup free = sm.setup;
  free.contact_margin = -1e3;  // N: no contact condition
  free.friction_coefficient = 1e6;
  NloptSettings ns;
  const NloptOutcome u = run_nlopt(free, sm.initial, sm.delta, ns);
  ASSERT_TRUE(u.feasible) << u.return_code;
  const Verification uv = verify_profile(sm.setup, u.best, 4);
  ASSERT_LT(uv.evaluation.min_normal_force, 0.0) << "the unconstrained optimum keeps contact";

  const NloptOutcome c = run_nlopt(sm.setup, sm.initial, sm.delta, ns);
  ASSERT_TRUE(c.converged) << c.return_code;
  const Verification cv = verify_profile(sm.setup, c.best, 4);
  EXPECT_TRUE(cv.feasible);
  EXPECT_GE(cv.evaluation.min_normal_force, sm.spec.contact_margin);
  EXPECT_LE(cv.evaluation.max_friction_ratio, sm.spec.friction_coefficient);
  EXPECT_GT(c.evaluation.energy, u.evaluation.energy);  // contact costs energy

  IdpSettings is = small_idp(2);
  const IdpResult i = run_idp(sm.setup, sm.initial, sm.delta, is);
  const Verification iv = verify_profile(sm.setup, i.best, 4);
  EXPECT_TRUE(iv.feasible);
  EXPECT_GE(iv.evaluation.min_normal_force, sm.spec.contact_margin);
}

}  // namespace
}  // namespace armstudy::studies
