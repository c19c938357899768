// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// `study: placement` case files: defaults, units, and every user error at file:line:col.
#include "cases/placement_case.hpp"

#include <gtest/gtest.h>

#include "testing/case_keys.hpp"

#include <filesystem>

#include "app/pipeline.hpp"
#include "studies/placement/geometry.hpp"

namespace armstudy::cases {
namespace {

constexpr double kDeg = core::kPi / 180;

struct Loaded {
  studies::placement::Spec spec;
  std::vector<std::string> errors;
};

Loaded load(const std::string& yaml) {
  Diagnostics d("c.yaml");
  const YAML::Node n = YAML::Load(yaml);
  Map root(n, d, "");
  Loaded out;
  out.spec = load_placement(root);
  root.finish();
  for (const auto& e : d.errors()) out.errors.push_back(e.format());
  return out;
}

bool has_error(const Loaded& l, const std::string& needle) {
  for (const auto& e : l.errors)
    if (e.find(needle) != std::string::npos) return true;
  return false;
}

std::string all(const Loaded& l) {
  std::string s;
  for (const auto& e : l.errors) s += e + "\n";
  return s;
}

// a file with more errors than are shown before its arm: a bad arm is still noticed (the
// error count, not the shown errors, says so) and the study gets the default two-link arm
TEST(PlacementCase, ABadArmAfterTheShownErrorsFallsBackToTheTwoLinkArm) {
  Diagnostics d("c.yaml");
  for (size_t i = 0; i < kMaxErrors; ++i) d.error(YAML::Mark::null_mark(), "earlier error");
  const YAML::Node n =
      YAML::Load("arm:\n  links:\n    - not a link\nplacement:\n  length_fraction: 0.5\n");
  Map root(n, d, "");
  const studies::placement::Spec spec = load_placement(root);
  EXPECT_EQ(spec.chain.num_links(), 2);
  EXPECT_GT(d.count(), kMaxErrors);
}

TEST(PlacementCase, MinimalCaseGetsTheThesisArmAndDocumentedDefaults) {
  const Loaded l = load("placement:\n  length_fraction: 0.5\n");
  ASSERT_TRUE(l.errors.empty()) << all(l);
  const auto& s = l.spec;
  ASSERT_EQ(s.chain.num_links(), 2);
  EXPECT_DOUBLE_EQ(s.chain.links[0].length, 0.4);
  EXPECT_DOUBLE_EQ(s.chain.links[1].mass, 2.0);
  EXPECT_DOUBLE_EQ(s.chain.links[0].inertia, 4.0 * 0.16 / 12);
  ASSERT_EQ(s.chain.point_masses.size(), 1u);
  EXPECT_DOUBLE_EQ(s.chain.point_masses[0].mass, 1.0);
  EXPECT_DOUBLE_EQ(s.chain.gravity, 0.0);
  EXPECT_NEAR(s.length, 0.5 * 4 * std::sqrt(0.08), 1e-15);
  EXPECT_DOUBLE_EQ(s.duration, 1.0);
  EXPECT_EQ(s.programs.size(), 2u);
  EXPECT_EQ(s.configurations, (std::vector<int>{1, 2}));
  EXPECT_EQ(s.nx_s, 50);
  EXPECT_NEAR(s.phi_step, kDeg, 1e-15);
  EXPECT_EQ(s.samples, 401);
  EXPECT_DOUBLE_EQ(s.singularity_margin, 0.01);
  EXPECT_FALSE(s.torque_limit);
  EXPECT_TRUE(s.refine);
  EXPECT_EQ(s.map_nx, 200);
  EXPECT_EQ(s.map_ny, 100);
}

TEST(PlacementCase, EveryKeyIsReadInSiUnits) {
  const Loaded l = load(
      "placement:\n"
      "  length_m: 0.3\n  duration_s: 2\n  programs: [poly4567]\n  configurations: [2]\n"
      "  nx_s: 10\n  phi_step_deg: 2\n  samples: 101\n  singularity_margin_m: 0.02\n"
      "  torque_limits_Nm: [10, 3]\n  power_limits_W: [20, 5]\n  refine: false\n"
      "  map: {nx: 50, ny: 40}\n  threads: 1\n"
      "  evaluate:\n    - {label: a, x_s_m: 0.5, phi_deg: 90}\n    - {root_xy_m: [0.1, 0.3]}\n");
  ASSERT_TRUE(l.errors.empty()) << all(l);
  const auto& s = l.spec;
  EXPECT_DOUBLE_EQ(s.length, 0.3);
  EXPECT_DOUBLE_EQ(s.duration, 2.0);
  EXPECT_EQ(s.programs, std::vector<core::MotionProgram>{core::MotionProgram::kPoly4567});
  EXPECT_EQ(s.configurations, std::vector<int>{2});
  EXPECT_NEAR(s.phi_step, 2 * kDeg, 1e-15);
  EXPECT_EQ(s.samples, 101);
  ASSERT_TRUE(s.torque_limit && s.power_limit);
  EXPECT_EQ((*s.torque_limit)[1], 3.0);
  EXPECT_EQ((*s.power_limit)[0], 20.0);
  EXPECT_FALSE(s.refine);
  EXPECT_EQ(s.map_ny, 40);
  ASSERT_EQ(s.evaluations.size(), 2u);
  EXPECT_NEAR(s.evaluations[0].phi, 0.5 * core::kPi, 1e-15);
  // a root location becomes the thesis's (x_s, phi) with (4.14)
  const Eigen::Vector2d root =
      studies::placement::root_in_line_frame(s.evaluations[1].x_s, s.evaluations[1].phi);
  EXPECT_NEAR(root.x(), 0.1, 1e-15);
  EXPECT_NEAR(root.y(), 0.3, 1e-15);
  EXPECT_EQ(s.evaluations[1].label, "placement 2");
}

TEST(PlacementCase, UserErrorsNameTheirPositionAndWhatIsExpected) {
  EXPECT_TRUE(has_error(load("placement:\n  length_m: 1.5\n"),
                        "c.yaml:2:13: 'placement.length_m' is 1.5 m, longer than Lmax"));
  EXPECT_TRUE(has_error(load("placement:\n  length_m: 0.5\n  length_fraction: 0.5\n"),
                        "expected exactly one of them"));
  EXPECT_TRUE(has_error(load("placement:\n  duration_s: 1\n"),
                        "missing required key 'placement.length_fraction'"));
  EXPECT_TRUE(
      has_error(load("placement:\n  length_fraction: 0\n"), "expected a fraction in (0, 1]"));
  EXPECT_TRUE(has_error(load("placement:\n  length_fraction: 0.5\n  programs: [cycloid]\n"),
                        "c.yaml:3:14: 'placement.programs[1]' is 'cycloid'"));
  EXPECT_TRUE(has_error(load("placement:\n  length_fraction: 0.5\n  programs: [cycloid]\n"),
                        "did you mean 'cycloidal'?"));
  EXPECT_TRUE(has_error(load("placement:\n  length_fraction: 0.5\n  configurations: [3]\n"),
                        "'placement.configurations[1]' is 3"));
  EXPECT_TRUE(has_error(load("placement:\n  length_fraction: 0.5\n  sampels: 10\n"),
                        "c.yaml:3:3: unknown key 'placement.sampels'; did you mean 'samples'?"));
  EXPECT_TRUE(has_error(load("placement:\n  length_fraction: 0.5\n  singularity_margin_m: -1\n"),
                        "'placement.singularity_margin_m' is -1"));
  EXPECT_TRUE(has_error(load("placement:\n  length_fraction: 0.5\n  singularity_margin_m: 0.3\n"),
                        "expected less than half the annulus width"));
  EXPECT_TRUE(has_error(load("placement:\n  length_fraction: 0.5\n  torque_limits_Nm: [1]\n"),
                        "expected a list of 2 numbers"));
  EXPECT_TRUE(has_error(load("gravity: 9.81\nplacement:\n  length_fraction: 0.5\n"),
                        "c.yaml:1:10: 'gravity' is 9.81 m/s^2; expected 0"));
  EXPECT_TRUE(has_error(load("placement:\n  length_fraction: 0.5\n  evaluate:\n    - {label: a}\n"),
                        "gives no placement"));
  EXPECT_TRUE(has_error(load("placement:\n  length_fraction: 0.5\n  evaluate:\n"
                             "    - {x_s_m: 0.5, phi_deg: 1, root_xy_m: [0, 1]}\n"),
                        "expected one placement"));
  EXPECT_TRUE(has_error(
      load("arm:\n  links:\n    - {length: 0.4, mass: 4}\n"
           "    - {length: 0.2, mass: 2, joint: passive}\nplacement:\n  length_fraction: 0.5\n"),
      "expected both joints active"));
  EXPECT_TRUE(has_error(load("name: x\n"), "missing required key 'placement'"));
}

TEST(PlacementCase, ArmKeyReplacesTheThesisArmAndSetsLmax) {
  const Loaded l = load(
      "arm:\n  links:\n    - {length: 0.5, mass: 3}\n    - {length: 0.3, mass: 1}\n  payload: 0.5\n"
      "placement:\n  length_fraction: 1.0\n");
  ASSERT_TRUE(l.errors.empty()) << all(l);
  EXPECT_NEAR(l.spec.length, 4 * std::sqrt(0.15), 1e-15);
  EXPECT_FALSE(load("arm:\n  links:\n    - {length: 0.5, mass: 3}\n    - {length: 0.3, mass: 1}\n"
                    "placement:\n  length_m: 1.6\n")
                   .errors.empty());
}

TEST(PlacementCase, BundledExamplesLoadWithTheThesisLengths) {
  const double fractions[] = {1.0, 0.8, 0.5, 0.4, 0.2};
  const double lmax = 4 * std::sqrt(0.4 * 0.2);
  for (int n = 1; n <= 5; ++n) {
    const std::string path = std::string(ARMSTUDY_SOURCE_DIR) +
                             "/reports/cases/placement-example-" + std::to_string(n) + ".yaml";
    Diagnostics d(path);
    std::string text;
    const auto node = parse_file(path, d, &text);
    ASSERT_TRUE(node) << path;
    Map root(*node, d, "");
    testing::mark_cli_keys(root);
    const auto spec = load_placement(root);
    root.finish();
    ASSERT_TRUE(d.empty()) << d.errors()[0].format();
    EXPECT_NEAR(spec.length, fractions[n - 1] * lmax, 1e-12) << path;
    EXPECT_FALSE(spec.evaluations.empty()) << "the thesis's printed placements are evaluated";
    // and the pipeline accepts the file as a whole
    EXPECT_TRUE(app::load_case(path).run) << path;
  }
}

}  // namespace
}  // namespace armstudy::cases

namespace armstudy::cases {
namespace {

TEST(PlacementCase, CycleTimeBlockLoadsItsLimitsAndGrids) {
  const Loaded l = load(
      "placement:\n  length_fraction: 0.5\n  cycle_time:\n"
      "    velocity_limit_rad_s: [3, 4]\n    torque_limit_Nm: [20, 8]\n"
      "    acceleration_limit_rad_s2: [50, 60]\n    map_grid_points: 50\n");
  ASSERT_TRUE(l.errors.empty()) << all(l);
  ASSERT_TRUE(l.spec.cycle_time.has_value());
  const studies::placement::CycleTimeSpec& ct = *l.spec.cycle_time;
  EXPECT_EQ(ct.velocity_limit[0], 3);
  EXPECT_EQ(ct.velocity_limit[1], 4);
  EXPECT_EQ(ct.torque_limit[0], 20);
  EXPECT_EQ(ct.torque_limit[1], 8);
  ASSERT_TRUE(ct.acceleration_limit.has_value());
  EXPECT_EQ((*ct.acceleration_limit)[1], 60);
  EXPECT_EQ(ct.map_grid_points, 50);
  EXPECT_EQ(ct.grid_points, 1000);  // (its default)
  EXPECT_FALSE(load("placement:\n  length_fraction: 0.5\n").spec.cycle_time.has_value());
}

TEST(PlacementCase, CycleTimeBlockNeedsBothLimits) {
  const Loaded l = load(
      "placement:\n  length_fraction: 0.5\n  cycle_time:\n"
      "    torque_limit_Nm: [20, 8]\n");
  EXPECT_TRUE(has_error(l, "placement.cycle_time.velocity_limit_rad_s")) << all(l);
}

}  // namespace
}  // namespace armstudy::cases
