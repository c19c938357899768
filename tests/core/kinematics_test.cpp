// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "core/kinematics.hpp"

#include <gtest/gtest.h>

#include "testing/arms.hpp"

namespace armstudy::core {
namespace {

using testing::arm_factory;
using testing::near_rel_vec;
using testing::random_joints;

TEST(Kinematics, JacobianMatchesCentralDifference) {
  std::mt19937 rng(7);
  for (const auto& arm : arm_factory()) {
    const int n = arm.chain.num_links();
    for (int trial = 0; trial < 20; ++trial) {
      const JointVector q = random_joints(rng, n, 3.0);
      const ChainPose pose = forward_kinematics(arm.chain, q);
      for (int link = 0; link < n; ++link) {
        const Eigen::Vector2d p_L(0.3 * arm.chain.links[link].length, 0.01);
        const PointJacobian J = point_jacobian(pose, link, p_L);
        const double h = 1e-6;
        for (int j = 0; j < n; ++j) {
          JointVector qp = q, qm = q;
          qp[j] += h;
          qm[j] -= h;
          const Eigen::Vector2d d = (point_position(forward_kinematics(arm.chain, qp), link, p_L) -
                                     point_position(forward_kinematics(arm.chain, qm), link, p_L)) /
                                    (2 * h);
          EXPECT_TRUE(near_rel_vec(J.col(j), d, 1e-8))
              << arm.name << " link " << link << " col " << j;
        }
      }
    }
  }
}

TEST(Kinematics, JacobianDotMatchesCentralDifferenceAlongVelocity) {
  std::mt19937 rng(11);
  for (const auto& arm : arm_factory()) {
    const int n = arm.chain.num_links();
    for (int trial = 0; trial < 20; ++trial) {
      const JointVector q = random_joints(rng, n, 3.0);
      const JointVector qd = random_joints(rng, n, 5.0);
      const int link = n - 1;
      const Eigen::Vector2d p_L(arm.chain.links[link].length, -0.02);
      const PointJacobian Jd = point_jacobian_dot(forward_kinematics(arm.chain, q), qd, link, p_L);
      const double h = 1e-6;
      const JointVector qp = q + h * qd, qm = q - h * qd;
      const PointJacobian d = (point_jacobian(forward_kinematics(arm.chain, qp), link, p_L) -
                               point_jacobian(forward_kinematics(arm.chain, qm), link, p_L)) /
                              (2 * h);
      EXPECT_TRUE(near_rel_vec(Jd.reshaped(), d.reshaped(), 1e-7)) << arm.name;
    }
  }
}

TEST(Kinematics, TwoLinkManipulabilityIsL1L2SinElbow) {
  const auto chain = testing::thesis_arm();
  for (double q2 : {-2.5, -0.3, 0.0, 0.7, 1.9}) {
    JointVector q(2);
    q << 0.4, q2;
    EXPECT_NEAR(manipulability(chain, q), 0.4 * 0.2 * std::abs(std::sin(q2)), 1e-12);
  }
  JointVector q(2);
  q << 0.1, 0.0;
  EXPECT_NEAR(smallest_singular_value(chain, q), 0.0, 1e-12);
}

TEST(Kinematics, WrongJointCountThrowsWithSizes) {
  const auto chain = testing::thesis_arm();
  JointVector q(3);
  q.setZero();
  try {
    forward_kinematics(chain, q);
    FAIL() << "expected a throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("3 entries"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace armstudy::core
