// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "core/dynamics.hpp"

#include <gtest/gtest.h>

#include "core/energy.hpp"
#include "core/kinematics.hpp"
#include "core/motion_program.hpp"
#include "testing/arms.hpp"

namespace armstudy::core {
namespace {

using testing::arm_factory;
using testing::near_rel;
using testing::near_rel_vec;
using testing::random_joints;

TEST(Dynamics, MassMatrixIsSymmetricPositiveDefinite) {
  std::mt19937 rng(3);
  for (const auto& arm : arm_factory()) {
    for (int trial = 0; trial < 50; ++trial) {
      const JointVector q = random_joints(rng, arm.chain.num_links(), 3.0);
      const JointMatrix M = mass_matrix(arm.chain, q);
      EXPECT_LT((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-15) << arm.name;
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es{Eigen::MatrixXd(M)};
      EXPECT_GT(es.eigenvalues().minCoeff(), 0.0) << arm.name;
    }
  }
}

TEST(Dynamics, InverseAndForwardDynamicsAreInverses) {
  std::mt19937 rng(5);
  for (const auto& arm : arm_factory()) {
    const int n = arm.chain.num_links();
    for (int trial = 0; trial < 50; ++trial) {
      const JointVector q = random_joints(rng, n, 3.0);
      const JointVector qd = random_joints(rng, n, 4.0);
      const JointVector qdd = random_joints(rng, n, 10.0);
      const JointVector tau = inverse_dynamics(arm.chain, q, qd, qdd);
      EXPECT_TRUE(near_rel_vec(forward_dynamics(arm.chain, q, qd, tau), qdd, 1e-9)) << arm.name;
    }
  }
}

// inverse and forward dynamics take each body's Jacobian once for M and h: the numbers of
// mass_matrix and bias_forces, each asked alone, bit for bit, on every arm, with its base
// turned too
TEST(Dynamics, OnePassDynamicsGiveMassMatrixAndBiasForcesBitForBit) {
  std::mt19937 rng(11);
  for (auto arm : arm_factory()) {
    const int n = arm.chain.num_links();
    for (double base_angle : {0.0, 0.7}) {
      arm.chain.base_angle = base_angle;
      for (int trial = 0; trial < 20; ++trial) {
        const JointVector q = random_joints(rng, n, 3.0);
        const JointVector qd = random_joints(rng, n, 4.0);
        const JointVector qdd = random_joints(rng, n, 10.0);
        const JointMatrix M = mass_matrix(arm.chain, q);
        const JointVector h = bias_forces(arm.chain, q, qd);
        const JointVector tau = inverse_dynamics(arm.chain, q, qd, qdd);
        const JointVector tau_two_pass = M * qdd + h;
        const JointVector qdd_two_pass = M.llt().solve(JointVector(tau - h));
        const JointVector qdd_one_pass = forward_dynamics(arm.chain, q, qd, tau);
        for (int j = 0; j < n; ++j) {
          EXPECT_EQ(tau[j], tau_two_pass[j]) << arm.name << " joint " << j;
          EXPECT_EQ(qdd_one_pass[j], qdd_two_pass[j]) << arm.name << " joint " << j;
        }
      }
    }
  }
}

TEST(Dynamics, PassiveForwardDynamicsGivesZeroPassiveTorque) {
  std::mt19937 rng(9);
  const auto chain = testing::tray_arm();
  for (int trial = 0; trial < 50; ++trial) {
    const JointVector q = random_joints(rng, 4, 3.0);
    const JointVector qd = random_joints(rng, 4, 4.0);
    const JointVector qdd_a = random_joints(rng, 4, 10.0);
    const MixedDynamics md = passive_forward_dynamics(chain, q, qd, qdd_a, JointVector::Zero(4));
    EXPECT_EQ(md.qdd[0], qdd_a[0]);
    EXPECT_EQ(md.qdd[1], qdd_a[1]);
    const JointVector tau = inverse_dynamics(chain, q, qd, md.qdd);
    EXPECT_NEAR(tau[2], 0.0, 1e-12);
    EXPECT_NEAR(tau[3], 0.0, 1e-12);
    EXPECT_TRUE(near_rel_vec(tau, md.tau, 1e-12));
  }
}

// The bias forces are C(q, qd) qd + g(q): check the Lagrangian identity
// h = d/dt(dK/dqd) - dK/dq + dU/dq at qdd = 0, by finite differences of K and U.
TEST(Dynamics, BiasForcesMatchLagrangeEquationsByFiniteDifferences) {
  std::mt19937 rng(13);
  for (const auto& arm : arm_factory()) {
    const int n = arm.chain.num_links();
    for (int trial = 0; trial < 10; ++trial) {
      const JointVector q = random_joints(rng, n, 3.0);
      const JointVector qd = random_joints(rng, n, 3.0);
      const double h = 1e-5;
      JointVector expected(n);
      // d/dt (M qd) at qdd = 0 is (dM/dq . qd) qd
      const JointMatrix Mdot =
          (mass_matrix(arm.chain, q + h * qd) - mass_matrix(arm.chain, q - h * qd)) / (2 * h);
      for (int i = 0; i < n; ++i) {
        JointVector qp = q, qm = q;
        qp[i] += h;
        qm[i] -= h;
        const double dK =
            (kinetic_energy(arm.chain, qp, qd) - kinetic_energy(arm.chain, qm, qd)) / (2 * h);
        const double dU =
            (potential_energy(arm.chain, qp) - potential_energy(arm.chain, qm)) / (2 * h);
        expected[i] = (Mdot * qd)[i] - dK + dU;
      }
      EXPECT_TRUE(near_rel_vec(bias_forces(arm.chain, q, qd), expected, 1e-7)) << arm.name;
    }
  }
}

// Signed actuator work up to every instant equals the change of kinetic plus potential
// energy, along random smooth motions with gravity.
TEST(Dynamics, WorkEnergyIdentityHoldsAlongRandomMotions) {
  std::mt19937 rng(17);
  for (const auto& arm : arm_factory()) {
    const int n = arm.chain.num_links();
    for (int trial = 0; trial < 3; ++trial) {
      const JointVector q0 = random_joints(rng, n, 2.0);
      const JointVector a = random_joints(rng, n, 1.5);
      const JointVector w = random_joints(rng, n, 6.0);
      // q(t) = q0 + a sin(w t): smooth; integrate tau . qd with Simpson on a fine grid
      const int samples = 4001;
      const double T = 1.0, dt = T / (samples - 1);
      std::vector<double> power(samples);
      double worst = 0.0;
      const auto state = [&](double t, JointVector* q, JointVector* qd, JointVector* qdd) {
        *q = q0 + (a.array() * (w.array() * t).sin()).matrix();
        *qd = (a.array() * w.array() * (w.array() * t).cos()).matrix();
        *qdd = (-a.array() * w.array().square() * (w.array() * t).sin()).matrix();
      };
      JointVector q, qd, qdd;
      state(0, &q, &qd, &qdd);
      const double e0 = kinetic_energy(arm.chain, q, qd) + potential_energy(arm.chain, q);
      for (int k = 0; k < samples; ++k) {
        state(k * dt, &q, &qd, &qdd);
        power[k] = signed_power(inverse_dynamics(arm.chain, q, qd, qdd), qd);
        if (k > 0 && k % 2 == 0) {
          const double work = integrate_simpson(std::span<const double>(power.data(), k + 1), dt);
          const double de = kinetic_energy(arm.chain, q, qd) + potential_energy(arm.chain, q) - e0;
          const double scale = std::max(1e-3, std::abs(de) + std::abs(work));
          worst = std::max(worst, std::abs(work - de) / scale);
        }
      }
      EXPECT_LT(worst, 1e-8) << arm.name;
    }
  }
}

TEST(Dynamics, StaticTorqueOfHorizontalArmEqualsWeightMoment) {
  const auto chain = testing::vertical_arm();
  JointVector q(2), z = JointVector::Zero(2);
  // horizontal arm: joint 1 holds sum m g x_com
  q << 0.0, 0.0;
  const JointVector tau = inverse_dynamics(chain, q, z, z);
  const double expected = 9.81 * (3.0 * 0.22 + 1.5 * (0.5 + 0.15) + 0.5 * 0.85);
  EXPECT_TRUE(near_rel(tau[0], expected, 1e-12));
}

TEST(MotionProgram, EveryProgramIsRestToRestAndDerivativesAreConsistent) {
  for (const auto& name : program_names()) {
    const MotionProgram p = *parse_program(name);
    const double T = 1.3, L = 0.7;
    const ProgramSample s0 = evaluate_program(p, 0, T, L), s1 = evaluate_program(p, T, T, L);
    EXPECT_NEAR(s0.s, 0, 1e-15) << name;
    EXPECT_NEAR(s1.s, L, 1e-12) << name;
    EXPECT_NEAR(s0.sd, 0, 1e-12) << name;
    EXPECT_NEAR(s1.sd, 0, 1e-12) << name;
    if (p != MotionProgram::kTrapezoidal) {
      EXPECT_NEAR(s0.sdd, 0, 1e-12) << name;
      EXPECT_NEAR(s1.sdd, 0, 1e-9) << name;
    }
    const double h = 1e-6;
    for (double t : {0.11, 0.5, 0.93}) {
      const ProgramSample a = evaluate_program(p, t - h, T, L),
                          b = evaluate_program(p, t + h, T, L);
      const ProgramSample m = evaluate_program(p, t, T, L);
      EXPECT_NEAR((b.s - a.s) / (2 * h), m.sd, 1e-6) << name;
      EXPECT_NEAR((b.sd - a.sd) / (2 * h), m.sdd, 1e-5) << name;
      EXPECT_NEAR((b.sdd - a.sdd) / (2 * h), m.sddd, 1e-4) << name;
    }
  }
  EXPECT_FALSE(parse_program("cubic").has_value());
}

}  // namespace
}  // namespace armstudy::core
