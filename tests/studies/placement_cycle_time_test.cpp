// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The placement study's cycle-time objective: its times are the time-optimal
// study's on the same line placed at the same root, no admissible map node beats its
// optimum, and configuration 2's optimum is configuration 1's mirror image; the energy of
// the fastest motion is the time-optimal motion's integral of |tau qd| by core's dynamics,
// and the trade-off front holds no placement that another beats in both objectives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "studies/placement/cycle_time_map.hpp"
#include "studies/placement/geometry.hpp"
#include "studies/placement/solve.hpp"
#include "studies/time_optimal/profile.hpp"
#include "studies/time_optimal/solve.hpp"
#include "studies/time_optimal/solvers.hpp"
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

// E = integral of |tau1 qd1| + |tau2 qd2| dt of the exact solver's motion on `grid_points`
// nodes, by the time-optimal study's own state at time (core's generic inverse dynamics) and
// the trapezoid on `steps` equal time steps
double energy_by_core(const Spec& spec, int configuration, double x_s, double phi, int grid_points,
                      int steps) {
  const time_optimal::Spec t = cycle_time_problem(spec, configuration, x_s, phi, grid_points);
  const time_optimal::Problem pb = time_optimal::make_problem(
      t, time_optimal::Limits{t.velocity_limit, t.torque_limit, t.acceleration_limit});
  const time_optimal::SolverOutput o = time_optimal::solve_exact(
      pb, time_optimal::make_nodes(pb.path, grid_points - 1), t.exact.checks_per_interval);
  EXPECT_TRUE(o.solved) << o.message;
  std::vector<double> node_t(1, 0.0);
  for (size_t k = 0; k + 1 < o.profile.s.size(); ++k)
    node_t.push_back(node_t.back() + 2 * (o.profile.s[k + 1] - o.profile.s[k]) /
                                         (o.profile.sd[k] + o.profile.sd[k + 1]));
  double e = 0, prev = 0;
  for (int k = 0; k <= steps; ++k) {
    const time_optimal::TimedState st =
        time_optimal::state_at_time(pb, o.profile, node_t, o.duration * k / steps);
    const double p = std::abs(st.tau[0] * st.qd[0]) + std::abs(st.tau[1] * st.qd[1]);
    if (k) e += 0.5 * (p + prev) * o.duration / steps;
    prev = p;
  }
  return e;
}

TEST(PlacementCycleTime, TheFastestMotionsEnergyIsItsIntegralOfAbsolutePower) {
  const Spec spec = cycle_spec();
  const CycleTimeOptimum& o = cycle_solved(1).optimum;
  ASSERT_TRUE(o.found) << o.reason;
  const FastMotionEnergy f = fastest_motion_energy(spec, 1, o.x_s, o.phi);
  ASSERT_TRUE(f.computed);
  const double by_core = energy_by_core(spec, 1, o.x_s, o.phi, f.grid_points, 200000);
  std::cout << "fastest motion at the optimum: " << f.energy << " J +- " << f.error << " J in "
            << f.duration << " s (" << f.grid_points
            << " points); core's dynamics, trapezoid: " << by_core << " J\n";
  // the same motion: the two integrals differ by the trapezoid's error at the bang-bang
  // switches (and the closed form's rounding)
  EXPECT_TRUE(testing::near_rel(f.energy, by_core, 1e-4)) << f.energy << " " << by_core;
  EXPECT_LT(f.error, 1e-2 * f.energy);
  EXPECT_TRUE(testing::near_rel(f.duration, o.converged.duration, 1e-3));
  // at a random admissible node, configuration 2
  const CycleTimeMap& map = cycle_solved(2).map;
  for (size_t m = map.time.size() / 2; m < map.time.size(); ++m) {
    if (!std::isfinite(map.time[m])) continue;
    const Eigen::Vector2d lp = line_of_root({map.x[m % map.x.size()], map.y[m / map.x.size()]});
    const FastMotionOnGrid g = fastest_motion_on_grid(spec, 2, lp[0], lp[1], 400);
    EXPECT_TRUE(
        testing::near_rel(g.energy, energy_by_core(spec, 2, lp[0], lp[1], 400, 200000), 1e-4));
    break;
  }
}

// the energy objective's spec on a coarse sweep (one program, configuration 1) with the
// cycle-time objective
Spec trade_off_spec() {
  Spec s = cycle_spec();
  s.programs = {core::MotionProgram::kPoly345};
  s.configurations = {1};
  s.nx_s = 20;
  s.phi_step = 3 * core::kDeg;
  s.sensitivity_margins.clear();
  return s;
}

TEST(PlacementCycleTime, TheTradeOffFrontIsNonDominatedFromTheTimeToTheEnergyOptimum) {
  const Spec spec = trade_off_spec();
  const Result r = solve(spec);
  ASSERT_EQ(r.cycle_time.size(), 1u);
  const CycleTime& ct = r.cycle_time.front();
  ASSERT_TRUE(ct.optimum.found);
  ASSERT_EQ(ct.at_energy_optima.size(), 1u);
  const EnergyOptimumCycleTime& e = ct.at_energy_optima.front();
  std::cout << r.message << "\n";
  EXPECT_EQ(r.message.rfind("fastest cycle ", 0), 0u) << r.message;
  ASSERT_TRUE(e.fast_energy.computed && ct.optimum.fast_energy.computed);
  ASSERT_TRUE(e.has_energy_at_time_optimum);
  std::cout << "time optimum " << ct.optimum.converged.duration << " s, fastest motion "
            << ct.optimum.fast_energy.energy << " J, poly345 in T " << e.energy_at_time_optimum
            << " J (" << status_name(e.status_at_time_optimum) << "); energy optimum " << e.energy
            << " J, least cycle " << e.time.duration << " s, fastest motion "
            << e.fast_energy.energy << " J; front of " << e.front.size() << "\n";
  // the energy optimum is the least energy in T, the time optimum the least cycle time
  EXPECT_LE(e.energy, e.energy_at_time_optimum + e.energy_at_time_optimum_error);
  EXPECT_GE(e.time.duration + e.time.error,
            ct.optimum.converged.duration - ct.optimum.duration_error);
  ASSERT_GE(e.front.size(), 2u);
  for (size_t k = 1; k < e.front.size(); ++k) {
    EXPECT_GT(e.front[k].time, e.front[k - 1].time);
    EXPECT_LT(e.front[k].energy, e.front[k - 1].energy);
  }
  // its ends: the energy optimum last (the least energy of the admissible set)
  EXPECT_EQ(e.front.back().kind, "energy_optimum");
  EXPECT_NEAR(e.front.back().energy, e.energy, 1e-4 * e.energy);
  if (e.status_at_time_optimum == CandidateStatus::kFeasible) {
    EXPECT_EQ(e.front.front().kind, "time_optimum");
    EXPECT_TRUE(testing::near_rel(e.front.front().time, ct.optimum.fine_time, 1e-9));
  }
  // no admissible map node re-evaluated beats a point of the front in both objectives
  const Arm2 arm = make_arm2(spec.chain);
  const ProgramTable table =
      make_program_table(core::MotionProgram::kPoly345, spec.duration, spec.length, spec.samples);
  const EnergyMap& em = r.cases.front().map;
  int checked = 0;
  for (size_t m = 0; m < em.status.size(); m += 7) {
    if (em.status[m] != CandidateStatus::kFeasible) continue;
    const Eigen::Vector2d lp =
        line_of_root({ct.map.x[m % ct.map.x.size()], ct.map.y[m / ct.map.x.size()]});
    const Candidate c = evaluate_candidate(spec, arm, table, 1, lp[0], lp[1]);
    const double t = cycle_time_on_grid(spec, 1, lp[0], lp[1], spec.cycle_time->grid_points);
    for (const CycleEnergyPoint& p : e.front)
      EXPECT_FALSE(t < p.time * (1 - 1e-9) && c.metrics.energy < p.energy * (1 - 1e-9))
          << "node " << m << " (" << t << " s, " << c.metrics.energy << " J) beats " << p.kind
          << " (" << p.time << " s, " << p.energy << " J)";
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

}  // namespace
}  // namespace armstudy::studies::placement
