// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// `arm: {model: FILE}`: an arm read from a URDF or an MJCF through MuJoCo's parser is the
// same arm as the one written out in YAML (dynamics, and the study's answer to 1e-9), its
// limits come from the model unless the case sets them, and a model that is no planar
// chain is refused naming the joint or body.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#include "cases/arm_loader.hpp"
#include "cases/placement_case.hpp"
#include "cases/time_optimal_case.hpp"
#include "core/dynamics.hpp"
#include "studies/placement/solve.hpp"
#include "studies/time_optimal/solve.hpp"

namespace armstudy::cases {
namespace {
namespace to = studies::time_optimal;
namespace pl = studies::placement;

// the case text as a file in tests/cases (models/ beside it), so relative paths resolve
template <class Spec>
Spec load_case_text(const std::string& yaml, Spec (*loader)(Map&), std::string* errors) {
  Diagnostics d(std::string(ARMSTUDY_SOURCE_DIR) + "/tests/cases/arm_model_case.yaml");
  const YAML::Node n = YAML::Load(yaml);
  Map root(n, d, "");
  root.get("study");
  root.get("name");
  Spec s = loader(root);
  root.finish();
  for (const auto& e : d.errors()) *errors += e.format() + "\n";
  return s;
}

// the bundled vertical 3-link case's path (reports/cases/time-optimal-3link.yaml) on small
// grids: the exact solver alone
const char* kThreeLinkPath = R"(
time_optimal:
  joint_path:
    kind: spline
    points_rad: [[-2.30, 0.50, 0.40], [-1.90, 0.20, 0.30], [-1.20, -0.20, -0.10], [-0.80, -0.50, -0.40]]
  dp: {segments: 6, levels: 20, convergence_segments: []}
  complex: {enabled: false}
  exact: {grid_points: 200, tolerance_rel: 0}
)";

const char* kThreeLinkYaml = R"(
arm:
  links:
    - {length: 0.40, mass: 3.0, inertia: rod}
    - {length: 0.35, mass: 2.0, inertia: rod}
    - {length: 0.25, mass: 1.0, inertia: rod}
  payload: 0.5
gravity: 9.81
)";

// the case's own ranges and limits (the same as the models')
const char* kThreeLinkLimits = R"(
    range_rad: [[-3.0, 0.0], [-1.5, 1.5], [-1.5, 1.5]]
  velocity_limit_rad_s: [2.5, 3.0, 4.0]
  torque_limit_Nm: [30.0, 12.0, 3.0]
)";

to::Spec three_link(const std::string& arm, bool limits) {
  std::string yaml = arm + kThreeLinkPath;
  // after points_rad (inside joint_path): the range, then the limits of time_optimal
  if (limits)
    yaml.insert(yaml.find("\n  dp:"),
                std::string(kThreeLinkLimits).substr(0, std::string(kThreeLinkLimits).size() - 1));
  std::string errors;
  to::Spec s = load_case_text<to::Spec>(yaml, &load_time_optimal, &errors);
  EXPECT_TRUE(errors.empty()) << errors << yaml;
  return s;
}

// mass matrix, bias and gravity torques of two chains at random states, relative
void expect_same_dynamics(const core::PlanarChain& a, const core::PlanarChain& b, double tol) {
  ASSERT_EQ(a.num_links(), b.num_links());
  EXPECT_NEAR(a.gravity, b.gravity, tol * 10);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-3, 3);
  const int n = a.num_links();
  for (int k = 0; k < 20; ++k) {
    core::JointVector q(n), qd(n), qdd(n);
    for (int i = 0; i < n; ++i) q[i] = u(rng), qd[i] = u(rng), qdd[i] = u(rng);
    const core::JointVector ta = core::inverse_dynamics(a, q, qd, qdd);
    const core::JointVector tb = core::inverse_dynamics(b, q, qd, qdd);
    EXPECT_LE((ta - tb).norm(), tol * ta.norm()) << "q = " << q.transpose();
  }
}

std::string model(const std::string& file) { return "arm: {model: models/" + file + "}\n"; }

TEST(ArmModel, TheVerticalThreeLinkArmFromUrdfAndMjcfIsTheYamlArm) {
  const to::Spec yaml = three_link(kThreeLinkYaml, true);
  const to::Spec urdf = three_link(model("arm3_vertical.urdf"), true);
  const to::Spec mjcf = three_link(model("arm3_vertical.xml"), true);
  // axes along -y, gravity -z: the model's x-z plane, x = model x, y = model z (up)
  for (const to::Spec* s : {&urdf, &mjcf}) {
    SCOPED_TRACE(s->arm_origin.format);
    expect_same_dynamics(yaml.chain, s->chain, 1e-13);
    EXPECT_NEAR(s->chain.gravity, 9.81, 1e-12);
    EXPECT_NEAR(s->chain.base_angle, 0.0, 1e-15);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(s->chain.links[i].length, yaml.chain.links[i].length, 1e-15);
    EXPECT_EQ(s->arm_origin.joint_names, (std::vector<std::string>{"shoulder", "elbow", "wrist"}));
  }
  const double t_yaml = to::solve(yaml).solvers.front().duration;
  ASSERT_GT(t_yaml, 0);
  for (const to::Spec* s : {&urdf, &mjcf})
    EXPECT_NEAR(to::solve(*s).solvers.front().duration / t_yaml - 1, 0.0, 1e-9)
        << s->arm_origin.format;
}

TEST(ArmModel, LimitsComeFromTheModelWhereTheCaseSetsNone) {
  // the URDF states effort, velocity and range of every joint: the case needs none of them
  const to::Spec urdf = three_link(model("arm3_vertical.urdf"), false);
  EXPECT_EQ(urdf.velocity_limit, Eigen::Vector3d(2.5, 3.0, 4.0));
  EXPECT_EQ(urdf.torque_limit, Eigen::Vector3d(30.0, 12.0, 3.0));
  ASSERT_EQ(urdf.joint_path.range.size(), 3u);
  EXPECT_EQ(urdf.joint_path.range[0], Eigen::Vector2d(-3.0, 0.0));
  std::string lines;
  for (const auto& l : urdf.arm_origin.limits) lines += l + "\n";
  EXPECT_NE(lines.find("<limit velocity> of joint 'wrist'"), std::string::npos) << lines;
  EXPECT_NE(lines.find("<limit effort> of joint 'shoulder'"), std::string::npos) << lines;
  EXPECT_NE(lines.find("<limit lower upper> of joint 'elbow'"), std::string::npos) << lines;
  // the MJCF: motor forcerange (30, 3) and ctrlrange 6 x gear 2 (12); no velocity limit in
  // MJCF, so the case must state it
  std::string errors;
  load_case_text<to::Spec>(model("arm3_vertical.xml") + kThreeLinkPath, &load_time_optimal,
                           &errors);
  EXPECT_NE(errors.find("missing required key 'time_optimal.velocity_limit_rad_s'"),
            std::string::npos)
      << errors;
  std::string yaml =
      model("arm3_vertical.xml") + kThreeLinkPath + "  velocity_limit_rad_s: [1, 2, 3]\n";
  errors.clear();
  const to::Spec mjcf = load_case_text<to::Spec>(yaml, &load_time_optimal, &errors);
  ASSERT_TRUE(errors.empty()) << errors;
  EXPECT_EQ(mjcf.torque_limit, Eigen::Vector3d(30.0, 12.0, 3.0));
  EXPECT_EQ(mjcf.velocity_limit, Eigen::Vector3d(1, 2, 3));
  lines.clear();
  for (const auto& l : mjcf.arm_origin.limits) lines += l + "\n";
  EXPECT_NE(lines.find("ctrlrange x gain 1 x gear 2 of actuator 'elbow_motor'"), std::string::npos)
      << lines;
  EXPECT_NE(lines.find("velocity_limit_rad_s [1, 2, 3] rad/s: the case"), std::string::npos)
      << lines;
  // a case key overrides the model's
  yaml += "  torque_limit_Nm: [5, 6, 7]\n";
  errors.clear();
  const to::Spec over = load_case_text<to::Spec>(yaml, &load_time_optimal, &errors);
  ASSERT_TRUE(errors.empty()) << errors;
  EXPECT_EQ(over.torque_limit, Eigen::Vector3d(5, 6, 7));
}

// the placement study's default arm, written out, and read from an MJCF and a URDF
const char* kPlacementTask = R"(
placement:
  length_fraction: 0.5
  nx_s: 6
  phi_step_deg: 30
  thesis_divisions: 2
  samples: 21
  map: {nx: 4, ny: 3}
  refine: false
  programs: [cycloidal]
  configurations: [1]
  threads: 1
)";

TEST(ArmModel, ThePlacementArmFromMjcfAndUrdfGivesTheSameOptimum) {
  std::string errors;
  const pl::Spec yaml = load_case_text<pl::Spec>(kPlacementTask, &load_placement, &errors);
  const pl::Spec mjcf = load_case_text<pl::Spec>(
      "arm: {model: ../../reports/cases/thesis_arm.xml}\n" + std::string(kPlacementTask),
      &load_placement, &errors);
  const pl::Spec urdf =
      load_case_text<pl::Spec>(model("thesis_arm.urdf") + kPlacementTask, &load_placement, &errors);
  ASSERT_TRUE(errors.empty()) << errors;
  expect_same_dynamics(yaml.chain, mjcf.chain, 1e-13);
  expect_same_dynamics(yaml.chain, urdf.chain, 1e-13);
  EXPECT_EQ(mjcf.chain.gravity, 0.0);
  const pl::Result ry = pl::solve(yaml);
  ASSERT_FALSE(ry.cases.empty());
  ASSERT_TRUE(ry.cases[0].found) << ry.cases[0].reason;
  const double e = ry.cases[0].refined.reported_metrics().energy;
  for (const pl::Spec* s : {&mjcf, &urdf}) {
    const pl::Result r = pl::solve(*s);
    ASSERT_TRUE(r.cases[0].found);
    EXPECT_NEAR(r.cases[0].refined.reported_metrics().energy / e - 1, 0.0, 1e-9);
  }
}

// the cycle-time objective on the arm read from MJCF (reports/cases/placement-mjcf.yaml's
// model): the same fastest placement, time and energy as the arm written in YAML
TEST(ArmModel, TheCycleTimeObjectiveOnTheMjcfArmIsTheYamlArms) {
  const std::string task = std::string(kPlacementTask) +
                           "  cycle_time:\n"
                           "    velocity_limit_rad_s: [3.0, 4.0]\n"
                           "    torque_limit_Nm: [20.0, 8.0]\n"
                           "    grid_points: 300\n";
  std::string errors;
  pl::Spec yaml = load_case_text<pl::Spec>(task, &load_placement, &errors);
  pl::Spec mjcf = load_case_text<pl::Spec>(
      "arm: {model: ../../reports/cases/thesis_arm.xml}\n" + task, &load_placement, &errors);
  ASSERT_TRUE(errors.empty()) << errors;
  ASSERT_TRUE(mjcf.cycle_time.has_value());
  for (pl::Spec* s : {&yaml, &mjcf}) {
    s->map_nx = 16;  // (a map with admissible nodes: kPlacementTask's 4 x 3 has none)
    s->map_ny = 8;
  }
  const pl::Result ry = pl::solve(yaml), rm = pl::solve(mjcf);
  ASSERT_EQ(ry.cycle_time.size(), 1u);
  ASSERT_EQ(rm.cycle_time.size(), 1u);
  const pl::CycleTimeOptimum &oy = ry.cycle_time[0].optimum, &om = rm.cycle_time[0].optimum;
  ASSERT_TRUE(oy.found) << oy.reason;
  ASSERT_TRUE(om.found) << om.reason;
  EXPECT_NEAR(om.converged.duration / oy.converged.duration - 1, 0.0, 1e-9);
  EXPECT_LE((om.root - oy.root).norm(), 1e-9);
  ASSERT_TRUE(oy.fast_energy.computed && om.fast_energy.computed);
  EXPECT_NEAR(om.fast_energy.energy / oy.fast_energy.energy - 1, 0.0, 1e-9);
  EXPECT_NE(rm.message.find("fastest cycle"), std::string::npos) << rm.message;
}

TEST(ArmModel, AVerticalModelIsRefusedByThePlacementStudyAndGravityIsTheModels) {
  std::string errors;
  load_case_text<pl::Spec>(model("arm3_vertical.xml") + kPlacementTask, &load_placement, &errors);
  EXPECT_NE(errors.find("expected 2 links for this study"), std::string::npos) << errors;
  errors.clear();
  load_case_text<to::Spec>(model("arm3_vertical.urdf") + "gravity: 9.81\n" + kThreeLinkPath,
                           &load_time_optimal, &errors);
  EXPECT_NE(errors.find("'gravity' is given with 'arm.model'"), std::string::npos) << errors;
}

}  // namespace
}  // namespace armstudy::cases
