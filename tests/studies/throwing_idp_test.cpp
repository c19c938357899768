// IDP (idp.hpp) and the SLSQP comparison (nlopt_solve.hpp) on a small instance of the
// throw: IDP never accepts a worse trajectory, its answer does not depend on the number of
// threads, and every candidate keeps the release angles of the active joints.
#include "studies/throwing/idp.hpp"

#include <gtest/gtest.h>

#include "studies/throwing/nlopt_solve.hpp"
#include "studies/throwing/throwing.hpp"

namespace armstudy::studies {
namespace {

struct Small {
  ThrowingSpec spec;
  ThrowSetup setup;
  VelocityProfile initial;
  Eigen::Vector2d delta;
  Small() {
    spec.steps_per_stage = 8;
    setup = make_throw_setup(spec);
    initial = eq8_profile(spec.start, Eigen::Vector2d::Zero(), spec.release, spec.release_rate,
                          spec.tf, 8);
    delta = spec.release - spec.start;
  }
};

IdpSettings small_idp(int threads) {
  IdpSettings s;
  s.iterations = 4;
  s.passes = 2;
  s.candidates = 5;
  s.threads = threads;
  return s;
}

TEST(Idp, CriterionNeverIncreasesAndEndsBelowTheStart) {
  Small sm;
  const IdpResult r = run_idp(sm.setup, sm.initial, sm.delta, small_idp(2));
  ASSERT_EQ(r.history.size(), 8u);
  double prev = r.initial_evaluation.criterion;
  for (const auto& h : r.history) {
    EXPECT_LE(h.criterion, prev);
    prev = h.criterion;
  }
  EXPECT_LT(r.evaluation.criterion, r.initial_evaluation.criterion);
  EXPECT_EQ(r.evaluations, 1 + 8L * 7 * 5);
  // the best profile keeps the release angles and rates of the active joints
  EXPECT_LT((displacement(r.best) - sm.delta).norm(), 1e-12);
  EXPECT_EQ(r.best.v.col(8), sm.initial.v.col(8));
}

TEST(Idp, AnswerDoesNotDependOnTheThreadCount) {
  Small sm;
  const IdpResult a = run_idp(sm.setup, sm.initial, sm.delta, small_idp(1));
  const IdpResult b = run_idp(sm.setup, sm.initial, sm.delta, small_idp(2));
  EXPECT_EQ(a.evaluation.criterion, b.evaluation.criterion);
  EXPECT_EQ(a.best.v, b.best.v);
}

TEST(Idp, ParallelEvaluationEqualsSerial) {
  Small sm;
  std::vector<VelocityProfile> ps(7, sm.initial);
  for (int i = 0; i < 7; ++i) ps[i].v(0, 3) += 0.3 * i;
  const auto a = evaluate_profiles(sm.setup, ps, 1);
  const auto b = evaluate_profiles(sm.setup, ps, 3);
  for (int i = 0; i < 7; ++i) EXPECT_EQ(a[i].criterion, b[i].criterion);
}

TEST(Slsqp, KeepsTheReleaseAnglesAndLowersTheEnergyOfItsFeasiblePoints) {
  Small sm;
  NloptSettings ns;
  ns.max_evaluations = 15;
  ns.threads = 2;
  const NloptOutcome r = run_nlopt(sm.setup, sm.initial, sm.delta, ns);
  EXPECT_FALSE(r.return_code.empty());
  EXPECT_GT(r.simulations, 0);
  EXPECT_LT((displacement(r.last) - sm.delta).norm(), 1e-6);
  if (r.feasible) {
    EXPECT_LE(r.evaluation.max_abs_theta4, sm.setup.half_width + 1e-6);
    EXPECT_LE(r.evaluation.max_current, sm.setup.current_max * (1 + 1e-6));
  }
}

}  // namespace
}  // namespace armstudy::studies
