// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// An arm read from a URDF or MJCF (arm: {model: FILE}) against MuJoCo: mj_inverse on the
// user's own model, loaded by MuJoCo from the file, and on armstudy's model.xml of it, at
// the same joint angles (the model's own), equals armstudy's dynamics to 1e-12; model.xml
// carries the limits the study used and says the arm's plane, and passes MuJoCo's
// mujoco-testxml (load, save, reload).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>

#include "cases/time_optimal_case.hpp"
#include "core/dynamics.hpp"
#include "scene/arm_scene.hpp"
#include "scene/chain_map.hpp"
#include "scene/model_export.hpp"
#include "scene/mujoco_model.hpp"
#include "scene/scene_error.hpp"
#include "testing/case_keys.hpp"
#include "testing/files.hpp"

namespace armstudy::scene {
namespace {
namespace fs = std::filesystem;
namespace to = studies::time_optimal;

const fs::path kRepo = ARMSTUDY_SOURCE_DIR;

to::Spec load_model_case(const fs::path& path) {
  cases::Diagnostics d(path.string());
  std::string text;
  const auto node = cases::parse_file(path.string(), d, &text);
  EXPECT_TRUE(node) << path;
  cases::Map root(*node, d, "");
  testing::mark_cli_keys(root);
  to::Spec spec = cases::load_time_optimal(root);
  root.finish();
  for (const auto& e : d.errors()) ADD_FAILURE() << e.format();
  return spec;
}

// the model's qpos are the chain's q: the arm's joints in the file's own order
core::JointVector torques_of_model(mjModel* m, mjData* d, const core::JointVector& q,
                                   const core::JointVector& qd, const core::JointVector& qdd) {
  mj_resetData(m, d);
  for (int i = 0; i < q.size(); ++i) {
    d->qpos[i] = q[i];
    d->qvel[i] = qd[i];
    d->qacc[i] = qdd[i];
  }
  mj_inverse(m, d);
  core::JointVector tau(q.size());
  for (int i = 0; i < q.size(); ++i) tau[i] = d->qfrc_inverse[i];
  return tau;
}

double rel(const core::JointVector& a, const core::JointVector& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(a.cwiseAbs().maxCoeff(), 1e-300);
}

TEST(ArmModelMujoco, MjInverseOnTheUsersModelAndOnModelXmlEqualsTheChainsDynamics) {
  struct Arm {
    fs::path case_file, model;
    const char* name;
  };
  // a horizontal SCARA (axes +z, gravity -z: none in the plane) and a vertical arm (axes
  // -y: gravity -z in the plane), from a URDF and an MJCF
  const fs::path vertical_case = testing::temp_path("arm_model_vertical.yaml");
  {
    std::string text = testing::slurp(kRepo / "reports/cases/time-optimal-3link.yaml");
    const size_t a = text.find("arm:\n"), t = text.find("time_optimal:\n");
    text.replace(
        a, t - a,
        "arm: {model: " + (kRepo / "tests/cases/models/arm3_vertical.xml").string() + "}\n");
    testing::write_file(vertical_case, text);
  }
  for (const Arm& arm : {Arm{kRepo / "reports/cases/time-optimal-scara-urdf.yaml",
                             kRepo / "reports/cases/scara3.urdf", "scara3_in_plane"},
                         Arm{vertical_case, kRepo / "tests/cases/models/arm3_vertical.xml",
                             "arm3_vertical_in_plane"}}) {
    SCOPED_TRACE(arm.model.string());
    const to::Spec spec = load_model_case(arm.case_file);
    const core::PlanarChain& chain = spec.chain;
    const int n = chain.num_links();
    MujocoModel user = MujocoModel::from_file(arm.model.string());
    ASSERT_EQ(user.model()->nv, n);
    TableDecor decor;
    decor.torque_limit.assign(spec.torque_limit.data(), spec.torque_limit.data() + n);
    decor.joint_range = spec.joint_path.range;
    decor.origin = spec.arm_origin;
    const ArmScene sc = horizontal_arm_scene(chain, decor);
    MujocoModel ours(sc.mjcf, "model.xml");
    const ChainMap map(chain, ours.model());
    // random poses lie outside the joints' ranges: the limits' forces must not enter
    user.model()->opt.disableflags |= mjDSBL_CONSTRAINT;
    ours.model()->opt.disableflags |= mjDSBL_CONSTRAINT;
    std::mt19937 rng(51);
    std::uniform_real_distribution<double> u(-2.5, 2.5);
    double worst_user = 0, worst_ours = 0;
    for (int k = 0; k < 50; ++k) {
      core::JointVector q(n), qd(n), qdd(n);
      for (int i = 0; i < n; ++i) q[i] = u(rng), qd[i] = u(rng), qdd[i] = 4 * u(rng);
      const core::JointVector tau = core::inverse_dynamics(chain, q, qd, qdd);
      worst_user =
          std::max(worst_user, rel(tau, torques_of_model(user.model(), user.data(), q, qd, qdd)));
      mj_resetData(ours.model(), ours.data());
      map.set_state(ours.model(), ours.data(), q, qd, &qdd);
      mj_inverse(ours.model(), ours.data());
      worst_ours = std::max(worst_ours, rel(tau, map.project(ours.data()->qfrc_inverse)));
    }
    EXPECT_LE(worst_user, 1e-12);
    EXPECT_LE(worst_ours, 1e-12);
    // model.xml: named after the arm, its plane, the limits used
    EXPECT_NE(sc.mjcf.find("<mujoco model=\"" + std::string(arm.name) + "\">"), std::string::npos);
    EXPECT_EQ(sc.mjcf.find("horizontal_arm"), std::string::npos);
    EXPECT_NE(sc.mjcf.find("the plane normal to the joints' axis"), std::string::npos) << sc.mjcf;
    EXPECT_NE(sc.mjcf.find("forcelimited=\"true\" forcerange=\"-" +
                           std::to_string(int(spec.torque_limit[0])) + " "),
              std::string::npos)
        << sc.mjcf;
    EXPECT_NE(sc.mjcf.find("limited=\"true\" range=\""), std::string::npos);
    for (int i = 0; i < n; ++i) {
      EXPECT_TRUE(ours.model()->jnt_limited[i]);
      EXPECT_EQ(ours.model()->jnt_range[2 * i], spec.joint_path.range[i].x());
      EXPECT_EQ(ours.model()->actuator_forcerange[2 * i + 1], spec.torque_limit[i]);
    }
    if (chain.gravity != 0) {
      EXPECT_EQ(sc.mjcf.find("seen from above"), std::string::npos);
      EXPECT_NE(sc.mjcf.find("vertical: gravity 9.81"), std::string::npos);
    }
    // MuJoCo's own round trip of model.xml (load, save with its writer, reload)
    if (std::system("command -v mujoco-testxml >/dev/null 2>&1") == 0) {
      const fs::path dir = testing::temp_path("arm_model_" + std::string(arm.name));
      fs::create_directories(dir);
      write_model_xml(dir, chain, sc.mjcf, {}, "no motion", "test");
      const std::string cmd = "cd " + dir.string() + " && mujoco-testxml model.xml >log.txt 2>&1";
      EXPECT_EQ(std::system(cmd.c_str()), 0) << testing::slurp(dir / "log.txt");
      fs::remove_all(dir);
    }
  }
  fs::remove(vertical_case);
}

}  // namespace
}  // namespace armstudy::scene
