// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// `study: time_optimal` case files: the documented defaults and the path forms.
#include "cases/time_optimal_case.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <regex>

#include "cases/arm_loader.hpp"
#include "core/dynamics.hpp"

namespace armstudy::cases {
namespace {
namespace to = studies::time_optimal;

struct TimeOptimalLoad {
  to::Spec spec;
  std::string errors;
};

TimeOptimalLoad load_yaml(const std::string& yaml) {
  Diagnostics d("c.yaml");
  const YAML::Node n = YAML::Load(yaml);
  Map root(n, d, "");
  TimeOptimalLoad out;
  out.spec = load_time_optimal(root);
  root.finish();
  for (const auto& e : d.errors()) out.errors += e.format() + "\n";
  return out;
}

TEST(TimeOptimalCase, DefaultsAreTheSourcesArmAndTheDocumentedSettings) {
  const TimeOptimalLoad l =
      load_yaml("time_optimal:\n  path: {points_m: [[0.3, 0.1], [-0.1, 0.8]]}\n");
  ASSERT_TRUE(l.errors.empty()) << l.errors;
  const to::Spec& s = l.spec;
  // massless links with 1.0 kg at the end of each, L1 = 0.5 m, L2 = 0.4 m, horizontal
  ASSERT_EQ(s.chain.num_links(), 2);
  EXPECT_EQ(s.chain.links[0].length, 0.5);
  EXPECT_EQ(s.chain.links[1].length, 0.4);
  EXPECT_EQ(s.chain.links[0].mass, 0.0);
  EXPECT_EQ(s.chain.gravity, 0.0);
  EXPECT_DOUBLE_EQ(payload_mass(s.chain), 1.0);
  // the mass matrix at q2 = 90 deg of two unit point masses: M11 = 2 L1^2 + L2^2
  const Eigen::MatrixXd M =
      core::mass_matrix(s.chain, core::JointVector(Eigen::Vector2d(0.0, M_PI / 2)));
  EXPECT_NEAR(M(0, 0), 2 * 0.25 + 0.16, 1e-12);
  EXPECT_EQ(s.path.kind, to::PathKind::kLine);
  EXPECT_EQ(s.configuration, 1);
  EXPECT_EQ(s.velocity_limit, Eigen::Vector2d(3.0, 4.0));
  EXPECT_EQ(s.torque_limit, Eigen::Vector2d(10.0, 4.0));
  EXPECT_FALSE(s.acceleration_limit.has_value());
  EXPECT_EQ(s.dp.segments, 10);
  EXPECT_EQ(s.dp.levels, 200);
  EXPECT_EQ(s.dp.states, std::vector<to::DpState>{to::DpState::kPathSpeed});
  EXPECT_EQ(s.dp.convergence_segments,
            (std::vector<int>{10, 20, 50, 100, 200}));  // the issue's table
  EXPECT_TRUE(s.complex.enabled);
  EXPECT_EQ(s.exact.grid_points, 1000);
  EXPECT_EQ(s.exact.grid_tolerance, 1e-3);
  EXPECT_EQ(s.exact.tolerance_rel, 1e-4);
  EXPECT_EQ(s.exact.max_grid_points, 200000);
}

TEST(TimeOptimalCase, ReadsEveryKeyAndAnEmptyConvergenceList) {
  const TimeOptimalLoad l = load_yaml(R"(
time_optimal:
  path: {kind: spline, points_m: [[0.6, -0.2], [0.55, 0.25], [0.2, 0.5]]}
  configuration: 2
  velocity_limit_rad_s: [2, 3]
  torque_limit_Nm: [5, 6]
  acceleration_limit_rad_s2: [7, 8]
  dp: {segments: 12, levels: 50, checks_per_segment: 3, states: [joint1_velocity, path_speed], convergence_segments: []}
  complex: {enabled: false, max_iterations: 10, tolerance: 1.0e-6, seed: 4}
  exact: {grid_points: 300, checks_per_interval: 5, grid_tolerance: 2.5e-3, tolerance_rel: 0, max_grid_points: 5000}
  motion_steps: 40
)");
  ASSERT_TRUE(l.errors.empty()) << l.errors;
  const to::Spec& s = l.spec;
  EXPECT_EQ(s.path.kind, to::PathKind::kSpline);
  EXPECT_EQ(s.path.points.size(), 3u);
  EXPECT_EQ(s.configuration, 2);
  EXPECT_EQ(*s.acceleration_limit, Eigen::Vector2d(7, 8));
  EXPECT_EQ(s.dp.segments, 12);
  EXPECT_EQ(s.dp.levels, 50);
  EXPECT_EQ(s.dp.checks_per_segment, 3);
  EXPECT_EQ(s.dp.states.front(), to::DpState::kJoint1Velocity);
  EXPECT_TRUE(s.dp.convergence_segments.empty());
  EXPECT_FALSE(s.complex.enabled);
  EXPECT_EQ(s.complex.seed, 4u);
  EXPECT_EQ(s.exact.grid_points, 300);
  EXPECT_EQ(s.exact.checks_per_interval, 5);
  EXPECT_EQ(s.exact.grid_tolerance, 2.5e-3);
  EXPECT_EQ(s.exact.tolerance_rel, 0.0);
  EXPECT_EQ(s.exact.max_grid_points, 5000);
  EXPECT_EQ(s.motion_steps, 40);
}

TEST(TimeOptimalCase, AGridToleranceMustBePositive) {
  const TimeOptimalLoad l = load_yaml(R"(
time_optimal:
  path: {kind: line, points_m: [[0.3, 0.1], [-0.1, 0.8]]}
  exact: {grid_tolerance: 0}
)");
  EXPECT_NE(l.errors.find("grid_tolerance"), std::string::npos) << l.errors;
}

TEST(TimeOptimalCase, AGradingToleranceMustNotBeNegative) {
  const TimeOptimalLoad l = load_yaml(R"(
time_optimal:
  path: {kind: line, points_m: [[0.3, 0.1], [-0.1, 0.8]]}
  exact: {tolerance_rel: -1.0e-4}
)");
  // one error, at the number (line 4), naming the key and the rule
  EXPECT_TRUE(std::regex_match(
      l.errors, std::regex("c\\.yaml:4:[0-9]+: [^\n]*tolerance_rel[^\n]*should be >= 0\n")))
      << l.errors;
  // 0 (no grading) and a positive tolerance are read as written
  for (const double tol : {0.0, 2.5e-4}) {
    const TimeOptimalLoad ok = load_yaml(
        "time_optimal:\n  path: {kind: line, points_m: [[0.3, 0.1], [-0.1, 0.8]]}\n"
        "  exact: {tolerance_rel: " +
        std::to_string(tol) + "}\n");
    EXPECT_TRUE(ok.errors.empty()) << ok.errors;
    EXPECT_EQ(ok.spec.exact.tolerance_rel, tol);
  }
}

TEST(TimeOptimalCase, APolylineNeedsTwoSegmentsPerPiece) {
  const TimeOptimalLoad l = load_yaml(R"(
time_optimal:
  path: {kind: polyline, points_m: [[0.6, -0.2], [0.55, 0.25], [0.2, 0.5], [-0.2, 0.5]]}
  dp: {segments: 4}
)");
  EXPECT_NE(l.errors.find("expected at least two segments per polyline piece (3 pieces)"),
            std::string::npos)
      << l.errors;
}

const char* kThreeLinks =
    "arm:\n  links:\n    - {length: 0.4, mass: 3.0}\n    - {length: 0.35, mass: 2.0}\n"
    "    - {length: 0.25, mass: 1.0}\ngravity: 9.81\n";

TEST(TimeOptimalCase, ReadsAJointPathWithItsRangesAndOneLimitPerJoint) {
  const TimeOptimalLoad l =
      load_yaml(std::string(kThreeLinks) +
                "time_optimal:\n  joint_path:\n    kind: spline\n"
                "    points_rad: [[-2.3, 0.5, 0.4], [-1.9, 0.2, 0.3], [-0.8, -0.5, -0.4]]\n"
                "    range_rad: [[-3, 0], [-1.5, 1.5], [-1.5, 1.5]]\n"
                "  velocity_limit_rad_s: [2, 3, 4]\n  torque_limit_Nm: [30, 12, 3]\n"
                "  acceleration_limit_rad_s2: [50, 60, 70]\n");
  ASSERT_EQ(l.errors, "");
  EXPECT_EQ(l.spec.space, to::PathSpace::kJoint);
  EXPECT_EQ(l.spec.joint_path.kind, to::PathKind::kSpline);
  ASSERT_EQ(l.spec.joint_path.points.size(), 3u);
  EXPECT_EQ(l.spec.joint_path.points[1][2], 0.3);
  ASSERT_EQ(l.spec.joint_path.range.size(), 3u);
  EXPECT_EQ(l.spec.joint_path.range[0], Eigen::Vector2d(-3, 0));
  EXPECT_EQ(l.spec.velocity_limit.size(), 3);
  EXPECT_EQ(l.spec.torque_limit[2], 3.0);
  EXPECT_EQ((*l.spec.acceleration_limit)[1], 60.0);
  EXPECT_EQ(l.spec.chain.num_links(), 3);
}

TEST(TimeOptimalCase, AJointPathRefusesATipPathBesideItAnElbowAndMissingLimits) {
  const std::string jp =
      "  joint_path: {kind: line, points_rad: [[-2.3, 0.5, 0.4], [-0.8, -0.5, -0.4]]}\n";
  const std::string limits = "  velocity_limit_rad_s: [2, 3, 4]\n  torque_limit_Nm: [30, 12, 3]\n";
  const auto has = [](const TimeOptimalLoad& l, const std::string& what) {
    return l.errors.find(what) != std::string::npos;
  };
  const TimeOptimalLoad both = load_yaml(std::string(kThreeLinks) + "time_optimal:\n" + jp +
                                         limits + "  path: {points_m: [[0.3, 0.1], [0.0, 0.5]]}\n");
  EXPECT_TRUE(has(both, "has both 'path' (a tip path) and 'joint_path'")) << both.errors;
  const TimeOptimalLoad elbow = load_yaml(std::string(kThreeLinks) + "time_optimal:\n" + jp +
                                          limits + "  configuration: 2\n");
  EXPECT_TRUE(has(elbow, "'time_optimal.configuration' chooses the elbow")) << elbow.errors;
  // a 3-link arm has no default limits (the defaults are the 2-link source's)
  const TimeOptimalLoad bare = load_yaml(std::string(kThreeLinks) + "time_optimal:\n" + jp);
  EXPECT_TRUE(
      has(bare, "missing required key 'time_optimal.velocity_limit_rad_s' for an arm of 3 links"))
      << bare.errors;
  EXPECT_TRUE(has(bare, "missing required key 'time_optimal.torque_limit_Nm'")) << bare.errors;
  // a 2-link arm's joint path takes the default limits
  const TimeOptimalLoad two =
      load_yaml("time_optimal:\n  joint_path: {points_rad: [[0.1, 1.0], [0.8, 0.4]]}\n");
  EXPECT_EQ(two.errors, "");
  EXPECT_EQ(two.spec.space, to::PathSpace::kJoint);
  EXPECT_EQ(two.spec.velocity_limit, to::joint_pair(3.0, 4.0));
}

TEST(TimeOptimalCase, ARefusedArmIsReportedOnceNotAgainstEveryWaypointAndLimit) {
  // 8 links (one more than a chain may have): the joint path and the limits are not judged
  // against the 2-link fallback arm, and nothing is read past a joint vector's capacity
  std::string yaml = "arm:\n  links:\n";
  for (int i = 0; i < 8; ++i) yaml += "    - {length: 0.1, mass: 1.0}\n";
  const std::string eight = "[0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1]";
  yaml += "time_optimal:\n  joint_path: {points_rad: [" + eight +
          ", [0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2]]}\n"
          "  velocity_limit_rad_s: " +
          eight + "\n  torque_limit_Nm: " + eight + "\n";
  const TimeOptimalLoad l = load_yaml(yaml);
  EXPECT_NE(l.errors.find("'arm.links' has 8 links; expected 1 to 7 links"), std::string::npos)
      << l.errors;
  EXPECT_EQ(std::count(l.errors.begin(), l.errors.end(), '\n'), 1) << l.errors;
}

}  // namespace
}  // namespace armstudy::cases
