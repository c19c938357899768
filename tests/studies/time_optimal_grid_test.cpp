// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The time-optimal study judging its own answer: the exact solver's grid
// convergence check flags a near-singular path and passes a regular one; DP and Complex
// failures name the segment, the place and the binding limit; a path that leaves the
// workspace is refused at its worst point, with enough digits to see by how much.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <regex>
#include <string>
#include <vector>

#include "studies/time_optimal/path.hpp"
#include "studies/time_optimal/profile.hpp"
#include "studies/time_optimal/solve.hpp"
#include "studies/time_optimal/solvers.hpp"

namespace armstudy::studies::time_optimal {
namespace {

Spec exact_only(Eigen::Vector2d a, Eigen::Vector2d b, int grid_points) {
  Spec spec;
  spec.chain = default_arm();
  spec.path.kind = PathKind::kLine;
  spec.path.points = {a, b};
  spec.exact.grid_points = grid_points;
  spec.dp.states = {};
  spec.dp.convergence_segments = {};
  spec.complex.enabled = false;
  return spec;
}

const Check* find_check(const std::vector<Check>& cs, const std::string& name) {
  for (const Check& c : cs)
    if (c.name == name) return &c;
  return nullptr;
}
// a pointer into a temporary list would dangle (AddressSanitizer found two such uses)
const Check* find_check(std::vector<Check>&& cs, const std::string& name) = delete;

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(TimeOptimalGrid, NearSingularPathFailsTheGridCheckAndSaysWhere) {
  // a line ending 1e-8 m inside the outer boundary (L1 + L2 = 0.9 m): the elbow is nearly
  // straight at the end, where the joint rates per metre of path grow without bound
  // (on its uniform grid: exact.tolerance_rel = 0 keeps it; by default the grid is graded,
  // TimeOptimalGraded.NearSingularLineConvergesOnItsGradedGrid)
  const double angle = 1.0, r = 0.9 - 1e-8;
  Spec spec = exact_only({0.3, 0.1}, {r * std::cos(angle), r * std::sin(angle)}, 1000);
  spec.exact.tolerance_rel = 0;
  const Result res = solve(spec);
  ASSERT_EQ(res.status, Status::kSolved) << res.message;
  const GridConvergence& g = res.grid;
  ASSERT_TRUE(g.computed);
  EXPECT_TRUE(g.refined_solved);
  EXPECT_EQ(g.refined_points, 1999);
  // the refined grid is much faster: the case grid is far from converged
  EXPECT_LT(g.refined_duration, g.duration);
  EXPECT_GT(g.change, 10 * spec.exact.grid_tolerance) << g.text;
  const std::vector<Check> all = checks(res);  // kept: c points into it
  const Check* c = find_check(all, "exact_grid_converged");
  ASSERT_NE(c, nullptr);
  EXPECT_FALSE(c->passed) << c->description;
  // where: the stretch holding the change ends at the path's end, near the singular pose
  EXPECT_NEAR(g.s_hi, res.path_length, 1e-12);
  EXPECT_GT(g.s_lo, 0.5 * res.path_length) << g.text;
  EXPECT_LT(g.min_sin_q2, 0.01) << g.text;
  EXPECT_TRUE(has(g.text, "near a singular pose")) << g.text;
  EXPECT_TRUE(has(g.text, "not converged")) << g.text;
  EXPECT_TRUE(has(res.message, "NOT converged")) << res.message;
  // the advice is what helps: grading the grid, not more uniform points
  EXPECT_TRUE(has(g.text, "exact.tolerance_rel > 0")) << g.text;
  EXPECT_FALSE(has(g.text, "more exact.grid_points")) << g.text;
}

TEST(TimeOptimalGrid, RegularPathPassesTheGridCheck) {
  // the source case's line, well inside the workspace
  const Spec spec = exact_only({0.3, 0.1}, {-0.1, 0.8}, 1000);
  const Result res = solve(spec);
  ASSERT_EQ(res.status, Status::kSolved) << res.message;
  const std::vector<Check> all = checks(res);  // kept: c points into it
  const Check* c = find_check(all, "exact_grid_converged");
  ASSERT_NE(c, nullptr);
  EXPECT_TRUE(c->passed) << c->description;
  // first order: the change halves when the grid doubles (measured 1.05e-4 on 1000 uniform
  // points; over exact.tolerance_rel, but their extrapolation is checked to 5.5e-6 s, so
  // the grid is kept)
  EXPECT_LT(res.grid.change, 3e-4) << res.grid.text;
  EXPECT_GT(res.grid.change, 0.0);
  EXPECT_GT(res.grid.path_min_sin_q2, 0.3);
}

// the headline is the converged duration: extrapolated from 200 grid points it lands within
// its stated error of the 3200-point grid's own extrapolation, closer than the 200-point
// value, and the observed order is the solver's first
TEST(TimeOptimalGrid, TheHeadlineIsTheExtrapolatedDurationWithinItsStatedError) {
  const Result coarse = solve(exact_only({0.3, 0.1}, {-0.1, 0.8}, 200));
  const Result fine = solve(exact_only({0.3, 0.1}, {-0.1, 0.8}, 3200));
  ASSERT_EQ(coarse.status, Status::kSolved) << coarse.message;
  ASSERT_EQ(fine.status, Status::kSolved) << fine.message;
  const GridConvergence& g = coarse.grid;
  ASSERT_TRUE(g.extrapolation_computed);
  ASSERT_TRUE(g.asymptotic) << g.coarse_duration << " " << g.duration << " " << g.refined_duration;
  EXPECT_NEAR(g.order, 1.0, 0.2);
  const double reference = fine.grid.extrapolated;
  EXPECT_LT(std::abs(g.extrapolated - reference), g.extrapolation_error)
      << g.extrapolated << " vs " << reference;
  EXPECT_LT(std::abs(g.extrapolated - reference), 0.1 * std::abs(g.duration - reference));
  EXPECT_TRUE(has(coarse.message, "extrapolated over 4 grids")) << coarse.message;
}

TEST(TimeOptimalGrid, DpFailureNamesTheSegmentThePlaceAndTheLimit) {
  // two velocity levels per node (rest and the maximum velocity curve): leaving rest at the
  // maximum speed in one segment breaks a torque limit
  Spec spec = exact_only({0.3, 0.1}, {-0.1, 0.8}, 200);
  spec.dp.states = {DpState::kPathSpeed, DpState::kJoint1Velocity};
  spec.dp.levels = 2;
  const Result res = solve(spec);
  ASSERT_EQ(res.status, Status::kSolved) << res.message;
  const PathGeometry path(spec.path);
  const std::vector<double> nodes = make_nodes(path, spec.dp.segments);
  const std::regex named(
      R"(segment (\d+) of 10 \(s = ([0-9.]+) to ([0-9.]+) m, \(x, y\) = \(([-0-9.]+), ([-0-9.]+)\) to \(([-0-9.]+), ([-0-9.]+)\) m\) cannot be crossed)");
  const std::regex limit(
      R"(the least breach is the joint [12] (torque|velocity) limit [0-9.]+ (N m|rad/s) at s = ([0-9.]+) m, used to ([0-9.]+) %)");
  for (const SolverResult& r : res.solvers) {
    if (r.name == "exact") continue;
    EXPECT_FALSE(r.solved) << r.name;
    std::smatch m, l;
    ASSERT_TRUE(std::regex_search(r.message, m, named)) << r.name << ": " << r.message;
    // the segment named is one of the DP's, at the place named
    const int k = std::stoi(m[1]);
    ASSERT_GE(k, 1);
    ASSERT_LE(k, 10);
    EXPECT_NEAR(std::stod(m[2]), nodes[k - 1], 6e-4) << r.message;
    EXPECT_NEAR(std::stod(m[3]), nodes[k], 6e-4) << r.message;
    EXPECT_NEAR(std::stod(m[4]), path.at(nodes[k - 1]).p.x(), 6e-4) << r.message;
    EXPECT_NEAR(std::stod(m[7]), path.at(nodes[k]).p.y(), 6e-4) << r.message;
    // the binding limit, inside that segment, broken
    ASSERT_TRUE(std::regex_search(r.message, l, limit)) << r.name << ": " << r.message;
    EXPECT_GE(std::stod(l[3]), nodes[k - 1] - 6e-4) << r.message;
    EXPECT_LE(std::stod(l[3]), nodes[k] + 6e-4) << r.message;
    EXPECT_GT(std::stod(l[4]), 100.0) << r.message;
  }
}

TEST(TimeOptimalGrid, ComplexFailureNamesTheSegmentThePlaceAndTheLimit) {
  // a vertical arm whose shoulder cannot hold the arm up along the middle of the path: no
  // crawl, however slow, meets the joint 1 torque limit there
  core::PlanarChain chain = default_arm();
  chain.gravity = 9.81;
  const Problem pb{chain, PathGeometry(PathSpec{PathKind::kLine, {{0.3, 0.3}, {0.8, 0.1}}}), 1,
                   Limits{joint_pair(3.0, 4.0), joint_pair(5.0, 4.0), std::nullopt}};
  ComplexSettings cs;
  const SolverOutput o = solve_complex(pb, 10, 4, cs);
  ASSERT_FALSE(o.solved);
  EXPECT_TRUE(has(o.message, "no feasible crawl")) << o.message;
  EXPECT_TRUE(has(o.message, "segment ")) << o.message;
  EXPECT_TRUE(has(o.message, "(x, y) = (")) << o.message;
  EXPECT_TRUE(has(o.message, "the joint 1 torque limit 5 N m at s = ")) << o.message;
}

TEST(TimeOptimalGrid, WorkspaceMessageNamesTheWorstPointWithItsExcess) {
  // a spline through points inside the outer circle that bulges out between them
  Spec spec = exact_only({0, 0}, {0, 0}, 200);
  spec.path.kind = PathKind::kSpline;
  spec.path.points.clear();
  // four points 1 mm inside the outer circle (0.9 m), 20 deg apart: the natural spline
  // through them bulges about 1.4 mm out between them
  for (double deg : {0.0, 20.0, 40.0, 60.0})
    spec.path.points.emplace_back(0.899 * std::cos(deg * M_PI / 180),
                                  0.899 * std::sin(deg * M_PI / 180));
  const PathGeometry path(spec.path);
  // independent search of the worst point: dense sampling
  double worst = -1, worst_s = 0;
  const int n = 2000000;
  for (int k = 0; k <= n; ++k) {
    const double s = path.length() * k / n;
    const double e = path.at(s).p.norm() - 0.9;
    if (e > worst) {
      worst = e;
      worst_s = s;
    }
  }
  ASSERT_GT(worst, 1e-4) << "the spline should bulge out";
  const Result res = solve(spec);
  ASSERT_EQ(res.status, Status::kUnsolvable);
  // "... at s = <s> m, (x, y) = (...) m, its worst point: <e> m (<e mm> mm) outside ..."
  const size_t at_s = res.message.find("at s = "), at_e = res.message.find("its worst point: ");
  ASSERT_NE(at_s, std::string::npos) << res.message;
  ASSERT_NE(at_e, std::string::npos) << res.message;
  const double s_named = std::strtod(res.message.c_str() + at_s + 7, nullptr);
  const double e_named = std::strtod(res.message.c_str() + at_e + 17, nullptr);
  EXPECT_NEAR(s_named, worst_s, 2 * path.length() / n + 1e-6) << res.message;
  // three significant digits of the excess, as found independently
  EXPECT_NEAR(e_named, worst, 0.005 * worst) << res.message;
  EXPECT_TRUE(has(res.message, "its worst point")) << res.message;
}

// A coarse grid overshoots a limit between its check points: the dense re-check doubles
// them there and solves again. The halved grid of the convergence check is then solved with
// the doubled check points (the study solves it on a second thread beside the re-check with
// the first ones, and must not keep that answer).
TEST(TimeOptimalGrid, TheHalvedGridIsSolvedWithTheCheckPointsTheReCheckDoubled) {
  Spec spec = exact_only({1.6, 0.4}, {0.4, 1.6}, 21);
  spec.chain = default_arm(1.0, 1.0);  // (the anchor problem's arm)
  spec.exact.checks_per_interval = 1;
  spec.exact.tolerance_rel = 0;  // (the case's 21 points, not a graded grid)
  spec.velocity_limit = Eigen::Vector2d(2.0, 2.0);
  spec.torque_limit = Eigen::Vector2d(10.0, 10.0);
  const Result res = solve(spec);
  ASSERT_EQ(res.status, Status::kSolved) << res.message;
  const SolverResult& exact = res.solvers.front();
  const std::vector<int>& checks = exact.checks_per_interval;
  ASSERT_EQ(checks.size(), 20u);
  int doubled = 0;
  for (int c : checks) doubled += c > 1;
  ASSERT_GT(doubled, 0) << "the re-check should have doubled some check points";
  EXPECT_TRUE(has(exact.method, "where the dense re-check found")) << exact.method;
  // the halved grid, independently: every interval split, both halves with its checks
  const Problem pb = make_problem(spec, res.limits);
  std::vector<double> fine;
  for (size_t k = 0; k < exact.node_s.size(); ++k) {
    if (k > 0) fine.push_back(0.5 * (exact.node_s[k - 1] + exact.node_s[k]));
    fine.push_back(exact.node_s[k]);
  }
  std::vector<int> fine_checks, first_checks(fine.size() - 1, 1);
  for (size_t i = 0; i + 1 < fine.size(); ++i) fine_checks.push_back(checks[i / 2]);
  const SolverOutput refined = solve_exact_reference(pb, fine, fine_checks);
  const SolverOutput stale = solve_exact_reference(pb, fine, first_checks);
  ASSERT_TRUE(refined.solved && stale.solved);
  ASSERT_NE(refined.duration, stale.duration) << "the test needs the two to differ";
  EXPECT_EQ(res.grid.refined_duration, refined.duration);
}

}  // namespace
}  // namespace armstudy::studies::time_optimal
