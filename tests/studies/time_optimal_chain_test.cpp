// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The time-optimal study on a path given in joint space: the same problem as a tip path
// takes the same time, and a vertical 3-link arm's exact solution meets every limit under
// dense resampling and is never slower than DP or Complex.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "studies/time_optimal/joint_path.hpp"
#include "studies/time_optimal/profile.hpp"
#include "studies/time_optimal/solve.hpp"
#include "testing/three_link.hpp"
#include "testing/time_optimal_solvers.hpp"

namespace armstudy::studies::time_optimal {
namespace {

using armstudy::testing::solver;

TEST(TimeOptimalChain, ATipPathAndTheSameMotionGivenInJointSpaceTakeTheSameTime) {
  // the source's arm and line, once as a tip path (inverse kinematics), once as a spline in
  // joint space through 201 points of that joint path: the same geometric path, so the
  // same fastest traversal (the duration does not depend on how s runs along the path)
  Spec tip;
  tip.chain = default_arm();
  tip.path = PathSpec{PathKind::kLine, {{0.3, 0.1}, {-0.1, 0.8}}};
  tip.exact.grid_points = 1000;
  tip.dp.segments = 10;
  tip.dp.levels = 50;
  tip.dp.convergence_segments = {};
  tip.complex.enabled = false;
  const Result rt = solve(tip);
  ASSERT_EQ(rt.status, Status::kSolved) << rt.message;

  const Problem pb = make_problem(tip, rt.limits);
  Spec joint = tip;
  joint.space = PathSpace::kJoint;
  joint.joint_path.kind = PathKind::kSpline;
  const int n = 200;
  for (int k = 0; k <= n; ++k)
    joint.joint_path.points.push_back(pb.at(rt.path_length * k / n, k == n).q);
  const Result rj = solve(joint);
  ASSERT_EQ(rj.status, Status::kSolved) << rj.message;
  EXPECT_TRUE(rj.joint_space);
  EXPECT_STREQ(rj.s_unit(), "rad");

  const double te = solver(rt, "exact").duration, je = solver(rj, "exact").duration;
  // each exact duration is first order in its grid: its error is about its change when the
  // grid is halved (GridConvergence), so the two agree to the sum of both
  ASSERT_TRUE(rt.grid.computed && rj.grid.computed);
  const double grid_accuracy = rt.grid.change + rj.grid.change;
  EXPECT_LT(grid_accuracy, 1e-3);
  EXPECT_NEAR(je / te - 1, 0.0, 2 * grid_accuracy)
      << "tip path " << te << " s, joint path " << je << " s, grid changes " << rt.grid.change
      << ", " << rj.grid.change;
  // and the joint-space DP sees the same problem too: within its own coarse error
  EXPECT_NEAR(solver(rj, "dp").duration / solver(rt, "dp").duration - 1, 0.0, 0.02);
}

TEST(TimeOptimalChain, ThreeLinkExactSolutionMeetsEveryLimitDenselyAndIsNeverSlower) {
  const Spec spec = testing::three_link_spec();
  ASSERT_EQ(spec.chain.num_links(), 3);
  ASSERT_EQ(spec.space, PathSpace::kJoint);
  const Result r = solve(spec);
  ASSERT_EQ(r.status, Status::kSolved) << r.message;
  for (const Check& c : checks(r))
    EXPECT_TRUE(c.passed) << c.name << ": " << c.value << " > " << c.tolerance;

  const SolverResult& exact = solver(r, "exact");
  for (const char* other : {"dp", "complex"}) {
    const SolverResult& o = solver(r, other);
    ASSERT_TRUE(o.solved) << other << ": " << o.message;
    EXPECT_LE(exact.duration, o.duration * (1 + 1e-12)) << other;
  }

  // dense resampling at 20001 equal time steps, independent of the study's own resampling
  const Problem pb = make_problem(spec, r.limits);
  Profile pr;
  pr.s = exact.node_s;
  pr.sd = exact.node_sd;
  double worst[2][3] = {};  // [velocity, torque][joint] largest |value| / limit
  const int steps = 20000;
  for (int i = 0; i <= steps; ++i) {
    const TimedState st = state_at_time(pb, pr, exact.node_t, exact.duration * i / steps);
    ASSERT_EQ(st.tau.size(), 3);
    for (int j = 0; j < 3; ++j) {
      worst[0][j] = std::max(worst[0][j], std::abs(st.qd[j]) / spec.velocity_limit[j]);
      worst[1][j] = std::max(worst[1][j], std::abs(st.tau[j]) / spec.torque_limit[j]);
    }
  }
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      EXPECT_LE(worst[k][j], 1 + kExactTolerance)
          << (k ? "torque" : "velocity") << " joint " << j + 1;
  // a time-optimal motion uses some limit fully: here joint 1's velocity and joint 2's torque
  EXPECT_GT(worst[0][0], 1 - 1e-3);
  EXPECT_GT(worst[1][1], 1 - 1e-3);
  // the path stays in every joint's range and ends where the case says
  EXPECT_FALSE(range_excursion(pb.path.joint(), spec.joint_path.range).has_value());
  const TimedState end = state_at_time(pb, pr, exact.node_t, exact.duration);
  EXPECT_LT((end.q - spec.joint_path.points.back()).norm(), 1e-12);
  EXPECT_LT(end.qd.norm(), 1e-12);
}

TEST(TimeOptimalChain, JointPathGeometryIsATwiceDifferentiableSplineThroughItsWaypoints) {
  JointPathSpec js;
  js.kind = PathKind::kSpline;
  js.points = {joint_pair(0.0, 0.0), joint_pair(0.5, 0.2), joint_pair(0.7, 0.9),
               joint_pair(1.5, 1.0)};
  const JointPathGeometry g(js);
  for (int i = 0; i < 4; ++i) EXPECT_LT((g.at(g.knot(i)).q - js.points[i]).norm(), 1e-14);
  // q' and q'' agree with central differences of q
  const double h = 1e-5;
  for (double s : {0.1, 0.5, 0.9, 1.4}) {
    const auto p = g.at(s), a = g.at(s - h), b = g.at(s + h);
    EXPECT_LT((p.dq - (b.q - a.q) / (2 * h)).norm(), 1e-8) << s;
    EXPECT_LT((p.ddq - (b.dq - a.dq) / (2 * h)).norm(), 1e-6) << s;
  }
  // natural ends: no curvature at the first and last waypoint
  EXPECT_LT(g.at(0).ddq.norm(), 1e-12);
  EXPECT_LT(g.at(g.length()).ddq.norm(), 1e-12);
  // a polyline stops at its corners
  js.kind = PathKind::kPolyline;
  EXPECT_EQ(JointPathGeometry(js).stops().size(), 2u);
}

}  // namespace
}  // namespace armstudy::studies::time_optimal
