// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The whole throwing study on a reduced setting (8 stages, 2 seeds): the saving is measured
// from a feasible reference, every reported optimum meets every constraint when re-simulated
// with 4x the steps (independently of the optimiser) and the release state within its
// tolerance, the optimum replays open loop within the stated tolerance, and the ball's
// flight obeys the ballistic formulas.
#include "studies/throwing/solve.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "testing/arms.hpp"

namespace armstudy::studies {
namespace {

ThrowingSpec reduced() {
  ThrowingSpec s;
  s.stages = 8;
  s.steps_per_stage = 20;  // 5 ms steps, as the bundled case's 2.5 ms
  s.idp.iterations = 4;
  s.idp.max_passes = 25;
  s.idp.candidates = 4;
  s.idp.seeds = 2;
  s.idp.tolerance = 5e-3;
  s.idp.restore = 0.7;
  s.nlopt.ftol_rel = 1e-5;
  s.power_max = 200;  // 8 stages cannot keep 60 W; the other limits as in the bundled case
  s.current_max = 10;
  s.grid.refinements = 0;  // one grid (the control grids: throwing_grid_test.cpp)
  return s;
}

void expect_meets_every_constraint(const ThrowingSpec& s, const Verification& v, const char* who) {
  const auto& e = v.evaluation;
  EXPECT_EQ(v.refinement, 4) << who;
  EXPECT_TRUE(v.feasible) << who;
  EXPECT_GE(e.min_normal_force, s.contact_margin) << who;
  EXPECT_LE(e.max_friction_ratio, s.friction_coefficient) << who;
  EXPECT_LE(e.max_abs_theta4, s.tray_width / 2) << who;
  EXPECT_LE(e.max_voltage, s.voltage_max) << who;
  EXPECT_LE(e.max_current, s.current_max) << who;
  EXPECT_LE(e.max_power, s.power_max) << who;
  EXPECT_LE(v.release_error, s.release_tolerance) << who;
  for (double w : v.worst) EXPECT_LE(w, 0.0) << who;
}

TEST(ThrowingStudy, OptimaMeetEveryConstraintAt4xStepsAndBeatAFeasibleReference) {
  const ThrowingSpec s = reduced();
  const ThrowingResult r = solve_throwing(s);
  ASSERT_EQ(r.status, Status::kSolved) << r.message;
  // the raw eq. 8 start misses the tray's release angle: the reference is its repair
  EXPECT_FALSE(r.initial_feasible);
  EXPECT_EQ(r.reference_kind, "repaired");
  EXPECT_TRUE(simulate_profile(make_throw_setup(s), r.reference.profile).feasible);
  ASSERT_EQ(r.idp_seeds.size(), 2u);
  for (const auto& sd : r.idp_seeds)
    EXPECT_TRUE(sd.converged) << "seed " << sd.seed << ": " << sd.passes << " passes, gain "
                              << sd.last_gain;
  expect_meets_every_constraint(s, r.idp_check, "IDP");
  ASSERT_TRUE(r.nlopt_ran);
  EXPECT_TRUE(r.nlopt_run.converged) << r.nlopt_run.return_code;
  expect_meets_every_constraint(s, r.nlopt_check, "SLSQP");
  const auto& e = r.idp.evaluation;
  EXPECT_LT(e.energy, r.reference.evaluation.energy);
  // the saving is the answer's, against the eq. 8 start
  EXPECT_NEAR(
      r.saving_percent,
      100 * (r.initial.evaluation.energy - r.nlopt.evaluation.energy) / r.initial.evaluation.energy,
      1e-9);
  EXPECT_GT(r.saving_percent, 0.0);
  EXPECT_LT(r.replay_error, s.replay_tolerance);
  EXPECT_LT(r.rk4_energy_error, 1e-3);
  // the active joints meet the release state by construction
  EXPECT_LT(r.idp.angle_error.head<2>().norm(), 1e-9);
  EXPECT_LT(r.idp.rate_error.norm(), 1e-9);
  // the recorded series covers [0, tf] with all four coordinates
  EXPECT_EQ(r.idp.series.t.front(), 0.0);
  EXPECT_NEAR(r.idp.series.t.back(), s.tf, 1e-12);
  EXPECT_EQ(r.idp.series.q.front().size(), 4);
  EXPECT_TRUE(r.nlopt_ran);
  // the answer is SLSQP's lowest converged, re-checked local optimum over its starts (IDP's
  // optimum among them, so it is never above IDP's), and its sentence says so
  EXPECT_EQ(r.answer, "slsqp");
  EXPECT_LE(r.nlopt.evaluation.energy, r.idp.evaluation.energy * (1 + 1e-9));
  ASSERT_GE(r.slsqp_starts.size(), 4u);
  for (const auto& st : r.slsqp_starts)
    if (st.run.converged && st.check.feasible) {
      EXPECT_GE(st.run.evaluation.energy, r.nlopt.evaluation.energy) << st.name;
    }
  EXPECT_LE(r.nlopt_run.kkt_residual, s.nlopt.kkt_tolerance);
  EXPECT_TRUE(r.flight.reaches);
  EXPECT_EQ(r.flight.landing.x(), r.nlopt_flight.landing.x());  // the flight is the answer's
  EXPECT_EQ(r.message.rfind("lowest-energy throw found: ", 0), 0u) << r.message;
}

TEST(ThrowingStudy, FlightLandsWhereTheBallisticFormulasSay) {
  const Eigen::Vector2d p(0.15, 0.13), v(-1.7, 1.8);
  const double g = 9.81;
  const Flight f = ballistic_flight(p, v, g, 0.0);
  ASSERT_TRUE(f.reaches);
  // y(T) = 0 and x(T) = x0 + vx T
  EXPECT_NEAR(p.y() + v.y() * f.duration - 0.5 * g * f.duration * f.duration, 0.0, 1e-12);
  EXPECT_NEAR(f.landing.x(), p.x() + v.x() * f.duration, 1e-12);
  EXPECT_NEAR(f.apex, p.y() + v.y() * v.y() / (2 * g), 1e-12);
  EXPECT_TRUE(testing::near_rel_vec(f.path.back(), f.landing, 1e-12));
}

TEST(ThrowingStudy, UnreachableLandingHeightIsAnUnsolvedStudyWithTheApex) {
  ThrowingSpec s = reduced();
  s.run_nlopt = false;
  s.idp.iterations = 1;
  s.idp.max_passes = 1;
  s.idp.seeds = 1;
  s.landing_height = 5.0;
  const ThrowingResult r = solve_throwing(s);
  EXPECT_EQ(r.status, Status::kUnsolvable);
  EXPECT_NE(r.message.find("never reaches the landing height 5.000 m"), std::string::npos)
      << r.message;
  EXPECT_NE(r.message.find("apex"), std::string::npos);
}

}  // namespace
}  // namespace armstudy::studies
