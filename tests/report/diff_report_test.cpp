// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The diff report's relative change of a key figure: finite wherever the ratio is.
#include "report/diff_report.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace armstudy::report {
namespace {

FigureDiff figure(double base, double now) {
  FigureDiff f;
  f.base = base;
  f.now = now;
  return f;
}

// 1e308 to -1e308: the difference overflows to -inf, which the column showed as "from 0"
TEST(DiffReport, TheRelativeChangeOfHugeOppositeFiguresIsMinusTwoNotFromZero) {
  EXPECT_EQ(figure(1e308, -1e308).rel_change(), -2.0);
  EXPECT_EQ(figure(-1e308, 1e308).rel_change(), 2.0);
  EXPECT_EQ(figure(2.0, 3.0).rel_change(), 0.5);
  EXPECT_EQ(figure(-2.0, -3.0).rel_change(), -0.5);
  EXPECT_TRUE(std::isinf(figure(0.0, 1.0).rel_change())) << "from 0 only from 0";
}

}  // namespace
}  // namespace armstudy::report
