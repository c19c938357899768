// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// MuJoCo's dynamics along the studies' own motions: the throwing study's simulated throw
// (passive tray and rolling ball) and a placement optimum's motion.

#include <gtest/gtest.h>

#include <cmath>

#include "core/dynamics.hpp"
#include "scene/mjcf_writer.hpp"
#include "scene/mujoco_check.hpp"
#include "studies/placement/solve.hpp"
#include "studies/throwing/solve.hpp"
#include "testing/arms.hpp"

namespace armstudy::scene {
namespace {

struct CheckedMotion {
  std::vector<core::JointVector> q, qd, qdd, tau;
};

CheckedMotion throw_motion(const studies::ThrowingSpec& spec) {
  const studies::ThrowSetup setup = studies::make_throw_setup(spec);
  const auto profile = studies::eq8_profile(spec.start, Eigen::Vector2d::Zero(), spec.release,
                                            spec.release_rate, spec.tf, spec.stages);
  const studies::ThrowMotion tm = studies::record_motion(setup, spec, profile);
  CheckedMotion m;
  for (size_t k = 0; k < tm.series.t.size(); ++k) {
    m.q.push_back(tm.series.q[k]);
    m.qd.push_back(tm.series.qd[k]);
    m.qdd.push_back(tm.series.qdd[k]);
    m.tau.push_back(studies::joint_torques(spec.arm.motor2, tm.series.tau_m[k]));
  }
  return m;
}

// What the MJCF's stand-in inertias (scene::stand_in_mass_matrix: dM) do to MuJoCo's
// passive accelerations, to first order: they become qdd_p - Mpp^-1 (dM qdd)_p. Returned
// relative to the largest passive |qdd| along the motion, as
// MujocoAgreement::acceleration_rel is.
double stand_in_acceleration_rel(const core::PlanarChain& chain, const CheckedMotion& m) {
  const int n = chain.num_links();
  const Eigen::MatrixXd dM = stand_in_mass_matrix(chain);
  std::vector<int> pas;
  for (int i = 0; i < n; ++i)
    if (!chain.links[i].active) pas.push_back(i);
  const int np = static_cast<int>(pas.size());
  double err = 0, scale = 0;
  for (size_t k = 0; k < m.q.size(); ++k) {
    const core::JointMatrix M = core::mass_matrix(chain, m.q[k]);
    const Eigen::VectorXd dtau = dM * Eigen::VectorXd(m.qdd[k]);
    Eigen::MatrixXd Mpp(np, np);
    Eigen::VectorXd rhs(np);
    for (int r = 0; r < np; ++r) {
      for (int c = 0; c < np; ++c) Mpp(r, c) = M(pas[r], pas[c]);
      rhs[r] = dtau[pas[r]];
      scale = std::max(scale, std::abs(m.qdd[k][pas[r]]));
    }
    err = std::max(err, Mpp.ldlt().solve(rhs).cwiseAbs().maxCoeff());
  }
  return err / scale;
}

TEST(MujocoCheck, ThrowingMotionAgreesWithMujocoIncludingTheRollingBall) {
  for (auto mount : {studies::Motor2Mount::kOnLink1, studies::Motor2Mount::kOnBase}) {
    studies::ThrowingSpec spec;
    spec.arm.motor2 = mount;
    spec.arm.rotor_inertia = 2e-7;  // rotors as spinners (kOnBase: rigid with link 2)
    const CheckedMotion m = throw_motion(spec);
    ASSERT_GT(m.q.size(), 50u);
    const core::PlanarChain chain = studies::make_tray_arm(spec.arm);
    const MujocoAgreement a = mujoco_agreement(chain, m.q, m.qd, m.qdd, m.tau);
    // the ball's link, a point mass, gets the stand-in inertia 2e-12 kg m^2 in MJCF (MuJoCo
    // rejects zero, and its XML writer writes less than 1e-12 as 0): against the ball's own
    // inertia about its hinge (m r4^2 plus its spin's, ~4e-7 kg m^2) that is ~5e-6, times
    // the sum of all joint accelerations over the passive ones. MuJoCo's passive
    // accelerations differ by exactly that (4.75e-6 here; 4.75e-4 with a 100 times larger
    // stand-in, 2.38e-8 with the former 1e-14) and by nothing else, and the check passes at
    // 1e-5. The torques: the stand-in times the summed accelerations, 2.9e-9 of the largest
    // torque (2.9e-7 with a 100 times larger stand-in)
    EXPECT_LT(a.torque_rel, 1e-8) << "worst sample " << a.worst_sample;
    const double expected = stand_in_acceleration_rel(chain, m);
    EXPECT_NEAR(a.acceleration_rel, expected, 0.01 * expected + 1e-10);
    EXPECT_LT(expected, 1e-5);
    for (const auto& c : mujoco_checks(a, true, 1e-5)) EXPECT_TRUE(c.passed) << c.name;
  }
}

TEST(MujocoCheck, WrongTorquesOrAccelerationsFailTheCheck) {
  const studies::ThrowingSpec spec;
  CheckedMotion m = throw_motion(spec);
  const core::PlanarChain chain = studies::make_tray_arm(spec.arm);
  CheckedMotion bad_tau = m;
  bad_tau.tau[40][1] *= 1.001;
  const MujocoAgreement a =
      mujoco_agreement(chain, bad_tau.q, bad_tau.qd, bad_tau.qdd, bad_tau.tau);
  EXPECT_FALSE(mujoco_checks(a, true)[0].passed);
  EXPECT_EQ(a.worst_sample, 40);
  CheckedMotion bad_qdd = m;
  bad_qdd.qdd[30][3] += 0.01 * std::abs(bad_qdd.qdd[30][3]) + 1.0;
  const MujocoAgreement b =
      mujoco_agreement(chain, bad_qdd.q, bad_qdd.qd, bad_qdd.qdd, bad_qdd.tau);
  EXPECT_FALSE(mujoco_checks(b, true)[1].passed);
}

TEST(MujocoCheck, PlacementOptimumAgreesWithMujoco) {
  studies::placement::Spec spec;
  spec.chain = testing::thesis_arm();
  spec.length = 0.4 * 4 * std::sqrt(0.4 * 0.2);
  spec.programs = {core::MotionProgram::kPoly345};
  spec.configurations = {1};
  spec.nx_s = 10;
  spec.phi_step = 6 * core::kPi / 180;
  spec.samples = 101;
  spec.map_nx = 10;
  spec.map_ny = 5;
  spec.refine = false;
  spec.threads = 1;
  const auto r = studies::placement::solve(spec);
  ASSERT_EQ(r.status, studies::Status::kSolved) << r.message;
  const auto& s = r.cases.at(0).series;
  ASSERT_GT(s.t.size(), 50u);
  CheckedMotion m;
  for (size_t k = 0; k < s.t.size(); ++k) {
    m.q.push_back(core::JointVector(s.q[k]));
    m.qd.push_back(core::JointVector(s.qd[k]));
    m.qdd.push_back(core::JointVector(s.qdd[k]));
    m.tau.push_back(core::JointVector(s.tau[k]));
  }
  const MujocoAgreement a = mujoco_agreement(spec.chain, m.q, m.qd, m.qdd, m.tau);
  EXPECT_LT(a.torque_rel, 1e-9);
  EXPECT_EQ(mujoco_checks(a, false).size(), 1u);
}

}  // namespace
}  // namespace armstudy::scene
