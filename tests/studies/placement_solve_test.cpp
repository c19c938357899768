// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The placement study's answer: physics invariants, singularity handling, refinement,
// limits, Pareto front and evaluations.
#include "studies/placement/solve.hpp"

#include <gtest/gtest.h>

#include <random>

#include "studies/placement/geometry.hpp"
#include "testing/arms.hpp"

namespace armstudy::studies::placement {
namespace {

using armstudy::testing::kDeg;
using testing::near_rel;

Spec thesis_spec(double fraction) {
  Spec s;
  s.chain = testing::thesis_arm();
  s.length = fraction * annulus(0.4, 0.2).lmax;
  s.map_nx = 60;  // small maps keep the tests fast
  s.map_ny = 30;
  s.nx_s = 30;
  s.phi_step = 2 * kDeg;
  return s;
}

const Result& example3() {
  static const Result r = solve(thesis_spec(0.5));
  return r;
}

TEST(PlacementSolve, SignedWorkOfRestToRestMotionsIsZero) {
  // no gravity, rest to rest: the actuators' signed work is the change of kinetic energy, 0
  const Arm2 arm = make_arm2(testing::thesis_arm());
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> xs(0.2, 0.6), ph(0, core::kPi);
  int tested = 0;
  for (const auto program : {core::MotionProgram::kCycloidal, core::MotionProgram::kPoly345}) {
    const ProgramTable t = make_program_table(program, 1.0, 0.45, 401);
    while (tested < 400) {
      const Line line = thesis_line(xs(rng), ph(rng));
      if (check_line(arm.L1, arm.L2, line, 0.45).boundary_distance < 0.01) continue;
      for (const int config : {1, 2}) {
        const LineMetrics m = evaluate_line(arm, t, line, config);
        EXPECT_LT(std::abs(m.signed_work), 1e-9) << "energy " << m.energy;
        EXPECT_GT(m.energy, 1e-3);
      }
      ++tested;
    }
    tested = 0;
  }
  for (const Check& c : example3().checks) EXPECT_TRUE(c.passed) << c.name << " " << c.value;
}

TEST(PlacementSolve, EnergyConvergesAsSamplesGrow) {
  const Result& r = example3();
  ASSERT_GE(r.convergence.size(), 5u);
  const double e_ref = r.convergence.back().energy;  // 3201 samples
  // the trapezoid on |power| (kinks where a joint's power changes sign) converges like h^2,
  // unevenly as kinks move against the grid: 51 and 101 samples are within 1e-3, the
  // default 401 and more within 2e-5 of 3201 samples
  double coarse = 0, fine = 0;
  for (const ConvergenceRow& row : r.convergence) {
    const double rel = std::abs(row.energy - e_ref) / e_ref;
    if (row.samples <= 101) {
      EXPECT_LT(rel, 1e-3) << row.samples;
      coarse = std::max(coarse, rel);
    }
    if (row.samples >= 401) {
      EXPECT_LT(rel, 2e-5) << row.samples;
      if (row.samples >= 801) fine = std::max(fine, rel);
    }
  }
  EXPECT_LT(fine, coarse);
  EXPECT_LT(std::abs(r.cases[0].refined.metrics.energy - e_ref) / e_ref, 1e-5);
}

TEST(PlacementSolve, TangentTrajectoryIsSingularNeverAnOptimum) {
  Spec s = thesis_spec(0.5);
  const Arm2 arm = make_arm2(s.chain);
  const ProgramTable t = make_program_table(core::MotionProgram::kCycloidal, 1.0, s.length, 401);
  // the thesis's (4.11b) direction: tangent to the inner circle
  const double x_s = 0.5, phi = core::kPi - std::asin(0.2 / x_s);
  for (const int config : {1, 2}) {
    const Candidate c = evaluate_candidate(s, arm, t, config, x_s, phi);
    EXPECT_EQ(c.status, CandidateStatus::kSingular);
    EXPECT_NEAR(c.boundary_distance, 0.0, 1e-12);
    EXPECT_NEAR(c.min_abs_sin, 0.0, 1e-6);
  }
  const Result& r = example3();
  for (const ProgramConfig& pc : r.cases) {
    ASSERT_TRUE(pc.found);
    EXPECT_EQ(pc.refined.status, CandidateStatus::kFeasible);
    EXPECT_GE(pc.refined.boundary_distance, s.singularity_margin);
    EXPECT_GE(pc.grid.boundary_distance, s.singularity_margin);
    // the thesis's own search ends on the tangent and picks a singular line there
    EXPECT_GT(pc.counts.thesis_rejected, 0);
  }
}

TEST(PlacementSolve, LmaxHasNoAdmissiblePlacement) {
  const Result r = solve(thesis_spec(1.0));
  EXPECT_EQ(r.status, Status::kUnsolvable);
  EXPECT_NE(r.message.find("longest line that fits is"), std::string::npos) << r.message;
  for (const ProgramConfig& pc : r.cases) EXPECT_FALSE(pc.found);
  Spec s = thesis_spec(1.0);
  s.length *= 1.01;
  const Result longer = solve(s);
  EXPECT_EQ(longer.status, Status::kUnsolvable);
  EXPECT_NE(longer.message.find("exceeds"), std::string::npos) << longer.message;
}

TEST(PlacementSolve, ConfigurationsAreMirrorImagesOfTheReversedLine) {
  // reversing a time-symmetric rest-to-rest motion keeps |power|; mirroring swaps the
  // configurations: E_1(X, Y) = E_2(L - X, Y) in the line frame
  const Arm2 arm = make_arm2(testing::thesis_arm());
  const double L = 0.5;
  const ProgramTable t = make_program_table(core::MotionProgram::kPoly345, 1.0, L, 401);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-0.2, 0.6);
  int tested = 0;
  while (tested < 50) {
    const Eigen::Vector2d root(u(rng), u(rng) * 0.5 + 0.3);
    const Eigen::Vector2d a = line_of_root(root), b = line_of_root({L - root.x(), root.y()});
    if (check_line(arm.L1, arm.L2, thesis_line(a[0], a[1]), L).boundary_distance < 0.01) continue;
    const LineMetrics m1 = evaluate_line(arm, t, thesis_line(a[0], a[1]), 1);
    const LineMetrics m2 = evaluate_line(arm, t, thesis_line(b[0], b[1]), 2);
    EXPECT_TRUE(near_rel(m1.energy, m2.energy, 1e-9));
    ++tested;
  }
  const Result& r = example3();
  ASSERT_EQ(r.cases.size(), 4u);
  EXPECT_TRUE(near_rel(r.cases[0].refined.metrics.energy, r.cases[1].refined.metrics.energy, 2e-4));
  EXPECT_TRUE(near_rel(r.cases[2].refined.metrics.energy, r.cases[3].refined.metrics.energy, 2e-4));
  // the 3-4-5 polynomial costs less than the cycloidal program (the thesis's finding)
  EXPECT_LT(r.cases[2].refined.metrics.energy, r.cases[0].refined.metrics.energy);
}

TEST(PlacementSolve, RefinedOptimumHasNoBetterAdmissibleNeighbour) {
  const Result& r = example3();
  Spec s = thesis_spec(0.5);
  const Arm2 arm = make_arm2(s.chain);
  for (const ProgramConfig& pc : r.cases) {
    ASSERT_TRUE(pc.found);
    EXPECT_LE(pc.refined.metrics.energy, pc.grid.metrics.energy);
    const ProgramTable t = make_program_table(pc.program, 1.0, s.length, s.samples);
    for (const double dx : {-1e-5, 0.0, 1e-5}) {
      for (const double dp : {-1e-3 * kDeg, 0.0, 1e-3 * kDeg}) {
        const Candidate c = evaluate_candidate(s, arm, t, pc.configuration, pc.refined.x_s + dx,
                                               pc.refined.phi + dp);
        if (c.status != CandidateStatus::kFeasible) continue;
        EXPECT_GE(c.metrics.energy, pc.refined.metrics.energy * (1 - 1e-6))
            << core::program_name(pc.program) << " " << pc.configuration << " " << dx << " " << dp;
      }
    }
  }
}

TEST(PlacementSolve, TorqueLimitsExcludeCandidatesAndThePerJointParetoFrontIsMonotone) {
  const Result& free = example3();
  const ProgramConfig& f = free.cases[2];  // poly345, configuration 1
  Spec s = thesis_spec(0.5);
  s.programs = {core::MotionProgram::kPoly345};
  s.configurations = {1};
  const double limit = 0.8 * f.refined.metrics.peak_torque[1];
  s.torque_limit = std::array<double, 2>{100.0, limit};
  const Result lim = solve(s);
  ASSERT_EQ(lim.cases.size(), 1u);
  const ProgramConfig& l = lim.cases[0];
  ASSERT_TRUE(l.found);
  EXPECT_GT(l.counts.over_limit, 0);
  EXPECT_LE(l.refined.metrics.peak_torque[1], limit);
  EXPECT_GE(l.refined.metrics.energy, f.refined.metrics.energy);
  for (int j = 0; j < 2; ++j) {
    const auto& front = f.pareto[j];
    ASSERT_FALSE(front.empty());
    for (size_t k = 1; k < front.size(); ++k) {
      EXPECT_GE(front[k].peak_torque[j], front[k - 1].peak_torque[j]);
      EXPECT_LT(front[k].energy, front[k - 1].energy);
    }
    // admissible placements only: the front ends at the refined optimum, never below it
    EXPECT_DOUBLE_EQ(front.back().energy, f.refined.metrics.energy);
    for (const ParetoPoint& p : front) EXPECT_FALSE(p.singular);
  }
}

TEST(PlacementSolve, EvaluationReportsTheSavingOfTheOptimum) {
  Spec s = thesis_spec(0.2);
  s.programs = {core::MotionProgram::kCycloidal};
  s.configurations = {2};
  s.evaluations = {{"thesis-config-2", 0.44, 67.19 * kDeg}, {"outside", 0.9, 0.0}};
  const Result r = solve(s);
  ASSERT_EQ(r.status, Status::kSolved);
  ASSERT_EQ(r.evaluations.size(), 2u);
  const Evaluation& e = r.evaluations[0];
  ASSERT_TRUE(e.has_saving);
  EXPECT_EQ(e.candidate.status, CandidateStatus::kFeasible);
  // both printed energies are the quadrature's
  EXPECT_DOUBLE_EQ(e.candidate.metrics.energy, e.candidate.convergence.energy);
  EXPECT_NEAR(e.saving, e.candidate.metrics.energy - r.cases[0].refined.convergence.energy, 1e-12);
  EXPECT_GE(e.saving, 0.0);
  EXPECT_NEAR(e.saving_percent, 100 * e.saving / e.candidate.metrics.energy, 1e-9);
  // the series is sampled where the doubling converged and ends on the sampled energy there
  double sampled = NAN;
  for (const ConvergenceRow& row : e.candidate.convergence.rows)
    if (row.samples == e.candidate.convergence.samples) sampled = row.energy;
  EXPECT_EQ(int(e.series.t.size()), e.candidate.convergence.samples);
  EXPECT_NEAR(e.series.energy.back(), sampled, 1e-9);
  EXPECT_NEAR(e.series.energy.back(), e.candidate.metrics.energy, 1e-4 * sampled);
  EXPECT_EQ(r.evaluations[1].candidate.status, CandidateStatus::kUnreachable);
  EXPECT_FALSE(r.evaluations[1].has_saving);
  // the optimum's series and placement are consistent with its line
  const ProgramConfig& pc = r.cases[0];
  EXPECT_TRUE(testing::near_rel_vec(pc.series.tip.front(), pc.placement.start, 1e-12));
  EXPECT_TRUE(testing::near_rel_vec(pc.series.tip.back(), pc.placement.end, 1e-12));
  EXPECT_NEAR((pc.placement.end - pc.placement.start).norm(), s.length, 1e-12);
}

}  // namespace
}  // namespace armstudy::studies::placement
