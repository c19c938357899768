// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The time-optimal study's solvers against each other, against an analytic duration and
// against infeasible problems.
#include "studies/time_optimal/solve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "studies/time_optimal/path.hpp"
#include "testing/time_optimal_solvers.hpp"

namespace armstudy::studies::time_optimal {
namespace {

// the default arm on a straight line, with settings small enough for a unit test
Spec line_spec(Eigen::Vector2d a, Eigen::Vector2d b) {
  Spec spec;
  spec.chain = default_arm();
  spec.path.kind = PathKind::kLine;
  spec.path.points = {a, b};
  spec.exact.grid_points = 400;
  spec.dp.segments = 10;
  spec.dp.levels = 100;
  spec.dp.convergence_segments = {};
  spec.complex.max_iterations = 5000;
  return spec;
}

using armstudy::testing::solver;

// distance of the segment a-b from the origin, m
double clearance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double t = std::clamp(-a.dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (a + t * d).norm();
}

TEST(TimeOptimal, ExactIsNeverSlowerThanDpOrComplexAndEverySolverMeetsItsLimits) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> radius(0.3, 0.8), angle(-3.0, 3.0);
  int solved = 0;
  while (solved < 6) {
    const double r1 = radius(rng), a1 = angle(rng), r2 = radius(rng), a2 = angle(rng);
    const Eigen::Vector2d a(r1 * std::cos(a1), r1 * std::sin(a1)),
        b(r2 * std::cos(a2), r2 * std::sin(a2));
    // lines well inside the annulus [0.1, 0.9] m
    if ((b - a).norm() < 0.2 || clearance(a, b) < 0.25) continue;
    const Result r = solve(line_spec(a, b));
    ASSERT_EQ(r.status, Status::kSolved) << r.message;
    ++solved;
    const double exact = solver(r, "exact").duration;
    for (const char* name : {"dp", "complex"}) {
      const SolverResult& s = solver(r, name);
      ASSERT_TRUE(s.solved) << name << ": " << s.message;
      EXPECT_LE(exact, s.duration * (1 + 1e-9)) << name;
      EXPECT_LE(s.violation.worst, kCoarseViolationTolerance) << name << ": " << s.violation.text;
    }
    EXPECT_LE(solver(r, "exact").violation.worst, kExactTolerance)
        << solver(r, "exact").violation.text;
    for (const Check& c : checks(r)) EXPECT_TRUE(c.passed) << c.name << " " << c.value;
  }
}

TEST(TimeOptimal, VelocityLimitedDurationConvergesToTheIntegralOfTheSlowestJointsPace) {
  // torques so large that the ends' accelerations take no time: T = int ds / s'_max(s)
  // with s'_max = min_j qd_max_j / |dq_j/ds|. On a grid the first and last intervals start
  // and end at rest (O(1/N) extra time), so the exact duration converges to T from above.
  Spec spec = line_spec({0.3, 0.1}, {-0.1, 0.8});
  spec.torque_limit = joint_pair(1e7, 1e7);
  spec.complex.enabled = false;
  spec.dp.states = {};
  // the uniform grids of 1000 and 4000 points (a graded grid could refine the first one
  // at the rest-to-rest ends, where the change arises)
  spec.exact.tolerance_rel = 0;
  const PathGeometry path(spec.path);
  const int n = 20000;
  double t = 0, prev = 0;
  for (int k = 0; k <= n; ++k) {
    const double s = path.length() * k / n;
    PathTrouble trouble;
    const auto jp = joint_point(spec.chain, path, spec.configuration, s, false, &trouble);
    ASSERT_TRUE(jp) << trouble.message;
    double pace = 0;  // s per m
    for (int j = 0; j < 2; ++j) pace = std::max(pace, std::abs(jp->dq[j]) / spec.velocity_limit[j]);
    if (k > 0) t += 0.5 * (pace + prev) * path.length() / n;
    prev = pace;
  }
  double excess[2];
  const int grids[2] = {1000, 4000};
  for (int g = 0; g < 2; ++g) {
    spec.exact.grid_points = grids[g];
    const Result r = solve(spec);
    ASSERT_EQ(r.status, Status::kSolved) << r.message;
    excess[g] = solver(r, "exact").duration / t - 1;
    EXPECT_GT(excess[g], -1e-6) << grids[g];
  }
  EXPECT_LT(excess[1], 0.5 * excess[0]);
  EXPECT_LT(excess[1], 1e-3);
}

TEST(TimeOptimal, WithTorqueBindingTheExactProfileUsesTheTorqueLimitFully) {
  Spec spec = line_spec({0.3, 0.1}, {-0.1, 0.8});
  spec.velocity_limit = joint_pair(100, 100);  // only the torques limit the motion
  spec.complex.enabled = false;
  const Result r = solve(spec);
  ASSERT_EQ(r.status, Status::kSolved) << r.message;
  const Violation& v = solver(r, "exact").violation;
  const double torque_use = std::max(v.ratio[1][0], v.ratio[1][1]);
  EXPECT_GT(torque_use, 0.999);
  EXPECT_LE(torque_use, 1 + kExactTolerance);
  // bang-bang: every sample has some joint at its torque limit (accelerating or braking),
  // except where the profile switches
  const MotionSamples& m = solver(r, "exact").samples;
  int at_limit = 0;
  for (int k = 0; k < m.tau.cols(); ++k) {
    double use = 0;
    for (int j = 0; j < 2; ++j) use = std::max(use, std::abs(m.tau(j, k)) / spec.torque_limit[j]);
    at_limit += use > 0.99;
  }
  EXPECT_GT(at_limit, 0.9 * m.tau.cols());
}

TEST(TimeOptimal, DpApproachesTheExactDurationAsSegmentsAndLevelsGrow) {
  Spec spec = line_spec({0.3, 0.1}, {-0.1, 0.8});
  spec.complex.enabled = false;
  spec.dp.levels = 60;
  spec.dp.convergence_segments = {10, 20, 40, 200};
  const Result r = solve(spec);
  ASSERT_EQ(r.status, Status::kSolved) << r.message;
  ASSERT_EQ(r.convergence.size(), 4u);
  for (const auto& row : r.convergence) {
    ASSERT_TRUE(row.solved) << row.segments;
    EXPECT_GE(row.excess, -1e-9) << row.segments;
    EXPECT_LE(row.worst_violation, kCoarseViolationTolerance) << row.segments;
  }
  EXPECT_EQ(r.convergence[2].levels, 240);
  EXPECT_LT(r.convergence[1].excess, r.convergence[0].excess);
  EXPECT_LT(r.convergence[2].excess, r.convergence[1].excess);
  EXPECT_LT(r.convergence[2].excess, 0.5 * r.convergence[0].excess);
  // N = 200 (1200 levels): within 0.5 % of the exact time
  EXPECT_EQ(r.convergence[3].levels, 1200);
  EXPECT_LT(r.convergence[3].excess, r.convergence[2].excess);
  EXPECT_LT(r.convergence[3].excess, 0.005);
}

TEST(TimeOptimal, JointOneVelocityStateFailsWhereJointOneTurnsBackAndSaysWhere) {
  Spec spec = line_spec({0.7, -0.2}, {0.2, 0.6});
  spec.dp.states = {DpState::kPathSpeed, DpState::kJoint1Velocity};
  spec.complex.enabled = false;
  const Result r = solve(spec);
  ASSERT_EQ(r.status, Status::kSolved) << r.message;
  EXPECT_TRUE(solver(r, "dp").solved);
  const SolverResult& j1 = solver(r, "dp_joint1");
  EXPECT_FALSE(j1.solved);
  EXPECT_NE(j1.message.find("joint 1 reverses"), std::string::npos) << j1.message;
  EXPECT_NE(j1.message.find("s = "), std::string::npos) << j1.message;
}

TEST(TimeOptimal, InfeasibleProblemsNameTheLimitOrReasonAndThePlace) {
  {
    Spec spec = line_spec({0.3, 0.1}, {-0.1, 0.8});
    spec.velocity_limit = joint_pair(3.0, 0.0);  // joint 2 must move but may not
    const Result r = solve(spec);
    EXPECT_EQ(r.status, Status::kUnsolvable);
    EXPECT_NE(r.message.find("joint 2 velocity limit"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("s = "), std::string::npos) << r.message;
  }
  {
    Spec spec = line_spec({0.3, 0.1}, {-0.1, 0.8});
    spec.acceleration_limit = Eigen::Vector2d(0.0, 5.0);
    const Result r = solve(spec);
    EXPECT_EQ(r.status, Status::kUnsolvable);
    EXPECT_NE(r.message.find("joint 1 acceleration limit"), std::string::npos) << r.message;
  }
  for (const auto& [a, b] :
       {std::pair<Eigen::Vector2d, Eigen::Vector2d>{{0.5, 0.0}, {1.0, 0.2}},  // beyond reach
        std::pair<Eigen::Vector2d, Eigen::Vector2d>{{0.3, 0.02},
                                                    {-0.3, 0.02}}}) {  // past the centre
    const Result r = solve(line_spec(a, b));
    EXPECT_EQ(r.status, Status::kUnsolvable);
    EXPECT_NE(r.message.find("leaves the workspace at s = "), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("annulus [0.10, 0.90] m"), std::string::npos) << r.message;
  }
  {
    // equal links: the annulus closes to a disc and the line runs through the singular base
    Spec spec = line_spec({0.4, 0.0}, {-0.4, 0.0});
    spec.chain = default_arm(0.45, 0.45);
    const Result r = solve(spec);
    EXPECT_EQ(r.status, Status::kUnsolvable);
    EXPECT_NE(r.message.find("s = 0.400 m"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("singular pose"), std::string::npos) << r.message;
  }
}

TEST(TimeOptimal, SmallSettingsStillSolveWithoutTouchingFreedResults) {
  // the smallest grids the case loader accepts (this once read a dangling reference)
  Spec spec = line_spec({0.3, 0.1}, {-0.1, 0.8});
  spec.exact.grid_points = 3;
  spec.dp.segments = 2;
  spec.dp.levels = 2;
  spec.dp.convergence_segments = {2, 3};
  spec.motion_steps = 1;
  const Result r = solve(spec);
  ASSERT_EQ(r.status, Status::kSolved) << r.message;
  EXPECT_GT(solver(r, "exact").duration, 0);
  EXPECT_EQ(r.motion_t.size(), 2u);
  EXPECT_NEAR(r.motion_t.back(), solver(r, "exact").duration, 1e-12);
}

}  // namespace
}  // namespace armstudy::studies::time_optimal
