// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// A 3-link time-optimal solution against MuJoCo, and the model.xml a case folder holds:
// MuJoCo's mj_inverse gives the study's torques along the exact motion; model.xml loads
// with mj_loadXML, its masses, centres of mass and inertias are the case's, and its
// keyframes put MuJoCo's arm in the poses of the strip's frames (the tray arm too, whose
// rolling ball has a hinge of its own in MuJoCo).
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include <mujoco/mujoco.h>

#include "core/kinematics.hpp"
#include "scene/chain_map.hpp"
#include "scene/mjcf_writer.hpp"
#include "scene/model_export.hpp"
#include "scene/mujoco_check.hpp"
#include "scene/mujoco_model.hpp"
#include "scene/pendulum_frames.hpp"
#include "scene/time_optimal_frames.hpp"
#include "studies/pendulum/solve.hpp"
#include "studies/time_optimal/solve.hpp"
#include "studies/tray_arm.hpp"
#include "testing/three_link.hpp"

namespace armstudy::scene {
namespace {
namespace fs = std::filesystem;
namespace to = studies::time_optimal;

fs::path temp_dir(const std::string& name) {
  const fs::path d =
      fs::temp_directory_path() / ("armstudy_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// every link body of model.xml carries the case's combined inertial (link + point masses)
void expect_case_inertials(const core::PlanarChain& chain, const mjModel* m) {
  for (int i = 0; i < chain.num_links(); ++i) {
    const int b = mj_name2id(m, mjOBJ_BODY, ("link" + std::to_string(i + 1)).c_str());
    ASSERT_GE(b, 0) << "link" << i + 1;
    const LinkInertial in = combined_inertial(chain, i);
    EXPECT_NEAR(m->body_mass[b], std::max(in.mass, kMinMjcfMass), 1e-15 * std::max(1.0, in.mass))
        << i;
    EXPECT_NEAR(m->body_inertia[3 * b + 2], std::max(in.izz, kMinMjcfInertia),
                1e-15 * std::max(1.0, in.izz))
        << i;
    EXPECT_NEAR(m->body_ipos[3 * b + 0], in.com_x, 1e-15) << i;
    EXPECT_NEAR(m->body_ipos[3 * b + 1], in.com_y, 1e-15) << i;
  }
  EXPECT_NEAR(m->opt.gravity[1], -chain.gravity, 1e-15);
}

TEST(ChainExportsMujoco, ThreeLinkExactTorquesAreMujocosInverseDynamics) {
  const to::Spec spec = testing::three_link_spec();
  const to::Result r = to::solve(spec);
  ASSERT_EQ(r.status, studies::Status::kSolved) << r.message;
  const to::MotionSamples& s = r.solvers.front().samples;
  ASSERT_GT(s.t.size(), 100u);
  ASSERT_EQ(s.tau.rows(), 3);
  std::vector<core::JointVector> q, qd, qdd, tau;
  for (int k = 0; k < s.q.cols(); ++k) {
    q.emplace_back(s.q.col(k));
    qd.emplace_back(s.qd.col(k));
    qdd.emplace_back(s.qdd.col(k));
    tau.emplace_back(s.tau.col(k));
  }
  const MujocoAgreement a = mujoco_agreement(spec.chain, q, qd, qdd, tau);
  EXPECT_EQ(a.samples, static_cast<int>(s.t.size()));
  EXPECT_LE(a.torque_rel, 1e-9) << "worst at sample " << a.worst_sample;
}

TEST(ChainExportsMujoco, SevenLinkJointSpaceLineSolvesAndMujocoAgrees) {
  // the longest chain armstudy builds: a vertical 7-link arm with point masses, along a
  // joint-space line; its generated MJCF has 7 hinges and MuJoCo's inverse dynamics agree
  core::PlanarChain c;
  for (int i = 0; i < core::kMaxLinks; ++i)
    c.links.push_back({0.15, 0.4 - 0.04 * i, 0.07, 0.01, 1e-3, true});
  c.point_masses = {{6, 0.15, 0.0, 0.2}};
  c.gravity = 9.81;
  to::Spec spec;
  spec.chain = core::make_chain(c);
  spec.space = to::PathSpace::kJoint;
  spec.joint_path.kind = to::PathKind::kLine;
  core::JointVector a(7), b(7);
  a << -2.0, 0.3, 0.2, 0.1, 0.0, -0.1, -0.2;
  b << -1.0, -0.2, -0.1, 0.2, 0.3, 0.1, 0.0;
  spec.joint_path.points = {a, b};
  spec.velocity_limit = core::JointVector::Constant(7, 3.0);
  spec.torque_limit = core::JointVector::Constant(7, 20.0);
  spec.exact.grid_points = 200;
  spec.dp.segments = 10;
  spec.dp.levels = 50;
  spec.dp.convergence_segments = {};
  spec.complex.enabled = false;
  const to::Result r = to::solve(spec);
  ASSERT_EQ(r.status, studies::Status::kSolved) << r.message;
  for (const studies::Check& ch : to::checks(r))
    EXPECT_TRUE(ch.passed) << ch.name << ": " << ch.value;
  const to::MotionSamples& s = r.solvers.front().samples;
  ASSERT_EQ(s.q.rows(), 7);
  std::vector<core::JointVector> q, qd, qdd, tau;
  for (int k = 0; k < s.q.cols(); ++k) {
    q.emplace_back(s.q.col(k));
    qd.emplace_back(s.qd.col(k));
    qdd.emplace_back(s.qdd.col(k));
    tau.emplace_back(s.tau.col(k));
  }
  EXPECT_LE(mujoco_agreement(spec.chain, q, qd, qdd, tau).torque_rel, 1e-9);
  const MujocoModel mm(write_mjcf(spec.chain), "7 links");
  EXPECT_EQ(mm.model()->njnt, 7);
  EXPECT_EQ(mm.model()->nu, 7);
  expect_case_inertials(spec.chain, mm.model());
}

TEST(ChainExportsMujoco, ModelXmlHasTheCasesInertialsAndKeyframesAtTheStripsPoses) {
  const to::Spec spec = testing::three_link_spec();
  const to::Result r = to::solve(spec);
  ASSERT_EQ(r.status, studies::Status::kSolved) << r.message;
  cases::RenderOptions options;  // 6 frames
  const ArmScene sc = time_optimal_scene(spec, r, options);
  const std::vector<PoseSample> keys = strip_keyframes(time_optimal_motion(r), options.frames);
  ASSERT_EQ(keys.size(), 6u);
  const fs::path dir = temp_dir("model_xml");
  EXPECT_EQ(write_model_xml(dir, sc.chain, sc.mjcf, keys, "the exact solution", "test"),
            "model.xml");

  MujocoModel mm = MujocoModel::from_file((dir / "model.xml").string());  // mj_loadXML
  const mjModel* m = mm.model();
  expect_case_inertials(spec.chain, m);
  ASSERT_EQ(m->nkey, 6);
  ASSERT_EQ(m->nq, 3);
  const int tip = mj_name2id(m, mjOBJ_SITE, "tip");
  ASSERT_GE(tip, 0);
  for (int k = 0; k < m->nkey; ++k) {
    // the strip's frame k: at t_k = T k / 5, the motion interpolated linearly between its
    // equal time steps (what write_strip draws)
    const double t = r.motion_t.back() * k / 5;
    EXPECT_NEAR(m->key_time[k], t, 1e-12 * r.motion_t.back()) << k;
    const size_t n = r.motion_t.size();
    size_t i = 0;
    while (i + 2 < n && r.motion_t[i + 1] < t) ++i;
    const double w =
        std::clamp((t - r.motion_t[i]) / (r.motion_t[i + 1] - r.motion_t[i]), 0.0, 1.0);
    const core::JointVector q = (1 - w) * r.motion_q.col(i) + w * r.motion_q.col(i + 1);
    // MuJoCo's arm at key k: the same joint angles and the same tip
    mj_resetDataKeyframe(m, mm.data(), k);
    mj_forward(m, mm.data());
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(mm.data()->qpos[j], q[j], 1e-12) << "key " << k << " joint " << j;
    const Eigen::Vector2d p = core::end_effector(spec.chain, q);
    EXPECT_NEAR(mm.data()->site_xpos[3 * tip + 0], p.x(), 1e-12) << k;
    EXPECT_NEAR(mm.data()->site_xpos[3 * tip + 1], p.y(), 1e-12) << k;
  }
  fs::remove_all(dir);
}

TEST(ChainExportsMujoco, TrayArmModelXmlKeyframesMoveTheBallsOwnHingeWithItsJoint) {
  // the pendulum: the tray arm's rolling ball spins on an extra MuJoCo hinge, so a keyframe's
  // qpos has more entries than the chain has joints; MuJoCo's state still reads back as the
  // snapshot's chain coordinates
  studies::PendulumSpec spec = studies::default_pendulum_spec();
  spec.duration = 0.5;
  const studies::PendulumResult r = studies::solve_pendulum(spec);
  ASSERT_EQ(r.status, studies::Status::kSolved) << r.message;
  const ArmScene sc = pendulum_scene(spec, r, cases::RenderOptions{});
  const std::vector<PoseSample> keys = pendulum_snapshots(r);
  ASSERT_GE(keys.size(), 3u);
  const fs::path dir = temp_dir("tray_model_xml");
  write_model_xml(dir, sc.chain, sc.mjcf, keys, "the snapshots", "test");
  MujocoModel mm = MujocoModel::from_file((dir / "model.xml").string());
  const mjModel* m = mm.model();
  expect_case_inertials(sc.chain, m);
  ASSERT_EQ(m->nkey, static_cast<int>(keys.size()));
  EXPECT_GT(m->nq, sc.chain.num_links());
  const ChainMap map(sc.chain, m);
  for (int k = 0; k < m->nkey; ++k) {
    mj_resetDataKeyframe(m, mm.data(), k);
    EXPECT_LT((map.chain_q(mm.data()) - keys[k].q).norm(), 1e-12) << k;
    EXPECT_LT((map.chain_qd(mm.data()) - keys[k].qd).norm(), 1e-12) << k;
    EXPECT_EQ(m->key_time[k], keys[k].t);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace armstudy::scene
