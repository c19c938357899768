// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The exact time-optimal solver on its graded grid: where the case's uniform grid does not
// converge to exact.tolerance_rel (near a singular pose the maximum velocity curve falls to
// zero over a stretch far shorter than an interval, and a uniform grid converges only like
// N^-1/2), the grid is refined where the halving change arises. The headline durations
// against references computed independently of armstudy (TOPP-RA) or on far finer grids.
// Measured: 20-115 ms each, 0.24 s for the five (load 6-11 on 2 cores).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include <yaml-cpp/yaml.h>

#include "cases/time_optimal_case.hpp"
#include "cases/yaml_reader.hpp"
#include "studies/time_optimal/solve.hpp"

namespace armstudy::studies::time_optimal {
namespace {

// the exact solver alone (no DP, Complex or DP table): what the headline needs
void exact_alone(Spec* spec) {
  spec->dp.states = {};
  spec->dp.convergence_segments = {};
  spec->complex.enabled = false;
}

Spec bundled_case(const std::string& file) {
  const std::string path = std::string(ARMSTUDY_SOURCE_DIR) + "/reports/cases/" + file;
  cases::Diagnostics d(path);
  const YAML::Node n = YAML::LoadFile(path);
  cases::Map root(n, d, "");
  Spec spec = cases::load_time_optimal(root);
  for (const auto& e : d.errors()) ADD_FAILURE() << e.format();
  exact_alone(&spec);
  return spec;
}

// the source's arm (L1 + L2 = 0.9 m) and limits, the source's start point, and a straight
// line ending 1e-8 m inside the outer circle: the elbow is almost stretched at the end (the
// line of TimeOptimalGrid.NearSingularPathFailsTheGridCheckAndSaysWhere)
Spec near_singular_line() {
  Spec spec;
  spec.chain = default_arm();
  spec.path.kind = PathKind::kLine;
  const double angle = 1.0, r = 0.9 - 1e-8;
  spec.path.points = {{0.3, 0.1}, {r * std::cos(angle), r * std::sin(angle)}};
  exact_alone(&spec);
  return spec;
}

TEST(TimeOptimalGraded, ThreeLinkSplineCaseWithin1e5SecondsOfToppra) {
  // TOPP-RA's extrapolation on the bundled 3-link joint-space spline (the independent
  // audit's figure, computed outside armstudy)
  constexpr double kToppraReference = 0.67523828;  // s
  const Result res = solve(bundled_case("time-optimal-3link.yaml"));
  ASSERT_EQ(res.status, Status::kSolved) << res.message;
  ASSERT_TRUE(res.grid.extrapolation_computed);
  EXPECT_NEAR(res.grid.extrapolated, kToppraReference, 1e-5) << res.grid.text;
  // and its stated error covers the difference
  EXPECT_LE(std::abs(res.grid.extrapolated - kToppraReference), res.grid.extrapolation_error);
}

TEST(TimeOptimalGraded, TwoLinkAnchorWithin1e5SecondsOfItsConvergedDuration) {
  // the anchor problem of tests/bench/time_optimal_anchor_bench.cpp and scripts/bench_toppra.sh:
  // 1 m links with 1 kg at the end of each, the tip on (1.6, 0.4) -> (0.4, 1.6) m,
  // |tau| <= 10 N m, |qd| <= 2 rad/s, elbow q2 > 0. TOPP-RA prints 1.180762 s at 1000
  // intervals; converged (the independent audit's figure) 1.180311 s.
  constexpr double kConvergedReference = 1.180311;  // s
  Spec spec;
  spec.chain = default_arm(1.0, 1.0);
  spec.path.kind = PathKind::kLine;
  spec.path.points = {{1.6, 0.4}, {0.4, 1.6}};
  spec.configuration = 1;
  spec.velocity_limit = joint_pair(2.0, 2.0);
  spec.torque_limit = joint_pair(10.0, 10.0);
  exact_alone(&spec);
  const Result res = solve(spec);
  ASSERT_EQ(res.status, Status::kSolved) << res.message;
  ASSERT_TRUE(res.grid.extrapolation_computed);
  EXPECT_NEAR(res.grid.extrapolated, kConvergedReference, 1e-5) << res.grid.text;
  // its 1000 uniform points change by 1.9e-4 when halved, over exact.tolerance_rel, but
  // their extrapolation's estimated error is within it: no grading, and the stated error
  // covers the difference from the reference
  EXPECT_FALSE(res.grid.graded) << res.grid.text;
  EXPECT_LE(res.grid.extrapolation_error, spec.exact.tolerance_rel * res.grid.extrapolated);
  EXPECT_GT(res.grid.change, spec.exact.tolerance_rel);
  EXPECT_LE(std::abs(res.grid.extrapolated - kConvergedReference), res.grid.extrapolation_error);
}

TEST(TimeOptimalGraded, EachBundledCasesStatedErrorCoversAnEightTimesFinerGrid) {
  // the headline (extrapolated, its error from the extrapolations one and two grids down)
  // against the same case on 8000 uniform points, whose own extrapolation is far closer to
  // the limit: the stated error covers the distance and is within exact.tolerance_rel
  for (const char* file : {"time-optimal-source.yaml", "time-optimal-spline.yaml",
                           "time-optimal-3link.yaml", "time-optimal-nonmonotonic.yaml"}) {
    SCOPED_TRACE(file);
    const Spec spec = bundled_case(file);
    const Result res = solve(spec);
    ASSERT_EQ(res.status, Status::kSolved) << res.message;
    const GridConvergence& g = res.grid;
    ASSERT_TRUE(g.extrapolation_computed) << g.text;
    Spec fine_spec = spec;
    fine_spec.exact.grid_points = 8000;
    fine_spec.exact.tolerance_rel = 0;  // (its uniform grid)
    const Result fine = solve(fine_spec);
    ASSERT_EQ(fine.status, Status::kSolved) << fine.message;
    ASSERT_TRUE(fine.grid.extrapolation_computed) << fine.grid.text;
    EXPECT_LE(std::abs(g.extrapolated - fine.grid.extrapolated), g.extrapolation_error)
        << g.extrapolated << " s against " << fine.grid.extrapolated << " s";
    EXPECT_LE(g.extrapolation_error, spec.exact.tolerance_rel * g.extrapolated);
  }
}

TEST(TimeOptimalGraded, TheStatedErrorCoversTheDurationOnLinesNeverSeenBefore) {
  // 36 random lines of the source's arm (ends in the annulus 0.25-0.85 m, velocity limits
  // 1-5 rad/s, torque limits 2-22 and 1-11 N m), default settings: the headline within its
  // stated error of the same line on 16,000 uniform points (extrapolated; its own error is
  // about 16x smaller). On such lines the durations' changes scatter around first order;
  // the error estimate before this test (the observed-order extrapolation's correction)
  // understated lines 25 and 32 here 2.4 and 7.6 times, and 15 of 263 such lines.
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0, 1);
  int compared = 0;
  for (int trial = 0; trial < 36; ++trial) {
    Spec spec;
    spec.chain = default_arm();
    spec.path.kind = PathKind::kLine;
    const auto point = [&] {
      const double r = 0.25 + 0.6 * u(rng), a = 2 * M_PI * u(rng);
      return Eigen::Vector2d(r * std::cos(a), r * std::sin(a));
    };
    const Eigen::Vector2d a = point(), b = point();
    spec.path.points = {{a.x(), a.y()}, {b.x(), b.y()}};
    spec.velocity_limit = joint_pair(1 + 4 * u(rng), 1 + 4 * u(rng));
    spec.torque_limit = joint_pair(2 + 20 * u(rng), 1 + 10 * u(rng));
    exact_alone(&spec);
    SCOPED_TRACE("line " + std::to_string(trial));
    const Result res = solve(spec);
    if (res.status != Status::kSolved) continue;  // (a line through the inner circle)
    Spec fine_spec = spec;
    fine_spec.exact.grid_points = 16000;
    fine_spec.exact.tolerance_rel = 0;
    const Result fine = solve(fine_spec);
    ASSERT_EQ(fine.status, Status::kSolved) << fine.message;
    ASSERT_TRUE(res.grid.extrapolation_computed && fine.grid.extrapolation_computed);
    EXPECT_LE(std::abs(res.grid.extrapolated - fine.grid.extrapolated),
              res.grid.extrapolation_error)
        << res.grid.extrapolated << " s against " << fine.grid.extrapolated << " s; "
        << res.grid.text;
    ++compared;
  }
  EXPECT_GE(compared, 24);
}

TEST(TimeOptimalGraded, NearSingularLineConvergesOnItsGradedGrid) {
  // armstudy's own reference for this line (not the audit's: its line is not in the
  // repository, and this one gives 1.2019 s on 1000 uniform points where the audit's gave
  // 2.136 s): the graded grid driven to exact.tolerance_rel = 1e-7, 2,731,300 points, 41 s
  // of CPU, extrapolated 0.7472406047 s +- 5.7e-8 s (1e-6: 246,502 points, 0.7472406109 s).
  // On uniform grids: 1.2019 s at 1000 points, 0.8299 s at 32,000.
  constexpr double kReference = 0.74724060;  // s
  const Spec spec = near_singular_line();
  const Result res = solve(spec);
  ASSERT_EQ(res.status, Status::kSolved) << res.message;
  const GridConvergence& g = res.grid;
  // the uniform grid was far off; the graded one converged within exact.tolerance_rel,
  // without reaching the node cap
  EXPECT_TRUE(g.graded) << g.text;
  EXPECT_EQ(g.uniform_points, spec.exact.grid_points);
  EXPECT_GT(g.uniform_change, 0.01) << g.text;
  EXPECT_FALSE(g.capped) << g.text;
  EXPECT_LE(g.change, spec.exact.tolerance_rel) << g.text;
  EXPECT_LT(g.grid_points, spec.exact.max_grid_points);
  // the check passes and the message no longer says NOT converged
  EXPECT_EQ(res.message.find("NOT converged"), std::string::npos) << res.message;
  // the headline within 1e-4 relative of the reference
  ASSERT_TRUE(g.extrapolation_computed);
  EXPECT_NEAR(g.extrapolated / kReference, 1.0, 1e-4) << g.extrapolated << " s; " << g.text;
}

TEST(TimeOptimalGraded, NodeCapStopsTheGradingAndSaysSo) {
  Spec spec = near_singular_line();
  spec.exact.max_grid_points = 1200;
  const Result res = solve(spec);
  ASSERT_EQ(res.status, Status::kSolved) << res.message;
  const GridConvergence& g = res.grid;
  EXPECT_TRUE(g.graded);
  EXPECT_TRUE(g.capped) << g.text;
  EXPECT_LE(g.grid_points, 1200);
  EXPECT_GT(g.change, spec.exact.tolerance_rel) << g.text;
  EXPECT_NE(g.text.find("exact.max_grid_points"), std::string::npos) << g.text;
}

TEST(TimeOptimalGraded, AConvergedUniformGridIsKept) {
  // the source's line, well inside the workspace: 1000 points change by ~1e-4; with a
  // looser target nothing is graded
  Spec spec = near_singular_line();
  spec.path.points = {{0.3, 0.1}, {-0.1, 0.8}};
  spec.exact.tolerance_rel = 1e-3;
  const Result res = solve(spec);
  ASSERT_EQ(res.status, Status::kSolved) << res.message;
  EXPECT_FALSE(res.grid.graded);
  EXPECT_EQ(res.grid.grid_points, spec.exact.grid_points);
}

}  // namespace
}  // namespace armstudy::studies::time_optimal
