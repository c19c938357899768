// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Every active constraint of a placement optimum is named, the same way for a configuration
// and its mirror image: at 0.9 Lmax with a 12 W elbow power limit both the outer clearance
// margin and the power limit bind the cycloidal optimum of both configurations, whose slacks
// differ only by rounding (4e-18 m against 8e-16 m; 7e-15 W against 2e-15 W), so a name
// chosen by the smaller slack changed with the configuration.
#include <gtest/gtest.h>

#include "studies/placement/geometry.hpp"
#include "studies/placement/printed_limits.hpp"
#include "studies/placement/solve.hpp"
#include "testing/arms.hpp"

namespace armstudy::studies::placement::active_set_test {

TEST(PlacementActiveSet, AConfigurationAndItsMirrorImageNameTheSameActiveConstraints) {
  Spec s;
  s.chain = testing::thesis_arm();
  s.length = 0.9 * annulus(0.4, 0.2).lmax;
  s.programs = {core::MotionProgram::kCycloidal};
  s.power_limit = std::array<double, 2>{1000.0, 12.0};
  s.map_nx = 20;
  s.map_ny = 10;
  const Result r = solve(s);
  ASSERT_EQ(r.cases.size(), 2u);
  const ProgramConfig& c1 = r.cases[0];
  const ProgramConfig& c2 = r.cases[1];
  ASSERT_TRUE(c1.found && c2.found);
  // mirror images: the same energy, roots mirrored in the line's perpendicular bisector
  const double e1 = c1.refined.reported_metrics().energy;
  const double e2 = c2.refined.reported_metrics().energy;
  EXPECT_NEAR(e1, e2, 1e-9 * e1);
  EXPECT_NEAR(c1.refined.root.x() + c2.refined.root.x(), s.length, 1e-6);
  EXPECT_NEAR(c1.refined.root.y(), c2.refined.root.y(), 1e-6);
  // both constraints active in both, in the same order, and the same one named binding
  for (const ProgramConfig* c : {&c1, &c2}) {
    const Decision& d = c->decision;
    ASSERT_EQ(d.active.size(), 2u) << c->configuration;
    EXPECT_EQ(d.active[0].kind, Binding::kOuterClearance);
    EXPECT_EQ(d.active[1].kind, Binding::kPowerLimit);
    EXPECT_EQ(d.active[1].joint, 1);
    EXPECT_EQ(d.binding, Binding::kOuterClearance);
    EXPECT_TRUE(d.margin_active());
    // a margin is active: the optimum is re-solved over the margins for both
    EXPECT_GE(c->margin_sensitivity.size(), 3u) << c->configuration;
  }
  // and the sentence counts both optima as set by the margin
  EXPECT_NE(r.message.find("2 of 2 optima are set by the clearance margin"), std::string::npos)
      << r.message;
  EXPECT_NE(r.message.find("the power limit of joint 2 (12.0000 W) is active too"),
            std::string::npos)
      << r.message;
  // every printed point (the optima and the margin-sweep points, each at the samples where
  // its doubling converged) keeps the 12 W limit to the peaks' sampling tolerance, and the
  // check says by how much the worst one reads above it
  const PrintedLimitExcess e = printed_limit_excess(s, r);
  std::printf("printed points %d, largest excess %.3g (%s)\n", e.points, e.relative,
              e.where.c_str());
  int found = 2;
  for (const ProgramConfig* c : {&c1, &c2})
    for (const MarginPoint& m : c->margin_sensitivity) found += m.found;
  EXPECT_EQ(e.points, found);
  const std::optional<Check> check = printed_limits_check(s, r);
  ASSERT_TRUE(check.has_value());
  EXPECT_TRUE(check->passed) << check->description;
  EXPECT_LE(e.relative, 1e-3);
  // a limit below a printed peak is caught
  Spec tighter = s;
  tighter.power_limit = std::array<double, 2>{1000.0, 11.0};
  EXPECT_FALSE(printed_limits_check(tighter, r)->passed);
}

}  // namespace armstudy::studies::placement::active_set_test
