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
  const studies::PendulumSpec def = studies::default_pendulum_spec();
  EXPECT_NEAR(s.theta3, -core::kPi / 2, 1e-12);
  EXPECT_NEAR(s.theta4, -core::kPi / 5, 1e-12);
  EXPECT_EQ(s.arm.m3, 0.109);
  EXPECT_EQ(s.arm.m4, 0.122);
  EXPECT_EQ(s.arm.r4, 0.075);
  EXPECT_EQ(s.arm.rb, 0.015);
  EXPECT_NEAR(s.arm.r3, def.arm.r3, 1e-12);
  EXPECT_NEAR(s.arm.I3, def.arm.I3, 1e-7);
  EXPECT_NEAR(s.arm.Ib, def.arm.Ib, 1e-15);
  EXPECT_EQ(s.duration, def.duration);
  EXPECT_EQ(s.snapshot_step, 0.13);
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
