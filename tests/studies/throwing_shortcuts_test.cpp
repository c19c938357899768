// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The throwing study's shortcuts give the answers of the full computations they replace:
// a simulation stopped at its first certain violation (simulate_profile's
// stop_when_infeasible) belongs to an infeasible profile, one that is not stopped equals the
// full simulation bit for bit, and IDP with the stop makes exactly the choices of IDP
// without it; a central-difference neighbour resumed from its point's checkpoints
// (simulate_profile_from, evaluate_neighbours) equals its full simulation bit for bit.
#include <gtest/gtest.h>

#include <random>

#include "studies/throwing/idp.hpp"
#include "studies/throwing/simulate.hpp"
#include "studies/throwing/solve.hpp"

namespace armstudy::studies {
namespace {

struct ShortcutCase {
  ThrowingSpec spec;
  ThrowSetup setup;
  VelocityProfile eq8;
  Eigen::Vector2d delta;
  explicit ShortcutCase(int stages = 16, int steps = 20) {
    spec.stages = stages;
    spec.steps_per_stage = steps;
    setup = make_throw_setup(spec);
    eq8 = eq8_profile(spec.start, Eigen::Vector2d::Zero(), spec.release, spec.release_rate, spec.tf,
                      spec.stages);
    delta = spec.release - spec.start;
  }
  // ratings and release angle wide enough for eq. 8 to be feasible
  void loosen() {
    spec.power_max = 200;
    spec.current_max = 10;
    spec.release_tolerance = 0.6;
    setup = make_throw_setup(spec);
  }
};

void expect_same(const ProfileEvaluation& a, const ProfileEvaluation& b, int i) {
  EXPECT_EQ(a.energy, b.energy) << i;
  EXPECT_EQ(a.violation, b.violation) << i;
  EXPECT_EQ(a.feasible, b.feasible) << i;
  EXPECT_EQ(a.finite, b.finite) << i;
  EXPECT_EQ(a.theta3_final, b.theta3_final) << i;
  EXPECT_EQ(a.max_power, b.max_power) << i;
  EXPECT_EQ(a.min_normal_force, b.min_normal_force) << i;
  EXPECT_EQ(a.max_friction_ratio, b.max_friction_ratio) << i;
  EXPECT_EQ(a.stage_friction, b.stage_friction) << i;
}

TEST(ThrowShortcuts, AStoppedSimulationIsInfeasibleAndAFinishedOneIsTheFullOne) {
  // from the feasible eq. 8 (wide limits) along random directions out to infeasible profiles,
  // the points on both sides of the feasibility boundary found by bisection: the last
  // feasible one is a hair inside a limit
  for (Motor2Mount mount : {Motor2Mount::kOnLink1, Motor2Mount::kOnBase}) {
    ShortcutCase c;
    c.spec.arm.motor2 = mount;
    c.loosen();
    ASSERT_TRUE(simulate_profile(c.setup, c.eq8, nullptr, 0.02).feasible);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int stopped = 0, finished = 0, feasible = 0;
    auto check = [&](const VelocityProfile& p, int i) {
      const ProfileEvaluation full = simulate_profile(c.setup, p, nullptr, 0.02);
      const ProfileEvaluation early = simulate_profile(c.setup, p, nullptr, 0.02, true);
      EXPECT_FALSE(full.stopped);
      if (early.stopped) {
        ++stopped;
        EXPECT_FALSE(full.feasible) << i;
        EXPECT_GT(full.violation, 0.0) << i;
        EXPECT_FALSE(early.feasible) << i;
        EXPECT_FALSE(better_profile(early, full)) << i;
      } else {
        ++finished;
        feasible += full.feasible;
        expect_same(early, full, i);
      }
      return full.feasible;
    };
    for (int i = 0; i < 12; ++i) {
      Eigen::Matrix<double, 2, Eigen::Dynamic> dir = Eigen::MatrixXd::Zero(2, c.eq8.v.cols());
      for (int k = 1; k < c.eq8.stages(); ++k) dir.col(k) = 4.0 * Eigen::Vector2d(u(rng), u(rng));
      auto at = [&](double a) {
        VelocityProfile p = c.eq8;
        p.v += a * dir;
        project_displacement(p, c.delta);
        return p;
      };
      if (check(at(1.0), i)) continue;
      double lo = 0.0, hi = 1.0;
      for (int b = 0; b < 40; ++b) {
        const double mid = 0.5 * (lo + hi);
        (simulate_profile(c.setup, at(mid), nullptr, 0.02).feasible ? lo : hi) = mid;
      }
      EXPECT_TRUE(check(at(lo), i));
      EXPECT_FALSE(check(at(hi), i));
    }
    EXPECT_GT(stopped, 5);
    EXPECT_GT(finished, 5);
    EXPECT_GT(feasible, 5);
  }
}

TEST(ThrowShortcuts, IdpWithTheEarlyStopMakesTheChoicesOfFullSimulations) {
  // wide limits but the power: 1 % inside its limit (with the back-off) at the start, so
  // that many candidates break it, some early in the throw
  ShortcutCase c(8, 8);
  c.loosen();
  c.spec.power_max = simulate_profile(c.setup, c.eq8).max_power / 0.97;
  c.setup = make_throw_setup(c.spec);
  IdpSettings s;
  s.iterations = 3;
  s.max_passes = 4;
  s.threads = 2;
  s.backoff = 0.02;
  const IdpResult a = run_idp(c.setup, c.eq8, c.delta, s);
  ASSERT_TRUE(a.initial_evaluation.feasible);
  s.stop_infeasible_candidates = false;
  const IdpResult b = run_idp(c.setup, c.eq8, c.delta, s);
  EXPECT_EQ(a.best.v, b.best.v);
  expect_same(a.evaluation, b.evaluation, -1);
  EXPECT_EQ(a.evaluations, b.evaluations);
  ASSERT_EQ(a.history.size(), b.history.size());
  for (size_t i = 0; i < a.history.size(); ++i) {
    EXPECT_EQ(a.history[i].energy, b.history[i].energy);
    EXPECT_EQ(a.history[i].improvements, b.history[i].improvements);
  }
  EXPECT_LT(a.evaluation.energy, a.initial_evaluation.energy);  // it did move
}

TEST(ThrowShortcuts, ANeighbourResumedFromCheckpointsEqualsItsFullSimulation) {
  for (Motor2Mount mount : {Motor2Mount::kOnLink1, Motor2Mount::kOnBase}) {
    ShortcutCase c;
    c.spec.arm.motor2 = mount;
    c.spec.arm.rotor_inertia = 2e-6;
    c.setup = make_throw_setup(c.spec);
    SimulationCheckpoints base;
    const ProfileEvaluation e0 = simulate_profile(c.setup, c.eq8, base, 0.02);
    expect_same(e0, simulate_profile(c.setup, c.eq8, nullptr, 0.02), -1);
    ASSERT_EQ(static_cast<int>(base.x.size()), c.eq8.stages());
    std::vector<VelocityProfile> ps{c.eq8};
    std::vector<int> first{0};
    for (int k = 1; k < c.eq8.stages(); ++k)
      for (int j = 0; j < 2; ++j)
        for (double step : {1e-5, -0.5}) {
          VelocityProfile p = c.eq8;
          p.v(j, k) += step;
          const ProfileEvaluation full = simulate_profile(c.setup, p, nullptr, 0.02);
          expect_same(simulate_profile_from(c.setup, p, base, k - 1, 0.02), full, k);
          // resuming earlier is the same computation too
          expect_same(simulate_profile_from(c.setup, p, base, (k - 1) / 2, 0.02), full, k);
          ps.push_back(p);
          first.push_back(k - 1);
        }
    const auto serial = evaluate_profiles(c.setup, ps, 1, 0.02);
    const auto resumed = evaluate_neighbours(c.setup, ps, first, 2, 0.02);
    ASSERT_EQ(serial.size(), resumed.size());
    for (size_t i = 0; i < ps.size(); ++i) expect_same(resumed[i], serial[i], static_cast<int>(i));
    // a profile that differs before the resume point is refused
    VelocityProfile early = c.eq8;
    early.v(0, 2) += 1e-5;
    EXPECT_THROW(simulate_profile_from(c.setup, early, base, 3, 0.02), std::invalid_argument);
  }
}

}  // namespace
}  // namespace armstudy::studies
