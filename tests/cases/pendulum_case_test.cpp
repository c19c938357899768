// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The `pendulum:` section of case files (pendulum_case.hpp): the bundled case equals the
// documented defaults (Sec. 3 of 003), and errors carry file:line:col.
#include "cases/pendulum_case.hpp"

#include <gtest/gtest.h>

#include "testing/case_keys.hpp"

#include "core/types.hpp"

namespace armstudy::cases {
namespace {

TEST(PendulumCase, BundledCaseEqualsTheDocumentedDefaults) {
  Diagnostics d(ARMSTUDY_SOURCE_DIR "/reports/cases/pendulum.yaml");
  std::string text;
  const auto root = parse_file(d.path(), d, &text);
  ASSERT_TRUE(root.has_value());
  Map m(*root, d, "");
  testing::mark_cli_keys(m);
  const studies::PendulumSpec s = load_pendulum_spec(m);
  m.finish();
  ASSERT_TRUE(d.empty()) << d.errors()[0].format();
  // the values default_pendulum_spec() and the case's comments document (Sec. 3's m3, m4,
  // r4, r_b; the tray's centre of mass at the cup bottom 0.015 + r4 + r_b, its inertia a
  // 0.18 m rod's m3 (r4 + r_b)^2 / 3; a solid ball 2/5 m4 r_b^2), written out here: the
  // bundled case and the defaults must both equal them
  for (const studies::PendulumSpec& p : {s, studies::default_pendulum_spec()}) {
    EXPECT_EQ(p.theta1, 0.0);
    EXPECT_EQ(p.theta2, 0.0);
    EXPECT_NEAR(p.theta3, -1.5707963267948966, 1e-12);
    EXPECT_NEAR(p.theta4, -0.6283185307179586, 1e-12);
    EXPECT_EQ(p.theta3_rate, 0.0);
    EXPECT_EQ(p.theta4_rate, 0.0);
    EXPECT_EQ(p.arm.gravity, 9.81);
    EXPECT_EQ(p.arm.circle_offset, 0.015);
    EXPECT_EQ(p.arm.m3, 0.109);
    EXPECT_EQ(p.arm.m4, 0.122);
    EXPECT_EQ(p.arm.r4, 0.075);
    EXPECT_EQ(p.arm.rb, 0.015);
    EXPECT_NEAR(p.arm.r3, 0.105, 1e-12);
    EXPECT_EQ(p.arm.r3_lateral, 0.0);
    EXPECT_NEAR(p.arm.I3, 2.943e-4, 1e-12);
    EXPECT_NEAR(p.arm.Ib, 1.098e-5, 1e-15);
    EXPECT_EQ(p.duration, 2.0);
    EXPECT_EQ(p.sample_step, 0.005);
    EXPECT_EQ(p.snapshot_step, 0.13);
    EXPECT_EQ(p.rtol, 1e-12);
    EXPECT_EQ(p.atol, 1e-12);
    EXPECT_EQ(p.drift_tolerance, 1e-8);
    EXPECT_EQ(p.max_steps, 10000000);
  }
}

TEST(PendulumCase, UnknownKeyAndWidthAreRejectedWithPositions) {
  Diagnostics d("p.yaml");
  const auto root = parse_text(
      "pendulum:\n  duration_s: 0\n  tray:\n    width_deg: 90\n  strat_deg: [1, 2]\n", d);
  ASSERT_TRUE(root.has_value());
  Map m(*root, d, "");
  load_pendulum_spec(m);
  m.finish();
  std::vector<std::string> msgs;
  for (const auto& e : d.errors()) msgs.push_back(e.format());
  ASSERT_EQ(msgs.size(), 3u) << ::testing::PrintToString(msgs);
  EXPECT_NE(msgs[0].find("p.yaml:4:5: unknown key 'pendulum.tray.width_deg'"), std::string::npos);
  EXPECT_NE(msgs[1].find("p.yaml:2:15: 'pendulum.duration_s' is 0"), std::string::npos);
  EXPECT_EQ(msgs[2], "p.yaml:5:3: unknown key 'pendulum.strat_deg'; did you mean 'start_deg'?");
}

}  // namespace
}  // namespace armstudy::cases
