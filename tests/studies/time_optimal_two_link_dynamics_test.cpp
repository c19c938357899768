// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The closed-form 2-link path dynamics (src/studies/time_optimal/two_link_dynamics.hpp)
// equal core's generic chain to 1e-12 relative: a = M q', b = M q'' + C(q, q') q', c = g(q)
// at random states of arms with lateral centres of mass, point masses, spinners, gravity and
// a rotated base (joint_point uses it for every point of a tip path).
#include "studies/time_optimal/two_link_dynamics.hpp"

#include <gtest/gtest.h>

#include <random>

#include "core/dynamics.hpp"
#include "studies/time_optimal/path.hpp"
#include "testing/arms.hpp"

namespace armstudy::studies::time_optimal {
namespace {

core::PlanarChain rich_arm_with_rotor(double gravity) {
  core::PlanarChain c;
  c.links = {{0.5, 2.0, 0.2, 0.03, 0.04, true}, {0.4, 1.5, 0.25, -0.02, 0.02, true}};
  c.point_masses = {{1, 0.4, 0.01, 0.7}, {0, 0.3, -0.02, 0.2}};
  core::SpinningInertia rotor;
  rotor.inertia = 0.003;
  rotor.coeffs = core::JointVector(2);
  rotor.coeffs << 1.0, 2.5;
  c.spinners = {rotor};
  c.gravity = gravity;
  c.base_angle = 0.4;
  c.base = Eigen::Vector2d(0.1, 0.2);
  return core::make_chain(c);
}

TEST(TwoLinkPathDynamics, EqualsTheGenericChainTo1e12) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ang(-3.0, 3.0), d1(-5.0, 5.0), d2(-50.0, 50.0);
  for (const core::PlanarChain& chain :
       {rich_arm_with_rotor(0.0), rich_arm_with_rotor(9.81), default_arm(1.0, 1.0)}) {
    const TwoLinkDynamics dyn = make_two_link_dynamics(chain);
    for (int k = 0; k < 2000; ++k) {
      core::JointVector q(2), dq(2), ddq(2), a, b, c;
      q << ang(rng), ang(rng);
      dq << d1(rng), d1(rng);
      ddq << d2(rng), d2(rng);
      path_dynamics(dyn, q, dq, ddq, &a, &b, &c);
      const core::JointVector zero = core::JointVector::Zero(2);
      const core::JointVector c_ref = core::inverse_dynamics(chain, q, zero, zero);
      const core::JointVector a_ref = core::mass_matrix(chain, q) * dq;
      const core::JointVector b_ref = core::inverse_dynamics(chain, q, dq, ddq) - c_ref;
      ASSERT_TRUE(testing::near_rel_vec(a, a_ref, 1e-12)) << k;
      ASSERT_TRUE(testing::near_rel_vec(b, b_ref, 1e-12)) << k;
      ASSERT_TRUE(testing::near_rel_vec(c, c_ref, 1e-12)) << k;
      // the dense re-check's inverse dynamics at joint rates qd = dq, qdd = ddq
      core::JointVector tau;
      inverse_dynamics(dyn, q, dq, ddq, &tau);
      ASSERT_TRUE(testing::near_rel_vec(tau, core::inverse_dynamics(chain, q, dq, ddq), 1e-12))
          << k;
    }
  }
  EXPECT_THROW(make_two_link_dynamics(testing::tray_arm()), std::invalid_argument);
}

}  // namespace
}  // namespace armstudy::studies::time_optimal
