// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The placement study's cycle-time objective: its times are the time-optimal
// study's on the same line placed at the same root, no admissible map node beats its
// optimum, and configuration 2's optimum is configuration 1's mirror image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "studies/placement/cycle_time_map.hpp"
#include "studies/placement/geometry.hpp"
#include "studies/time_optimal/solve.hpp"
#include "testing/arms.hpp"

namespace armstudy::studies::placement {
namespace {

// example 3's line (L = 0.5 Lmax) on the thesis's arm under the time-optimal study's kind
// of limits (joint velocity and torque), on a small map
Spec cycle_spec() {
  Spec s;
  s.chain = testing::thesis_arm();
  s.length = 0.5 * annulus(0.4, 0.2).lmax;
  s.map_nx = 40;
  s.map_ny = 20;
  CycleTimeSpec ct;
  ct.velocity_limit = time_optimal::joint_pair(3.0, 4.0);
  ct.torque_limit = time_optimal::joint_pair(20.0, 8.0);
  s.cycle_time = ct;
  return s;
}

struct CycleSolved {
  CycleTimeMap map;
  CycleTimeOptimum optimum;
};

CycleSolved solve_configuration(int configuration) {
  CycleSolved s;
  s.map = cycle_time_map(cycle_spec(), configuration);
  s.optimum = cycle_time_optimum(cycle_spec(), configuration, s.map);
  return s;
}

const CycleSolved& cycle_solved(int configuration) {
  static const CycleSolved s1 = solve_configuration(1), s2 = solve_configuration(2);
  return configuration == 1 ? s1 : s2;
}

// The time-optimal study set up here on its own: the line on the world X axis from the
// origin, the arm's root at (X, Y) of the line frame, limits and grid as the cycle-time
// spec's; only the exact solver.
time_optimal::Result time_optimal_at(const Eigen::Vector2d& root, int configuration) {
  const Spec p = cycle_spec();
  time_optimal::Spec t;
  t.chain = p.chain;
  t.chain.base = root;
  t.chain.base_angle = 0.7;  // (any: the time does not depend on the base's rotation)
  t.path.points = {Eigen::Vector2d(0, 0), Eigen::Vector2d(p.length, 0)};
  t.configuration = configuration;
  t.velocity_limit = p.cycle_time->velocity_limit;
  t.torque_limit = p.cycle_time->torque_limit;
  t.dp.states.clear();
  t.dp.convergence_segments.clear();
  t.complex.enabled = false;
  t.exact.grid_points = p.cycle_time->grid_points;
  t.exact.tolerance_rel = p.cycle_time->tolerance_rel;
  return time_optimal::solve(t);
}

void expect_same_time(const Eigen::Vector2d& root, int configuration) {
  const Eigen::Vector2d lp = line_of_root(root);
  const ConvergedCycleTime c = converged_cycle_time(cycle_spec(), configuration, lp[0], lp[1]);
  const time_optimal::Result r = time_optimal_at(root, configuration);
  ASSERT_TRUE(c.solved) << c.message;
  ASSERT_EQ(r.status, Status::kSolved) << r.message;
  const double t = r.grid.reference_duration(r.solvers.front().duration);
  EXPECT_LE(std::abs(c.duration - t), c.error + r.grid.extrapolation_error)
      << "root (" << root.transpose() << "), configuration " << configuration;
  EXPECT_TRUE(testing::near_rel(c.duration, t, 1e-9));  // (the same problem, rotated)
}

TEST(PlacementCycleTime, TheOptimumAndRandomPlacementsTakeTheTimeOptimalStudysDuration) {
  const CycleTimeOptimum& o = cycle_solved(1).optimum;
  ASSERT_TRUE(o.found) << o.reason;
  std::cout << "optimum: " << o.converged.duration << " s +- " << o.duration_error << " s at root ("
            << o.root.transpose() << ") m +- " << o.root_error << " m; map nodes solved "
            << cycle_solved(1).map.solved << " in " << cycle_solved(1).map.seconds
            << " s; refinement solves " << o.evaluations << "\n";
  for (const LimitUse& u : o.converged.limits)
    std::cout << "  joint " << u.joint << " " << u.kind << " " << u.ratio
              << (u.binding ? " binding" : "") << "\n";
  expect_same_time(o.root, 1);
  std::mt19937 rng(52);
  const CycleTimeMap& map = cycle_solved(1).map;
  std::uniform_int_distribution<size_t> pick(0, map.time.size() - 1);
  for (int n = 0; n < 3;) {
    const size_t m = pick(rng);
    if (!std::isfinite(map.time[m])) continue;
    expect_same_time({map.x[m % map.x.size()], map.y[m / map.x.size()]}, n % 2 ? 2 : 1);
    ++n;
  }
}

TEST(PlacementCycleTime, NoAdmissibleMapNodeIsFasterThanTheOptimumBeyondItsError) {
  for (const int configuration : {1, 2}) {
    const CycleSolved& s = cycle_solved(configuration);
    ASSERT_TRUE(s.optimum.found) << s.optimum.reason;
    EXPECT_GT(s.map.solved, 0);
    // the map's five fastest nodes, each converged on its own
    std::vector<size_t> nodes;
    for (size_t m = 0; m < s.map.time.size(); ++m)
      if (std::isfinite(s.map.time[m])) nodes.push_back(m);
    std::partial_sort(nodes.begin(), nodes.begin() + 5, nodes.end(),
                      [&](size_t a, size_t b) { return s.map.time[a] < s.map.time[b]; });
    for (size_t k = 0; k < 5; ++k) {
      const size_t m = nodes[k];
      const Eigen::Vector2d lp =
          line_of_root({s.map.x[m % s.map.x.size()], s.map.y[m / s.map.x.size()]});
      const ConvergedCycleTime c = converged_cycle_time(cycle_spec(), configuration, lp[0], lp[1]);
      ASSERT_TRUE(c.solved) << c.message;
      EXPECT_GE(c.duration, s.optimum.converged.duration - s.optimum.duration_error - c.error)
          << "node " << m << ", configuration " << configuration;
    }
    EXPECT_LE(s.optimum.fine_time, s.optimum.grid_time * (1 + 1e-2));
  }
}

TEST(PlacementCycleTime, ConfigurationTwosOptimumIsTheMirrorImageOfConfigurationOnes) {
  // mirrored in the line's perpendicular bisector (X -> L - X), the arm's elbow flips and the
  // line runs backwards; the time-optimal motion reversed in time keeps the same limits
  const CycleTimeOptimum& o1 = cycle_solved(1).optimum;
  const CycleTimeOptimum& o2 = cycle_solved(2).optimum;
  ASSERT_TRUE(o1.found && o2.found);
  const double L = cycle_spec().length;
  EXPECT_LE(std::abs(o1.converged.duration - o2.converged.duration),
            o1.duration_error + o2.duration_error);
  const Eigen::Vector2d mirror(L - o1.root.x(), o1.root.y());
  std::cout << "conf. 1: " << o1.converged.duration << " s, conf. 2: " << o2.converged.duration
            << " s; mirror distance " << (mirror - o2.root).norm() << " m\n";
  EXPECT_LE((mirror - o2.root).norm(), 1e-3)
      << "conf. 1 (" << o1.root.transpose() << "), conf. 2 (" << o2.root.transpose() << ")";
  // the maps, node by node (their X nodes are symmetric about L / 2)
  const CycleTimeMap &m1 = cycle_solved(1).map, &m2 = cycle_solved(2).map;
  const size_t nx = m1.x.size();
  double worst = 0;
  for (size_t m = 0; m < m1.time.size(); ++m) {
    const size_t i = m % nx, j = m / nx, mm = j * nx + (nx - 1 - i);
    ASSERT_EQ(std::isfinite(m1.time[m]), std::isfinite(m2.time[mm])) << m;
    if (std::isfinite(m1.time[m])) worst = std::max(worst, std::abs(m1.time[m] / m2.time[mm] - 1));
  }
  std::cout << "largest relative difference of mirrored map nodes: " << worst << "\n";
  EXPECT_LT(worst, 2e-2);
}

}  // namespace
}  // namespace armstudy::studies::placement
