// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The one-pass dynamics of the tray arm (src/studies/throwing/tray_dynamics.hpp) equal the
// generic chain's (core::passive_forward_dynamics and ball_contact_forces) to 1e-12 relative
// at random states of both motor mounts, with rotor inertia, a lateral tray centre of mass
// and a rotated base; and a whole planned throw through the fast path equals the same throw
// through the generic chain, figure by figure.
#include "studies/throwing/tray_dynamics.hpp"

#include <gtest/gtest.h>

#include <random>

#include "studies/throwing/simulate.hpp"
#include "studies/throwing/solve.hpp"
#include "testing/arms.hpp"

namespace armstudy::studies {
namespace {

TEST(TrayDynamics, EqualsTheGenericChainAtRandomStates) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ang(-3.0, 3.0), rate(-40.0, 40.0), acc(-2000.0, 2000.0);
  for (Motor2Mount mount : {Motor2Mount::kOnLink1, Motor2Mount::kOnBase}) {
    TrayArmParams p;
    p.motor2 = mount;
    p.rotor_inertia = 3e-6;
    p.r3_lateral = 0.004;
    core::PlanarChain chain = make_tray_arm(p);
    chain.base_angle = 0.3;
    chain.base = Eigen::Vector2d(0.1, -0.2);
    const TrayDynamics fast(chain);
    int identical = 0;
    for (int k = 0; k < 2000; ++k) {
      core::JointVector q(4), qd(4), qdd(4);
      q << ang(rng), ang(rng), ang(rng), ang(rng);
      qd << rate(rng), rate(rng), rate(rng), rate(rng);
      qdd << acc(rng), acc(rng), 0.0, 0.0;
      const core::MixedDynamics ref =
          core::passive_forward_dynamics(chain, q, qd, qdd, core::JointVector::Zero(4));
      const Eigen::Vector2d f_ref = ball_contact_forces(chain, p.m4, q, qd, ref.qdd);
      Eigen::Vector2d f;
      const core::MixedDynamics d = fast.mixed(q, qd, qdd, p.m4, f);
      ASSERT_TRUE(testing::near_rel_vec(d.qdd, ref.qdd, 1e-12)) << "state " << k;
      ASSERT_TRUE(testing::near_rel_vec(d.tau, ref.tau, 1e-12)) << "state " << k;
      ASSERT_TRUE(testing::near_rel_vec(f, f_ref, 1e-12)) << "state " << k;
      identical += d.qdd == ref.qdd && d.tau == ref.tau && f == f_ref;
    }
    // the same sums in the same order: bit for bit in practice
    EXPECT_EQ(identical, 2000);
  }
  EXPECT_THROW(TrayDynamics{testing::thesis_arm()}, std::invalid_argument);
}

TEST(TrayDynamics, APlannedThrowEqualsTheGenericChainsThrow) {
  ThrowingSpec spec;
  spec.arm.rotor_inertia = 2e-6;
  ThrowSetup setup = make_throw_setup(spec);
  const VelocityProfile profile = eq8_profile(spec.start, Eigen::Vector2d::Zero(), spec.release,
                                              spec.release_rate, spec.tf, spec.stages);
  std::vector<ThrowSample> fast_samples, ref_samples;
  const ProfileEvaluation fast = simulate_profile(setup, profile, &fast_samples);
  setup.generic_dynamics = true;
  const ProfileEvaluation ref = simulate_profile(setup, profile, &ref_samples);
  ASSERT_TRUE(ref.finite);
  EXPECT_TRUE(testing::near_rel(fast.energy, ref.energy, 1e-12));
  EXPECT_TRUE(testing::near_rel(fast.theta3_final, ref.theta3_final, 1e-12));
  EXPECT_TRUE(testing::near_rel(fast.theta4_final, ref.theta4_final, 1e-12));
  EXPECT_TRUE(testing::near_rel(fast.min_normal_force, ref.min_normal_force, 1e-12));
  EXPECT_TRUE(testing::near_rel(fast.max_friction_excess, ref.max_friction_excess, 1e-12));
  EXPECT_TRUE(testing::near_rel(fast.max_power, ref.max_power, 1e-12));
  EXPECT_EQ(fast.feasible, ref.feasible);
  ASSERT_EQ(fast_samples.size(), ref_samples.size());
  for (size_t i = 0; i < ref_samples.size(); ++i) {
    ASSERT_TRUE(testing::near_rel_vec(fast_samples[i].qdd, ref_samples[i].qdd, 1e-12)) << i;
    ASSERT_TRUE(testing::near_rel_vec(fast_samples[i].tau_m, ref_samples[i].tau_m, 1e-12)) << i;
    ASSERT_TRUE(testing::near_rel(fast_samples[i].normal_force, ref_samples[i].normal_force, 1e-12))
        << i;
  }
}

}  // namespace
}  // namespace armstudy::studies
