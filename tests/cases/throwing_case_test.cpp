// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The `throwing:` section of case files (throwing_case.hpp): the bundled case spells out
// exactly the documented defaults (Table 1, Sec. 4 of 003), degrees become radians, and
// every user error names its file:line:col with what was expected.
#include "cases/throwing_case.hpp"

#include <gtest/gtest.h>

#include "testing/case_keys.hpp"

#include <cmath>

#include "core/types.hpp"

namespace armstudy::cases {
namespace {

studies::ThrowingSpec load_text(const std::string& text, Diagnostics& d) {
  const auto root = parse_text(text, d);
  EXPECT_TRUE(root.has_value());
  Map m(*root, d, "");
  testing::mark_cli_keys(m);
  auto s = load_throwing_spec(m);
  m.finish();
  return s;
}

TEST(ThrowingCase, BundledCaseEqualsTheDocumentedDefaults) {
  Diagnostics d(ARMSTUDY_SOURCE_DIR "/reports/cases/throwing.yaml");
  std::string text;
  const auto root = parse_file(d.path(), d, &text);
  ASSERT_TRUE(root.has_value());
  Map m(*root, d, "");
  testing::mark_cli_keys(m);
  const studies::ThrowingSpec s = load_throwing_spec(m);
  m.finish();
  ASSERT_TRUE(d.empty()) << d.errors()[0].format();
  const studies::ThrowingSpec def;
  EXPECT_NEAR(s.release[0], 13 * core::kPi / 36, 1e-12);
  EXPECT_NEAR(s.release[1], -7 * core::kPi / 36, 1e-12);
  EXPECT_NEAR(s.theta3_release, -7 * core::kPi / 24, 1e-12);
  EXPECT_NEAR(s.start[0], def.start[0], 1e-12);
  EXPECT_NEAR(s.tray_width, def.tray_width, 1e-12);
  EXPECT_NEAR(s.release_tolerance, def.release_tolerance, 1e-6);
  EXPECT_EQ(s.arm.l1, def.arm.l1);
  EXPECT_EQ(s.arm.circle_offset, def.arm.circle_offset);
  EXPECT_NEAR(s.arm.Ib, 4.8e-7, 1e-15);  // solid sphere = Table 1's figure
  EXPECT_EQ(s.motor.Ra, def.motor.Ra);
  EXPECT_EQ(s.current_max, def.current_max);
  EXPECT_EQ(s.stages, def.stages);
  EXPECT_EQ(s.idp.iterations, def.idp.iterations);
  EXPECT_EQ(s.idp.max_passes, def.idp.max_passes);
  EXPECT_EQ(s.idp.tolerance, def.idp.tolerance);
  EXPECT_EQ(s.idp.seeds, def.idp.seeds);
  EXPECT_GE(s.idp.seeds, 4);
  EXPECT_EQ(s.idp.shrink, def.idp.shrink);
  EXPECT_EQ(s.idp.restore, def.idp.restore);
  EXPECT_EQ(s.idp.candidates, def.idp.candidates);
  EXPECT_EQ(s.idp.region, def.idp.region);
  EXPECT_EQ(s.steps_per_stage, def.steps_per_stage);
  EXPECT_EQ(s.power_max, 60.0);  // Table 1: rated 60 W
  EXPECT_EQ(s.voltage_max, 24.0);
  EXPECT_EQ(s.contact_margin, def.contact_margin);
  EXPECT_GT(s.contact_margin, 0.0);
  EXPECT_EQ(s.friction_coefficient, def.friction_coefficient);
  EXPECT_EQ(s.backoff, def.backoff);
  EXPECT_EQ(s.allow_not_converged, false);
  EXPECT_EQ(s.check_refinement, 4);
  EXPECT_EQ(s.nlopt.ftol_rel, def.nlopt.ftol_rel);
  EXPECT_EQ(s.nlopt.xtol_rel, def.nlopt.xtol_rel);
  EXPECT_EQ(s.nlopt.max_time, def.nlopt.max_time);
  EXPECT_EQ(s.nlopt.max_evaluations, def.nlopt.max_evaluations);
  EXPECT_EQ(s.arm.motor2, studies::Motor2Mount::kOnLink1);
}

TEST(ThrowingCase, EmptySectionGivesDefaultsAndOnBaseMountIsRead) {
  Diagnostics d("t.yaml");
  const auto s =
      load_text("throwing:\n  motors:\n    motor2: on_base\n    rotor_inertia_kg_m2: 2.0e-6\n", d);
  ASSERT_TRUE(d.empty()) << d.errors()[0].format();
  EXPECT_EQ(s.arm.motor2, studies::Motor2Mount::kOnBase);
  EXPECT_EQ(s.arm.rotor_inertia, 2.0e-6);
  EXPECT_EQ(s.tf, 0.8);
}

TEST(ThrowingCase, ErrorsNameLineColumnAndWhatWasExpected) {
  Diagnostics d("t.yaml");
  load_text(
      "throwing:\n"
      "  ball:\n"
      "    mass_kg: -0.01\n"
      "    inertia: hollow\n"
      "  motors:\n"
      "    motor2: on_bse\n"
      "  task:\n"
      "    release_deg: [65, -35]\n"
      "  idp:\n"
      "    stages: 1\n"
      "    candiates: 4\n",
      d);
  std::vector<std::string> msgs;
  for (const auto& e : d.errors()) msgs.push_back(e.format());
  ASSERT_EQ(msgs.size(), 6u) << ::testing::PrintToString(msgs);
  EXPECT_EQ(msgs[0],
            "t.yaml:3:14: 'throwing.ball.mass_kg' is -0.01; should be in [1e-06, 1000000] kg");
  EXPECT_NE(msgs[1].find("t.yaml:4:14: 'throwing.ball.inertia' (or 'solid_sphere') is 'hollow'"),
            std::string::npos);
  EXPECT_NE(msgs[2].find("t.yaml:6:13:"), std::string::npos);
  EXPECT_NE(msgs[2].find("did you mean 'on_base'?"), std::string::npos);
  EXPECT_NE(msgs[3].find("t.yaml:8:18:"), std::string::npos);
  EXPECT_NE(msgs[3].find("expected a list of 3 numbers"), std::string::npos);
  EXPECT_NE(msgs[4].find("t.yaml:10:13: 'throwing.idp.stages' is 1; should be in [2, 64]"),
            std::string::npos);
  EXPECT_EQ(msgs[5],
            "t.yaml:11:5: unknown key 'throwing.idp.candiates'; did you mean 'candidates'?");
}

TEST(ThrowingCase, ConstraintAndConvergenceKeysAreRead) {
  Diagnostics d("t.yaml");
  const auto s = load_text(
      "throwing:\n"
      "  motors: {power_max_W: 45}\n"
      "  constraints: {contact_margin_N: 0.05, friction_coefficient: 0.3, release_tolerance_deg: "
      "2, backoff: 0.01}\n"
      "  idp: {max_passes: 7, tolerance: 1.0e-4, seeds: 6}\n"
      "  nlopt: {ftol_rel: 1.0e-7, xtol_rel: 1.0e-5}\n"
      "  checks: {allow_not_converged: true, refinement: 8}\n",
      d);
  ASSERT_TRUE(d.empty()) << d.errors()[0].format();
  EXPECT_EQ(s.power_max, 45);
  EXPECT_EQ(s.contact_margin, 0.05);
  EXPECT_EQ(s.friction_coefficient, 0.3);
  EXPECT_NEAR(s.release_tolerance, 2 * core::kPi / 180, 1e-15);
  EXPECT_EQ(s.backoff, 0.01);
  EXPECT_EQ(s.idp.max_passes, 7);
  EXPECT_EQ(s.idp.tolerance, 1e-4);
  EXPECT_EQ(s.idp.seeds, 6);
  EXPECT_EQ(s.nlopt.ftol_rel, 1e-7);
  EXPECT_EQ(s.nlopt.xtol_rel, 1e-5);
  EXPECT_TRUE(s.allow_not_converged);
  EXPECT_EQ(s.check_refinement, 8);
}

TEST(ThrowingCase, NegativeFrictionCoefficientIsAnError) {
  Diagnostics d("t.yaml");
  load_text("throwing:\n  constraints:\n    friction_coefficient: -1\n", d);
  ASSERT_EQ(d.errors().size(), 1u);
  EXPECT_NE(
      d.errors()[0].format().find("t.yaml:3:27: 'throwing.constraints.friction_coefficient' is -1"),
      std::string::npos)
      << d.errors()[0].format();
}

}  // namespace
}  // namespace armstudy::cases
