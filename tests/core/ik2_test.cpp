// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "core/ik2.hpp"

#include <gtest/gtest.h>

#include "core/kinematics.hpp"
#include "testing/arms.hpp"

namespace armstudy::core {
namespace {

using testing::near_rel_vec;

TEST(Ik2, IkThenFkReturnsThePointInBothConfigurations) {
  const auto chain = testing::thesis_arm();
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> r(0.2 + 1e-3, 0.6 - 1e-3), a(-3.1, 3.1);
  for (int trial = 0; trial < 200; ++trial) {
    const double rad = r(rng), ang = a(rng);
    const Eigen::Vector2d p(rad * std::cos(ang), rad * std::sin(ang));
    for (int config : {1, 2}) {
      const auto q = ik_2link(0.4, 0.2, p, config);
      ASSERT_TRUE(q.has_value());
      if (config == 1)
        EXPECT_GT((*q)[1], 0.0);
      else
        EXPECT_LT((*q)[1], 0.0);
      JointVector qv(2);
      qv << (*q)[0], (*q)[1];
      EXPECT_TRUE(near_rel_vec(end_effector(chain, qv), p, 1e-12));
    }
  }
}

TEST(Ik2, VelocityAndAccelerationMatchTheJacobian) {
  const auto chain = testing::thesis_arm();
  const Eigen::Vector2d p(0.35, 0.2), v(-0.3, 0.5), acc(1.2, -0.7);
  for (int config : {1, 2}) {
    const auto st = ik_2link_motion(0.4, 0.2, p, v, acc, config);
    ASSERT_TRUE(st.has_value());
    JointVector q(2), qd(2), qdd(2);
    q << st->q[0], st->q[1];
    qd << st->qd[0], st->qd[1];
    qdd << st->qdd[0], st->qdd[1];
    const ChainPose pose = forward_kinematics(chain, q);
    const Eigen::Vector2d tip(0.2, 0.0);
    EXPECT_TRUE(near_rel_vec(point_jacobian(pose, 1, tip) * qd, v, 1e-12));
    const Eigen::Vector2d a2 =
        point_jacobian(pose, 1, tip) * qdd + point_jacobian_dot(pose, qd, 1, tip) * qd;
    EXPECT_TRUE(near_rel_vec(a2, acc, 1e-12));
  }
}

TEST(Ik2, ReachNamesHowFarOutsideTheAnnulus) {
  const Reach out = reach_2link(0.4, 0.2, Eigen::Vector2d(0.72, 0.0));
  EXPECT_FALSE(out.reachable());
  EXPECT_NEAR(out.margin, -0.12, 1e-12);
  EXPECT_NEAR(out.inner, 0.2, 1e-15);
  EXPECT_NEAR(out.outer, 0.6, 1e-15);
  const Reach in = reach_2link(0.4, 0.2, Eigen::Vector2d(0.0, 0.15));
  EXPECT_NEAR(in.margin, -0.05, 1e-12);
  EXPECT_FALSE(ik_2link(0.4, 0.2, Eigen::Vector2d(0.72, 0.0), 1).has_value());
  EXPECT_THROW(ik_2link(0.4, 0.2, Eigen::Vector2d(0.3, 0.0), 3), std::invalid_argument);
}

}  // namespace
}  // namespace armstudy::core
