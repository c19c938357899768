// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// MuJoCo's own dynamics (mj_inverse, mj_forward) on the generated MJCF equal core's
// Kane-method dynamics along smooth motions, for every arm of the factory, a 4-link chain
// with gravity, lateral centres of mass and a rotor, and the tray arm with its rolling ball.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/dynamics.hpp"
#include "scene/chain_map.hpp"
#include "scene/mjcf_writer.hpp"
#include "scene/mujoco_model.hpp"
#include "scene/scene_error.hpp"
#include "testing/arms.hpp"

namespace armstudy::scene {
namespace {

using testing::near_rel_vec;

// relative to the larger operand's size (not to 1: the tray arm's torques are mN m)
template <typename A, typename B>
::testing::AssertionResult near_scaled(const A& a, const B& b, double tol) {
  const double scale = std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff());
  const double d = (a - b).cwiseAbs().maxCoeff();
  if (d <= tol * scale) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "[" << a.transpose() << "] vs [" << b.transpose()
                                       << "]: max |delta| " << d << " > " << tol << " x " << scale;
}

// fails on any MuJoCo warning (MujocoTest fixture)
class MujocoTest : public ::testing::Test {
 protected:
  void SetUp() override { take_mujoco_warnings(); }
  void TearDown() override { EXPECT_EQ(take_mujoco_warnings(), ""); }
};

// a 4-link chain with gravity, lateral centres of mass, a payload and a rotor on joint 2
core::PlanarChain four_link_gravity() {
  core::PlanarChain c;
  c.links = {{0.6, 5.0, 0.3, 0.02, 0.16, true},
             {0.5, 3.0, 0.22, -0.03, 0.07, true},
             {0.3, 1.2, 0.12, 0.01, 0.011, true},
             {0.2, 0.6, 0.09, 0.0, 0.002, true}};
  c.point_masses = {{3, 0.2, 0.0, 0.8}, {1, 0.25, 0.04, 0.3}};
  core::SpinningInertia rotor;
  rotor.inertia = 3e-5;
  rotor.coeffs = core::JointVector::Zero(4);
  rotor.coeffs[1] = 50.0;  // a gear ratio
  c.spinners = {rotor};
  c.gravity = 9.81;
  c.base = Eigen::Vector2d(0.1, -0.2);
  c.base_angle = 0.3;
  return core::make_chain(c);
}

std::vector<testing::NamedArm> arms() {
  auto a = testing::arm_factory();
  a.push_back({"four_link_gravity_rotor", four_link_gravity()});
  return a;
}

// a smooth motion q_i(t) = a_i sin(w_i t + p_i) with analytic derivatives
struct Motion {
  core::JointVector a, w, p;
  void at(double t, core::JointVector* q, core::JointVector* qd, core::JointVector* qdd) const {
    const int n = static_cast<int>(a.size());
    q->resize(n);
    qd->resize(n);
    qdd->resize(n);
    for (int i = 0; i < n; ++i) {
      (*q)[i] = a[i] * std::sin(w[i] * t + p[i]);
      (*qd)[i] = a[i] * w[i] * std::cos(w[i] * t + p[i]);
      (*qdd)[i] = -a[i] * w[i] * w[i] * std::sin(w[i] * t + p[i]);
    }
  }
};

Motion random_motion(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> amp(0.3, 2.0), freq(1.0, 8.0), phase(0.0, 6.28);
  Motion m;
  m.a.resize(n);
  m.w.resize(n);
  m.p.resize(n);
  for (int i = 0; i < n; ++i) {
    m.a[i] = amp(rng);
    m.w[i] = freq(rng);
    m.p[i] = phase(rng);
  }
  return m;
}

TEST_F(MujocoTest, MjInverseEqualsCoreInverseDynamicsAlongMotions) {
  std::mt19937 rng(20261123);
  for (const auto& arm : arms()) {
    SCOPED_TRACE(arm.name);
    MujocoModel mm(write_mjcf(arm.chain), arm.name);
    const ChainMap map(arm.chain, mm.model());
    // the rolling constraint is satisfied by construction: its force must not enter
    mm.model()->opt.disableflags |= mjDSBL_EQUALITY;
    const int n = arm.chain.num_links();
    for (int trial = 0; trial < 3; ++trial) {
      const Motion motion = random_motion(rng, n);
      for (int k = 0; k <= 40; ++k) {
        const double t = 0.025 * k;
        core::JointVector q, qd, qdd;
        motion.at(t, &q, &qd, &qdd);
        mj_resetData(mm.model(), mm.data());
        map.set_state(mm.model(), mm.data(), q, qd, &qdd);
        mj_inverse(mm.model(), mm.data());
        const core::JointVector tau_mj = map.project(mm.data()->qfrc_inverse);
        // the MJCF's stand-in inertias (the tray arm's ball link, 2e-12 kg m^2) add their
        // share, 3.8e-9 of the largest torque on the tray arm
        const core::JointVector tau =
            core::inverse_dynamics(arm.chain, q, qd, qdd) + stand_in_mass_matrix(arm.chain) * qdd;
        ASSERT_TRUE(near_scaled(tau_mj, tau, 1e-9)) << "t = " << t;
      }
    }
  }
}

TEST_F(MujocoTest, MassMatrixProjectsExactlyOntoTheChain) {
  std::mt19937 rng(7);
  for (const auto& arm : arms()) {
    SCOPED_TRACE(arm.name);
    MujocoModel mm(write_mjcf(arm.chain), arm.name);
    const ChainMap map(arm.chain, mm.model());
    const int n = arm.chain.num_links();
    const int nv = mm.model()->nv;
    for (int trial = 0; trial < 10; ++trial) {
      const core::JointVector q = testing::random_joints(rng, n, 3.0);
      map.set_state(mm.model(), mm.data(), q, core::JointVector::Zero(n));
      mj_forward(mm.model(), mm.data());
      Eigen::Matrix<mjtNum, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> M(nv, nv);
      mj_fullM(mm.model(), M.data(), mm.data()->qM);
      const Eigen::MatrixXd Mc = map.jacobian().transpose() * M * map.jacobian();
      // plus the MJCF's stand-in inertias (2e-12 kg m^2 on the tray arm's ball link)
      const Eigen::MatrixXd Mcore =
          core::mass_matrix(arm.chain, q) + stand_in_mass_matrix(arm.chain);
      ASSERT_TRUE(near_scaled(Eigen::Map<const Eigen::VectorXd>(Mc.data(), n * n),
                              Eigen::Map<const Eigen::VectorXd>(Mcore.data(), n * n), 1e-10));
    }
  }
}

// forward dynamics, including passive joints (zero torque) and the MuJoCo motor path
TEST_F(MujocoTest, MjForwardAccelerationsEqualCoreForwardDynamics) {
  std::mt19937 rng(99);
  for (const auto& arm : arms()) {
    if (!spinner_bodies(arm.chain).empty()) continue;  // see the rolling-ball test below
    SCOPED_TRACE(arm.name);
    MujocoModel mm(write_mjcf(arm.chain), arm.name);
    const ChainMap map(arm.chain, mm.model());
    const int n = arm.chain.num_links();
    for (int trial = 0; trial < 20; ++trial) {
      const core::JointVector q = testing::random_joints(rng, n, 3.0);
      const core::JointVector qd = testing::random_joints(rng, n, 4.0);
      core::JointVector tau = testing::random_joints(rng, n, 5.0);
      mj_resetData(mm.model(), mm.data());
      map.set_state(mm.model(), mm.data(), q, qd);
      int u = 0;
      for (int i = 0; i < n; ++i) {
        if (arm.chain.links[i].active)
          mm.data()->ctrl[u++] = tau[i];
        else
          tau[i] = 0.0;
      }
      mj_forward(mm.model(), mm.data());
      core::JointVector qdd_mj(n);
      for (int i = 0; i < n; ++i) qdd_mj[i] = mm.data()->qacc[map.dof(i)];
      ASSERT_TRUE(near_scaled(qdd_mj, core::forward_dynamics(arm.chain, q, qd, tau), 1e-9));
    }
  }
}

// the rolling ball: with its spin enforced by a stiff equality, MuJoCo's accelerations of
// the passive tray and ball follow core's reduced model (soft-constraint regularisation
// bounds the agreement)
TEST_F(MujocoTest, RollingBallAccelerationsFollowCorePassiveDynamics) {
  const core::PlanarChain chain = testing::tray_arm();
  MujocoModel mm(write_mjcf(chain), "tray_arm");
  const ChainMap map(chain, mm.model());
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const core::JointVector q = testing::random_joints(rng, 4, 2.0);
    const core::JointVector qd = testing::random_joints(rng, 4, 3.0);
    mj_resetData(mm.model(), mm.data());
    map.set_state(mm.model(), mm.data(), q, qd);
    mm.data()->ctrl[0] = 0.01;
    mm.data()->ctrl[1] = -0.02;
    core::JointVector tau = core::JointVector::Zero(4);
    tau[0] = 0.01;
    tau[1] = -0.02;
    mj_forward(mm.model(), mm.data());
    core::JointVector qdd_mj(4);
    for (int i = 0; i < 4; ++i) qdd_mj[i] = mm.data()->qacc[map.dof(i)];
    const core::JointVector qdd = core::forward_dynamics(chain, q, qd, tau);
    // soft-constraint regularisation: MuJoCo 2.2 caps the impedance at 0.9999
    EXPECT_TRUE(near_scaled(qdd_mj, qdd, 2e-3)) << "trial " << trial;
  }
}

TEST(MujocoModel, MissingFileGivesMujocosMessageWithTheFile) {
  try {
    MujocoModel::from_file("/nonexistent/arm.xml");
    FAIL() << "no exception";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/arm.xml"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace armstudy::scene
