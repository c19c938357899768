// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// A drawn polyline keeps only the points a frame can show: a finely sampled path (the
// time-optimal tip path has a thousand points) is drawn as few segments, every dropped
// point within the tolerance of the line drawn.

#include <gtest/gtest.h>

#include <cmath>

#include "scene/arm_scene.hpp"
#include "scene/polyline.hpp"

namespace armstudy::scene {
namespace {

double distance_to_polyline(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& line) {
  double best = 1e300;
  for (size_t k = 1; k < line.size(); ++k) {
    const Eigen::Vector2d a = line[k - 1], ab = line[k] - a;
    const double u = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (p - (a + u * ab)).norm());
  }
  return best;
}

TEST(Polyline, AStraightLineOfAThousandPointsIsOneSegment) {
  std::vector<Eigen::Vector2d> p;
  for (int k = 0; k <= 1000; ++k) p.emplace_back(0.3 + 0.001 * k, -0.2 + 0.0005 * k);
  EXPECT_EQ(simplify_polyline(p, 1e-6), (std::vector<size_t>{0, 1000}));
}

TEST(Polyline, EveryDroppedPointOfAnArcStaysWithinTheTolerance) {
  std::vector<Eigen::Vector2d> p;
  for (int k = 0; k <= 1000; ++k) {
    const double a = 1.5 * k / 1000.0;
    p.emplace_back(0.5 * std::cos(a), 0.5 * std::sin(a));
  }
  const double tol = 2e-4;
  const std::vector<size_t> kept = simplify_polyline(p, tol);
  ASSERT_GE(kept.size(), 3u);
  EXPECT_LT(kept.size(), 60u);  // an arc of 0.75 m drawn to 0.2 mm needs a few dozen segments
  EXPECT_EQ(kept.front(), 0u);
  EXPECT_EQ(kept.back(), 1000u);
  std::vector<Eigen::Vector2d> line;
  for (size_t k : kept) line.push_back(p[k]);
  for (const Eigen::Vector2d& q : p) EXPECT_LE(distance_to_polyline(q, line), tol);
}

// a path that turns back on itself (a tip going out and back along one line): the turning
// point is kept, though it lies on the line through the ends
TEST(Polyline, ATurningPointOnTheChordIsKept) {
  std::vector<Eigen::Vector2d> p;
  for (int k = 0; k <= 100; ++k) p.emplace_back(0.01 * k, 0.0);
  for (int k = 99; k >= 50; --k) p.emplace_back(0.01 * k, 0.0);
  const std::vector<size_t> kept = simplify_polyline(p, 1e-6);
  EXPECT_EQ(kept, (std::vector<size_t>{0, 100, 150}));
}

TEST(Polyline, NoToleranceKeepsEveryPoint) {
  std::vector<Eigen::Vector2d> p = {{0, 0}, {1, 0}, {2, 0}};
  EXPECT_EQ(simplify_polyline(p, 0.0).size(), 3u);
  EXPECT_TRUE(simplify_polyline(std::vector<Eigen::Vector2d>{}, 1.0).empty());
  EXPECT_EQ(simplify_polyline(std::vector<Eigen::Vector2d>{{1, 2}}, 1.0), (std::vector<size_t>{0}));
}

// the table scene draws a finely sampled task path as few capsules
TEST(Polyline, TheTableSceneDrawsASampledArcAsFewSegments) {
  core::PlanarChain chain;
  chain.links = {{0.5, 1.0, 0.25, 0.0, 0.02, true}, {0.4, 1.0, 0.2, 0.0, 0.01, true}};
  TableDecor decor;
  for (int k = 0; k <= 1000; ++k) {
    const double a = 1.2 * k / 1000.0;
    decor.task_path.emplace_back(0.6 * std::cos(a), 0.6 * std::sin(a));
  }
  const ArmScene s = horizontal_arm_scene(chain, decor);
  size_t segments = 0;
  for (size_t at = s.mjcf.find("name=\"task"); at != std::string::npos;
       at = s.mjcf.find("name=\"task", at + 1))
    segments += s.mjcf.compare(at, 12, "name=\"task_s") != 0 &&
                s.mjcf.compare(at, 12, "name=\"task_e") != 0;
  EXPECT_GE(segments, 4u);
  EXPECT_LE(segments, 100u);
}

}  // namespace
}  // namespace armstudy::scene
