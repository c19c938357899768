// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The closed-form 2-link evaluator of the placement study against core's generic
// kinematics and Kane dynamics, and the integrals it computes.
#include "studies/placement/arm2.hpp"

#include <gtest/gtest.h>

#include <random>

#include "core/dynamics.hpp"
#include "core/energy.hpp"
#include "core/ik2.hpp"
#include "core/kinematics.hpp"
#include "studies/placement/geometry.hpp"
#include "testing/arms.hpp"

namespace armstudy::studies::placement {
namespace {

using testing::near_rel;
using testing::near_rel_vec;

// a 2-link horizontal arm with lateral centres of mass, extra point masses and a rotor
core::PlanarChain odd_arm() {
  core::PlanarChain c;
  c.links = {{0.5, 3.0, 0.22, 0.01, 0.07, true}, {0.35, 1.5, 0.15, -0.02, 0.02, true}};
  c.point_masses = {{1, 0.35, 0.0, 0.5}, {0, 0.3, 0.02, 0.4}, {1, 0.1, -0.03, 0.2}};
  core::SpinningInertia rotor;
  rotor.inertia = 1e-3;
  rotor.coeffs.resize(2);
  rotor.coeffs << 0.0, 1.0;
  c.spinners = {rotor};
  return core::make_chain(c);
}

TEST(PlacementArm2, SampleEqualsCoreIkAndInverseDynamics) {
  std::mt19937 rng(11);
  for (const auto& chain : {testing::thesis_arm(), odd_arm()}) {
    const Arm2 arm = make_arm2(chain);
    const Annulus an = annulus(arm.L1, arm.L2);
    std::uniform_real_distribution<double> rad(an.inner + 1e-3, an.outer - 1e-3), ang(-3.1, 3.1),
        vel(-2, 2), acc(-20, 20);
    for (int trial = 0; trial < 500; ++trial) {
      const double r = rad(rng), a = ang(rng);
      const Eigen::Vector2d p(r * std::cos(a), r * std::sin(a)), v(vel(rng), vel(rng)),
          ac(acc(rng), acc(rng));
      for (const int config : {1, 2}) {
        const auto st = core::ik_2link_motion(arm.L1, arm.L2, p, v, ac, config);
        ASSERT_TRUE(st);
        core::JointVector q(2), qd(2), qdd(2);
        q << st->q[0], st->q[1];
        qd << st->qd[0], st->qd[1];
        qdd << st->qdd[0], st->qdd[1];
        const core::JointVector tau = core::inverse_dynamics(chain, q, qd, qdd);
        const Arm2Sample o =
            arm2_sample(arm, p.x(), p.y(), v.x(), v.y(), ac.x(), ac.y(), config == 1 ? 1.0 : -1.0);
        EXPECT_TRUE(near_rel(o.c2, std::cos(st->q[1]), 1e-12));
        EXPECT_TRUE(near_rel(o.s2, std::sin(st->q[1]), 1e-12));
        EXPECT_TRUE(near_rel(o.c1, std::cos(st->q[0]), 1e-12));
        EXPECT_TRUE(near_rel(o.s1, std::sin(st->q[0]), 1e-12));
        EXPECT_TRUE(near_rel_vec(Eigen::Vector2d(o.qd1, o.qd2), st->qd, 1e-9));
        EXPECT_TRUE(near_rel_vec(Eigen::Vector2d(o.qdd1, o.qdd2), st->qdd, 1e-9));
        EXPECT_TRUE(
            near_rel_vec(Eigen::Vector2d(o.tau1, o.tau2), Eigen::Vector2d(tau[0], tau[1]), 1e-9))
            << "config " << config << " p " << p.transpose();
      }
    }
  }
}

TEST(PlacementArm2, EnergyAndPeaksEqualCoreAlongALine) {
  const core::PlanarChain chain = testing::thesis_arm();
  const Arm2 arm = make_arm2(chain);
  const double L = 0.4;
  const ProgramTable table = make_program_table(core::MotionProgram::kPoly345, 1.0, L, 301);
  const Line line = thesis_line(0.5, 2.2);
  for (const int config : {1, 2}) {
    const LineMetrics m = evaluate_line(arm, table, line, config);
    std::vector<double> t, p_abs, p_signed;
    double pk1 = 0, pk2 = 0;
    for (int k = 0; k < table.size(); ++k) {
      const Eigen::Vector2d p = line.start + table.s[k] * line.dir;
      const auto st = core::ik_2link_motion(arm.L1, arm.L2, p, table.sd[k] * line.dir,
                                            table.sdd[k] * line.dir, config);
      ASSERT_TRUE(st);
      core::JointVector q(2), qd(2), qdd(2);
      q << st->q[0], st->q[1];
      qd << st->qd[0], st->qd[1];
      qdd << st->qdd[0], st->qdd[1];
      const core::JointVector tau = core::inverse_dynamics(chain, q, qd, qdd);
      t.push_back(k * table.dt);
      p_abs.push_back(core::absolute_power(tau, qd));
      p_signed.push_back(core::signed_power(tau, qd));
      pk1 = std::max(pk1, std::abs(tau[0]));
      pk2 = std::max(pk2, std::abs(tau[1]));
    }
    EXPECT_TRUE(near_rel(m.energy, core::integrate_trapezoid(t, p_abs), 1e-10));
    // both are 0 up to their quadrature errors (Gregory's O(h^6), the trapezoid's O(h^4))
    EXPECT_NEAR(m.signed_work, core::integrate_trapezoid(t, p_signed), 1e-8);
    EXPECT_LT(std::abs(m.signed_work), 1e-10);
    EXPECT_TRUE(near_rel(m.peak_torque[0], pk1, 1e-10));
    EXPECT_TRUE(near_rel(m.peak_torque[1], pk2, 1e-10));
    const TimeSeries ts = sample_series(arm, table, line, config);
    EXPECT_TRUE(near_rel(ts.energy.back(), m.energy, 1e-12));
  }
}

TEST(PlacementArm2, ThesisArmParametersMatchTheLagrangeCoefficients) {
  // (6.23): I_{1,0} + (m2 + m) L1^2, I_{2,A} + m L2^2, m2 L1 rG2 + m L1 L2
  const Arm2 a = make_arm2(testing::thesis_arm());
  const double I10 = 4.0 * 0.4 * 0.4 / 12 + 4.0 * 0.2 * 0.2;
  const double I2A = 2.0 * 0.2 * 0.2 / 12 + 2.0 * 0.1 * 0.1;
  const double J2 = I2A + 1.0 * 0.2 * 0.2;
  EXPECT_NEAR(a.a11, I10 + 3.0 * 0.4 * 0.4 + J2, 1e-15);
  EXPECT_NEAR(a.a22, J2, 1e-15);
  EXPECT_NEAR(a.A, 2.0 * 0.4 * 0.1 + 1.0 * 0.4 * 0.2, 1e-15);
  EXPECT_EQ(a.B, 0.0);
}

TEST(PlacementArm2, RejectsGravityAndPassiveJoints) {
  EXPECT_THROW(make_arm2(testing::vertical_arm()), std::invalid_argument);
  EXPECT_THROW(make_arm2(testing::tray_arm()), std::invalid_argument);
}

}  // namespace
}  // namespace armstudy::studies::placement

namespace armstudy::studies::placement {
namespace {

// the structure-of-arrays evaluator returns the scalar reference's figures bit for bit
// (lines of every kind: interior, near the boundaries, outside, singular; table sizes that
// are and are not multiples of its block), and both equal the generic chain's IK and
// inverse dynamics to 1e-12 relative on a well-conditioned line
TEST(PlacementArm2, BlockedEvaluatorEqualsTheScalarReference) {
  const Arm2 arm = make_arm2(testing::thesis_arm());
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> xs(0.0, 0.7), ph(-core::kPi, core::kPi);
  for (const int n : {3, 11, 12, 255, 256, 257, 401, 801}) {
    const ProgramTable table = make_program_table(core::MotionProgram::kCycloidal, 1.0, 0.3, n);
    for (int k = 0; k < 200; ++k) {
      const Line line = thesis_line(xs(rng), ph(rng));
      for (const int config : {1, 2}) {
        const LineMetrics a = evaluate_line(arm, table, line, config);
        const LineMetrics b = evaluate_line_scalar(arm, table, line, config);
        const auto same = [](double x, double y) {
          return x == y || (std::isnan(x) && std::isnan(y));
        };
        ASSERT_TRUE(same(a.energy, b.energy)) << n << " " << a.energy << " " << b.energy;
        ASSERT_TRUE(same(a.signed_work, b.signed_work));
        ASSERT_TRUE(same(a.energy_coarse, b.energy_coarse));
        ASSERT_TRUE(same(a.min_abs_sin, b.min_abs_sin));
        for (int j = 0; j < 2; ++j) {
          ASSERT_TRUE(same(a.peak_torque[j], b.peak_torque[j]));
          ASSERT_TRUE(same(a.peak_power[j], b.peak_power[j]));
        }
      }
    }
  }
}

TEST(PlacementArm2, BlockedEvaluatorEqualsTheGenericChainTo1e12) {
  const core::PlanarChain chain = testing::thesis_arm();
  const Arm2 arm = make_arm2(chain);
  const ProgramTable table = make_program_table(core::MotionProgram::kCycloidal, 1.0, 0.3, 401);
  const Line line = thesis_line(0.5, 2.2);
  for (const int config : {1, 2}) {
    const LineMetrics m = evaluate_line(arm, table, line, config);
    double e = 0, pk1 = 0, pk2 = 0, prev = 0;
    for (int k = 0; k < table.size(); ++k) {
      const Eigen::Vector2d p = line.start + table.s[k] * line.dir;
      const auto st = core::ik_2link_motion(arm.L1, arm.L2, p, table.sd[k] * line.dir,
                                            table.sdd[k] * line.dir, config);
      ASSERT_TRUE(st);
      core::JointVector q(2), qd(2), qdd(2);
      q << st->q[0], st->q[1];
      qd << st->qd[0], st->qd[1];
      qdd << st->qdd[0], st->qdd[1];
      const core::JointVector tau = core::inverse_dynamics(chain, q, qd, qdd);
      const double pa = core::absolute_power(tau, qd);
      if (k > 0) e += 0.5 * table.dt * (pa + prev);
      prev = pa;
      pk1 = std::max(pk1, std::abs(tau[0]));
      pk2 = std::max(pk2, std::abs(tau[1]));
    }
    EXPECT_TRUE(testing::near_rel(m.energy, e, 1e-12)) << "config " << config;
    EXPECT_TRUE(testing::near_rel(m.peak_torque[0], pk1, 1e-12));
    EXPECT_TRUE(testing::near_rel(m.peak_torque[1], pk2, 1e-12));
  }
}

}  // namespace
}  // namespace armstudy::studies::placement
