// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The tray arm as a core::PlanarChain (src/studies/tray_arm.hpp): its kinetic and
// potential energy equal the first-principles expressions written out here independently
// (positions of every centre of mass, rolling ball spin), and the motor mapping is
// power-consistent for both mounts of motor 2.
#include "studies/tray_arm.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/dynamics.hpp"
#include "testing/arms.hpp"

namespace armstudy::studies {
namespace {

using Vec2 = Eigen::Vector2d;
Vec2 e(double a) { return {std::cos(a), std::sin(a)}; }
Vec2 perp(const Vec2& v) { return {-v.y(), v.x()}; }

// kinetic and potential energy from the positions of 003's Fig. 1, written out by hand
struct Energies {
  double K, U;
};
Energies hand_energies(const TrayArmParams& p, const core::JointVector& q,
                       const core::JointVector& qd) {
  const double a1 = q[0], a2 = a1 + q[1], a3 = a2 + q[2], a4 = a3 + q[3];
  const double w1 = qd[0], w2 = w1 + qd[1], w3 = w2 + qd[2], w4 = w3 + qd[3];
  // positions and velocities of the centres of mass (d/dt e(a) = w perp(e(a)))
  const Vec2 v1 = p.r1 * w1 * perp(e(a1));
  const Vec2 v2 = p.l1 * w1 * perp(e(a1)) + p.r2 * w2 * perp(e(a2));
  const Vec2 base3 = p.l1 * w1 * perp(e(a1)) + p.l2 * w2 * perp(e(a2));
  const Vec2 v3 = base3 + w3 * perp(p.r3 * e(a3) + p.r3_lateral * perp(e(a3)));
  const Vec2 v4 = base3 + p.circle_offset * w3 * perp(e(a3)) + p.r4 * w4 * perp(e(a4));
  // rolling: the ball's absolute spin is the tray's rate minus (r4 / rb) theta4'
  const double wb = w3 - (p.r4 / p.rb) * qd[3];
  const double K =
      0.5 * (p.m1 * v1.squaredNorm() + p.I1 * w1 * w1 + p.m2 * v2.squaredNorm() + p.I2 * w2 * w2 +
             p.m3 * v3.squaredNorm() + p.I3 * w3 * w3 + p.m4 * v4.squaredNorm() + p.Ib * wb * wb);
  const double y1 = p.r1 * std::sin(a1);
  const double y2 = p.l1 * std::sin(a1) + p.r2 * std::sin(a2);
  const double y3 =
      p.l1 * std::sin(a1) + p.l2 * std::sin(a2) + p.r3 * std::sin(a3) + p.r3_lateral * std::cos(a3);
  const double y4 = p.l1 * std::sin(a1) + p.l2 * std::sin(a2) + p.circle_offset * std::sin(a3) +
                    p.r4 * std::sin(a4);
  const double U = p.gravity * (p.m1 * y1 + p.m2 * y2 + p.m3 * y3 + p.m4 * y4);
  return {K, U};
}

TEST(TrayArm, EnergiesMatchFirstPrinciplesForRandomStates) {
  std::mt19937 rng(5);
  TrayArmParams p;
  p.r3_lateral = 0.004;  // exercise the lateral centre of mass too
  p.circle_offset = 0.021;
  const core::PlanarChain chain = make_tray_arm(p);
  for (int trial = 0; trial < 50; ++trial) {
    const core::JointVector q = testing::random_joints(rng, 4, 3.0);
    const core::JointVector qd = testing::random_joints(rng, 4, 10.0);
    const Energies h = hand_energies(p, q, qd);
    EXPECT_TRUE(testing::near_rel(core::kinetic_energy(chain, q, qd), h.K, 1e-12));
    EXPECT_TRUE(testing::near_rel(core::potential_energy(chain, q), h.U, 1e-12));
  }
}

TEST(TrayArm, TrayAndBallJointsArePassiveAndTheBallIsTheTip) {
  TrayArmParams p;
  const core::PlanarChain chain = make_tray_arm(p);
  ASSERT_EQ(chain.num_links(), 4);
  EXPECT_TRUE(chain.links[0].active);
  EXPECT_TRUE(chain.links[1].active);
  EXPECT_FALSE(chain.links[2].active);
  EXPECT_FALSE(chain.links[3].active);
  core::JointVector q(4);
  q << 0.3, -0.2, 0.5, 0.1;
  const Vec2 expect = p.l1 * e(0.3) + p.l2 * e(0.1) + p.circle_offset * e(0.6) + p.r4 * e(0.7);
  EXPECT_TRUE(testing::near_rel_vec(ball_position(chain, q), expect, 1e-14));
}

TEST(TrayArm, MotorTorquesDoTheSameWorkAsJointTorquesForBothMounts) {
  std::mt19937 rng(11);
  for (Motor2Mount mount : {Motor2Mount::kOnLink1, Motor2Mount::kOnBase}) {
    const Eigen::Matrix<double, 2, 4> B = motor_matrix(mount);
    for (int trial = 0; trial < 20; ++trial) {
      const core::JointVector qd = testing::random_joints(rng, 4, 5.0);
      const core::JointVector tau = testing::random_joints(rng, 4, 2.0);
      const Eigen::Vector2d tau_m = motor_torques(mount, tau);
      const Eigen::Matrix<double, 4, 1> qd4 = qd;
      const Eigen::Vector2d rate = B * qd4;
      // power of the motors equals the power of the active joint torques
      core::JointVector active = tau;
      active[2] = active[3] = 0.0;
      EXPECT_TRUE(testing::near_rel(tau_m.dot(rate), active.dot(qd), 1e-13));
      EXPECT_TRUE(testing::near_rel_vec(joint_torques(mount, tau_m), active, 1e-14));
    }
  }
}

TEST(TrayArm, RotorInertiaAddsOnTheMotorRates) {
  TrayArmParams p;
  p.rotor_inertia = 3e-6;
  p.motor2 = Motor2Mount::kOnBase;
  const core::PlanarChain with = make_tray_arm(p);
  p.rotor_inertia = 0.0;
  const core::PlanarChain without = make_tray_arm(p);
  core::JointVector q(4), qd(4);
  q << 0.1, 0.2, -0.3, 0.05;
  qd << 1.0, -2.0, 0.5, 3.0;
  // rotor 1 spins at qd1, rotor 2 (on the base) at qd1 + qd2
  const double extra = 0.5 * 3e-6 * (1.0 * 1.0 + (1.0 - 2.0) * (1.0 - 2.0));
  EXPECT_TRUE(testing::near_rel(
      core::kinetic_energy(with, q, qd) - core::kinetic_energy(without, q, qd), extra, 1e-12));
}

TEST(TrayArm, RejectsNonPositiveBallRadius) {
  TrayArmParams p;
  p.rb = 0.0;
  EXPECT_THROW(make_tray_arm(p), std::invalid_argument);
}

}  // namespace
}  // namespace armstudy::studies
