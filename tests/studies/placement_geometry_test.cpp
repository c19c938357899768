// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The thesis's search intervals (cases 4.7-4.13), the exact annulus check and the line frame
// of the placement study (Kopmaz 2016, Ch. 4).
#include "studies/placement/geometry.hpp"

#include <gtest/gtest.h>

#include <random>

#include "testing/arms.hpp"

namespace armstudy::studies::placement {
namespace {

using armstudy::testing::kDeg;
const Annulus kThesis = annulus(0.4, 0.2);

TEST(PlacementGeometry, LmaxIsTheChordOfTheOuterCircleTangentToTheInner) {
  EXPECT_NEAR(kThesis.lmax, 1.1314, 1e-4);  // Ch. 9
  EXPECT_NEAR(longest_line(kThesis, 0.0), kThesis.lmax, 1e-12);
  EXPECT_LT(longest_line(kThesis, 0.01), kThesis.lmax);
  // the (4.10) line: start on the outer circle, tangent to the inner, end on the outer
  const PhiInterval p = thesis_phi_interval(kThesis, kThesis.lmax, kThesis.outer);
  EXPECT_EQ(p.thesis_case, 1);
  EXPECT_NEAR(p.init / kDeg, 160.53, 0.01);  // printed in Example 1
  const LineCheck c = check_line(0.4, 0.2, thesis_line(kThesis.outer, p.init), kThesis.lmax);
  EXPECT_NEAR(c.r_min, kThesis.inner, 1e-12);
  EXPECT_NEAR(c.r_max, kThesis.outer, 1e-12);
  EXPECT_NEAR(c.boundary_distance, 0.0, 1e-12);
  EXPECT_NEAR(c.min_abs_sin, 0.0, 1e-6);
}

TEST(PlacementGeometry, Case2IntervalRunsFromTheOuterCircleToTheInnerTangent) {
  const double L = 0.8 * kThesis.lmax;
  const XsInterval xs = thesis_xs_interval(kThesis, L);
  EXPECT_EQ(xs.thesis_case, 2);
  EXPECT_DOUBLE_EQ(xs.init, kThesis.outer);
  for (const double x_s : {xs.fin, 0.5 * (xs.init + xs.fin), xs.init}) {
    const PhiInterval p = thesis_phi_interval(kThesis, L, x_s);
    EXPECT_EQ(p.thesis_case, 2);
    // phi_init (4.11a): the end point lies on the outer circle
    const Line a = thesis_line(x_s, p.init);
    EXPECT_NEAR((a.start + L * a.dir).norm(), kThesis.outer, 1e-12);
    // phi_fin (4.11b): the line's carrier is tangent to the inner circle
    const Line b = thesis_line(x_s, p.fin);
    EXPECT_NEAR(std::abs(b.start.x() * b.dir.y() - b.start.y() * b.dir.x()), kThesis.inner, 1e-12);
  }
}

TEST(PlacementGeometry, ShortLinesUseCase4AndStartAlongTheAxisWhenThereIsRoom) {
  const double L = 0.2 * kThesis.lmax;  // 0.226 m <= 2 L2
  EXPECT_EQ(thesis_xs_interval(kThesis, L).thesis_case, 3);
  EXPECT_DOUBLE_EQ(thesis_xs_interval(kThesis, L).fin, kThesis.inner);
  const PhiInterval p = thesis_phi_interval(kThesis, L, 0.3);
  EXPECT_EQ(p.thesis_case, 4);
  EXPECT_EQ(p.init, 0.0);  // (4.13a): R - x_s >= L
}

TEST(PlacementGeometry, ExactCheckMatchesDenseSampling) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> xs(0.1, 0.7), ph(-3.1, 3.1), len(0.05, 1.1);
  for (int trial = 0; trial < 300; ++trial) {
    const Line line = thesis_line(xs(rng), ph(rng));
    const double L = len(rng);
    const LineCheck c = check_line(0.4, 0.2, line, L);
    double rmin = 1e9, rmax = 0;
    for (int k = 0; k <= 20000; ++k) {
      const double r = (line.start + (L * k / 20000) * line.dir).norm();
      rmin = std::min(rmin, r);
      rmax = std::max(rmax, r);
    }
    EXPECT_NEAR(c.r_min, rmin, 1e-6);
    EXPECT_NEAR(c.r_max, rmax, 1e-12);
    EXPECT_NEAR(c.boundary_distance, std::min(rmin - kThesis.inner, kThesis.outer - rmax), 1e-6);
  }
}

TEST(PlacementGeometry, RootLocationRoundTripsThroughTheThesisLine) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Vector2d root(u(rng), u(rng));
    const Eigen::Vector2d lp = line_of_root(root);
    EXPECT_TRUE(testing::near_rel_vec(root_in_line_frame(lp[0], lp[1]), root, 1e-14));
    // (4.14): the root seen from the line's start, in the frame of the line
    const Line line = thesis_line(lp[0], lp[1]);
    const Eigen::Vector2d n(-line.dir.y(), line.dir.x());
    EXPECT_NEAR((-line.start).dot(line.dir), root.x(), 1e-14);
    EXPECT_NEAR((-line.start).dot(n), root.y(), 1e-14);
  }
}

}  // namespace
}  // namespace armstudy::studies::placement
