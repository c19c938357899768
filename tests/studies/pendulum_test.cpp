// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The pendulum test of 003 Sec. 3 (pendulum.hpp): with joints 1 and 2 locked the tray and
// the rolling ball conserve mechanical energy to 1e-8 over 2 s; the equilibrium stays at
// rest; snapshots come every 0.13 s; small swings have the period of the linearised system.
#include "studies/pendulum/solve.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/dynamics.hpp"

namespace armstudy::studies {
namespace {

TEST(Pendulum, ConservesMechanicalEnergyToOneInTenToTheEightOverTwoSeconds) {
  const PendulumResult r = solve_pendulum(default_pendulum_spec());
  ASSERT_EQ(r.status, Status::kSolved) << r.message;
  EXPECT_NEAR(r.t.back(), 2.0, 1e-12);
  EXPECT_LE(r.energy_drift_rel, 1e-8);
  EXPECT_GT(r.energy_scale, 1e-3);  // the motion exchanges real energy
  // the locked joints never move
  for (const auto& q : r.q) {
    EXPECT_EQ(q[0], 0.0);
    EXPECT_EQ(q[1], 0.0);
  }
}

TEST(Pendulum, LooserToleranceDriftsMoreSoTheCheckCanFail) {
  PendulumSpec s = default_pendulum_spec();
  s.rtol = s.atol = 1e-4;
  s.sample_step = 0.13;  // output times bound the step: let the tolerance decide it
  const PendulumResult r = solve_pendulum(s);
  ASSERT_EQ(r.status, Status::kSolved);
  EXPECT_GT(r.energy_drift_rel, 1e-8);
  EXPECT_GT(r.energy_drift_rel, 100 * solve_pendulum(default_pendulum_spec()).energy_drift_rel);
}

TEST(Pendulum, SnapshotsEveryPoint13Seconds) {
  const PendulumResult r = solve_pendulum(default_pendulum_spec());
  ASSERT_EQ(r.snapshot_t.size(), 16u);  // 0, 0.13, ..., 1.95
  for (size_t i = 0; i < r.snapshot_t.size(); ++i) {
    EXPECT_NEAR(r.snapshot_t[i], 0.13 * i, 1e-12);
    EXPECT_NEAR(r.t[r.snapshot_index[i]], r.snapshot_t[i], 1e-12);
  }
}

TEST(Pendulum, HangingAtRestStaysAtRest) {
  PendulumSpec s = default_pendulum_spec();
  s.theta4 = 0.0;  // ball at the cup bottom, tray hanging: an equilibrium
  const PendulumResult r = solve_pendulum(s);
  for (const auto& q : r.q) {
    EXPECT_NEAR(q[2], -core::kPi / 2, 1e-12);
    EXPECT_NEAR(q[3], 0.0, 1e-12);
  }
}

TEST(Pendulum, SmallSwingsHaveTheLinearisedPeriods) {
  // linearise about the hanging equilibrium: M x'' + K x = 0 for (theta3, theta4)
  PendulumSpec s = default_pendulum_spec();
  const core::PlanarChain chain = make_tray_arm(s.arm);
  core::JointVector q0(4);
  q0 << 0.0, 0.0, -core::kPi / 2, 0.0;
  const core::JointMatrix M = core::mass_matrix(chain, q0).bottomRightCorner(2, 2);
  Eigen::Matrix2d K;
  const double d = 1e-5;
  for (int j = 0; j < 2; ++j) {
    core::JointVector qp = q0, qm = q0;
    qp[2 + j] += d;
    qm[2 + j] -= d;
    const core::JointVector z = core::JointVector::Zero(4);
    K.col(j) =
        (core::bias_forces(chain, qp, z) - core::bias_forces(chain, qm, z)).tail(2) / (2 * d);
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> es(K, Eigen::Matrix2d(M));
  const Eigen::Vector2d w = es.eigenvalues().cwiseSqrt();
  const Eigen::Vector2d mode = es.eigenvectors().col(0);  // slow mode
  // start a tiny swing along the slow mode and find its period by zero crossings
  s.theta3 = -core::kPi / 2 + 1e-4 * mode[0] / mode.norm();
  s.theta4 = 1e-4 * mode[1] / mode.norm();
  s.duration = 3.0;
  s.sample_step = 1e-3;
  const PendulumResult r = solve_pendulum(s);
  std::vector<double> up;
  for (size_t k = 1; k < r.t.size(); ++k) {
    const double a = r.q[k - 1][3], b = r.q[k][3];
    if (a < 0 && b >= 0) up.push_back(r.t[k - 1] + (r.t[k] - r.t[k - 1]) * (-a) / (b - a));
  }
  ASSERT_GE(up.size(), 2u);
  const double period = (up.back() - up.front()) / (up.size() - 1);
  EXPECT_NEAR(period, 2 * core::kPi / w[0], 1e-3 * period);
}

}  // namespace
}  // namespace armstudy::studies
