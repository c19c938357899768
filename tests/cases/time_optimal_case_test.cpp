// `study: time_optimal` case files: the documented defaults and the path forms.
#include "cases/time_optimal_case.hpp"

#include <gtest/gtest.h>

#include "cases/arm_loader.hpp"
#include "core/dynamics.hpp"

namespace armstudy::cases {
namespace {
namespace to = studies::time_optimal;

struct Loaded {
  to::Spec spec;
  std::string errors;
};

Loaded load(const std::string& yaml) {
  Diagnostics d("c.yaml");
  const YAML::Node n = YAML::Load(yaml);
  Map root(n, d, "");
  Loaded out;
  out.spec = load_time_optimal(root);
  root.finish();
  for (const auto& e : d.errors()) out.errors += e.format() + "\n";
  return out;
}

TEST(TimeOptimalCase, DefaultsAreTheSourcesArmAndTheDocumentedSettings) {
  const Loaded l = load("time_optimal:\n  path: {points_m: [[0.3, 0.1], [-0.1, 0.8]]}\n");
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
  const Eigen::MatrixXd M = core::mass_matrix(s.chain, core::JointVector(Eigen::Vector2d(0.0, M_PI / 2)));
  EXPECT_NEAR(M(0, 0), 2 * 0.25 + 0.16, 1e-12);
  EXPECT_EQ(s.path.kind, to::PathKind::kLine);
  EXPECT_EQ(s.configuration, 1);
  EXPECT_EQ(s.velocity_limit, Eigen::Vector2d(3.0, 4.0));
  EXPECT_EQ(s.torque_limit, Eigen::Vector2d(10.0, 4.0));
  EXPECT_FALSE(s.acceleration_limit.has_value());
  EXPECT_EQ(s.dp.segments, 10);
  EXPECT_EQ(s.dp.levels, 200);
  EXPECT_EQ(s.dp.states, std::vector<to::DpState>{to::DpState::kPathSpeed});
  EXPECT_EQ(s.dp.convergence_segments, (std::vector<int>{10, 20, 50, 100, 200}));  // the issue's table
  EXPECT_TRUE(s.complex.enabled);
  EXPECT_EQ(s.exact.grid_points, 1000);
  EXPECT_EQ(s.exact.grid_tolerance, 1e-3);
}

TEST(TimeOptimalCase, ReadsEveryKeyAndAnEmptyConvergenceList) {
  const Loaded l = load(R"(
time_optimal:
  path: {kind: spline, points_m: [[0.6, -0.2], [0.55, 0.25], [0.2, 0.5]]}
  configuration: 2
  velocity_limit_rad_s: [2, 3]
  torque_limit_Nm: [5, 6]
  acceleration_limit_rad_s2: [7, 8]
  dp: {segments: 12, levels: 50, checks_per_segment: 3, states: [joint1_velocity, path_speed], convergence_segments: []}
  complex: {enabled: false, max_iterations: 10, tolerance: 1.0e-6, seed: 4}
  exact: {grid_points: 300, checks_per_interval: 5, grid_tolerance: 2.5e-3}
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
  EXPECT_EQ(s.motion_steps, 40);
}

TEST(TimeOptimalCase, AGridToleranceMustBePositive) {
  const Loaded l = load(R"(
time_optimal:
  path: {kind: line, points_m: [[0.3, 0.1], [-0.1, 0.8]]}
  exact: {grid_tolerance: 0}
)");
  EXPECT_NE(l.errors.find("grid_tolerance"), std::string::npos) << l.errors;
}

TEST(TimeOptimalCase, APolylineNeedsTwoSegmentsPerPiece) {
  const Loaded l = load(R"(
time_optimal:
  path: {kind: polyline, points_m: [[0.6, -0.2], [0.55, 0.25], [0.2, 0.5], [-0.2, 0.5]]}
  dp: {segments: 4}
)");
  EXPECT_NE(l.errors.find("expected at least two segments per polyline piece (3 pieces)"), std::string::npos)
      << l.errors;
}

}  // namespace
}  // namespace armstudy::cases
