// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The time-optimal study's fast paths keep its answers: solve_exact (no allocation, rows
// without tags, its points without trigonometric functions) gives solve_exact_reference's
// numbers to 1e-12 relative and its failure messages word for word, on tip paths (line, polyline,
// spline, acceleration limits, a rotated base with gravity) and on a 3-link joint-space path; the
// joint points of a tip path equal core's generic chain (forward kinematics, the Jacobian and the
// generic recursion) to 1e-12 relative, and so do the dense re-check's joint rates without angles
// (TipRateEvaluator; its loop over arrays gives the point-by-point numbers bitwise) and its
// closed-form torques; resample gives resample_reference's samples and limit uses bitwise,
// the samples' torques (closed form) to 1e-12 relative.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <tuple>

#include "core/dynamics.hpp"
#include "core/ik2.hpp"
#include "core/kinematics.hpp"
#include "studies/time_optimal/profile.hpp"
#include "studies/time_optimal/solve.hpp"
#include "studies/time_optimal/solvers.hpp"
#include "studies/time_optimal/two_link_dynamics.hpp"
#include "testing/arms.hpp"
#include "testing/three_link.hpp"

namespace armstudy::studies::time_optimal {
namespace {

core::PlanarChain rich_arm(double gravity) {
  core::PlanarChain c;
  c.links = {{0.5, 2.0, 0.2, 0.03, 0.04, true}, {0.4, 1.5, 0.25, -0.02, 0.02, true}};
  c.point_masses = {{1, 0.4, 0.01, 0.7}, {0, 0.3, -0.02, 0.2}};
  c.gravity = gravity;
  c.base_angle = 0.4;
  c.base = Eigen::Vector2d(0.1, 0.2);
  return core::make_chain(c);
}

Problem tip_problem(const core::PlanarChain& chain, PathKind kind, std::vector<Eigen::Vector2d> pts,
                    core::JointVector v, core::JointVector t,
                    std::optional<core::JointVector> acc) {
  PathSpec ps;
  ps.kind = kind;
  ps.points = std::move(pts);
  return Problem{chain, PathGeometry(ps), 1, Limits{v, t, acc}};
}

std::vector<Problem> problems() {
  std::vector<Problem> out;
  out.push_back(tip_problem(default_arm(1.0, 1.0), PathKind::kLine, {{1.6, 0.4}, {0.4, 1.6}},
                            joint_pair(2, 2), joint_pair(10, 10), std::nullopt));
  out.push_back(tip_problem(default_arm(), PathKind::kPolyline,
                            {{0.3, 0.1}, {0.1, 0.6}, {-0.3, 0.5}}, joint_pair(3, 4),
                            joint_pair(10, 4), joint_pair(40, 60)));
  out.push_back(tip_problem(default_arm(), PathKind::kSpline,
                            {{0.5, 0.2}, {0.3, 0.5}, {-0.1, 0.6}, {-0.4, 0.3}}, joint_pair(3, 4),
                            joint_pair(10, 4), std::nullopt));
  out.push_back(tip_problem(rich_arm(9.81), PathKind::kLine, {{0.55, 0.35}, {0.05, 0.8}},
                            joint_pair(3, 4), joint_pair(40, 20), std::nullopt));
  const Spec three = testing::three_link_spec();  // the bundled 3-link case's joint-space spline
  out.push_back(make_problem(
      three, Limits{three.velocity_limit, three.torque_limit, three.acceleration_limit}));
  return out;
}

// the solver's points come without trigonometric functions (PointSource::solver_at): its
// s' agree with the reference solver's (Problem::at's points) to 1e-12 relative
void expect_same_to_rounding(const std::vector<double>& fast, const std::vector<double>& ref) {
  ASSERT_EQ(fast.size(), ref.size());
  for (size_t k = 0; k < ref.size(); ++k)
    ASSERT_NEAR(fast[k], ref[k], 1e-12 * std::max(1.0, std::abs(ref[k]))) << k;
}

TEST(TimeOptimalFastPaths, SolveExactGivesTheReferenceNumbersToRounding) {
  for (const Problem& pb : problems()) {
    for (int intervals : {7, 200}) {
      const std::vector<double> nodes = make_nodes(pb.path, intervals);
      for (int checks : {1, 2, 5}) {
        const SolverOutput fast = solve_exact(pb, nodes, checks);
        const SolverOutput ref = solve_exact_reference(pb, nodes, checks);
        ASSERT_TRUE(ref.solved) << ref.message;
        ASSERT_TRUE(fast.solved) << fast.message;
        EXPECT_NEAR(fast.duration, ref.duration, 1e-12 * ref.duration);
        ASSERT_EQ(fast.profile.sd.size(), ref.profile.sd.size());
        expect_same_to_rounding(fast.profile.sd, ref.profile.sd);
      }
    }
  }
}

void expect_same_samples(const MotionSamples& a, const MotionSamples& b) {
  EXPECT_EQ(a.s, b.s);
  EXPECT_EQ(a.t, b.t);
  EXPECT_EQ(a.sd, b.sd);
  EXPECT_EQ(a.sdd, b.sdd);
  EXPECT_EQ(a.q, b.q);
  EXPECT_EQ(a.qd, b.qd);
  EXPECT_EQ(a.qdd, b.qdd);
  // the kept samples' torques by the closed form (two_link_dynamics.hpp)
  ASSERT_EQ(a.tau.rows(), b.tau.rows());
  ASSERT_EQ(a.tau.cols(), b.tau.cols());
  for (Eigen::Index i = 0; i < b.tau.size(); ++i)
    EXPECT_NEAR(a.tau(i), b.tau(i), 1e-12 * std::max(1.0, std::abs(b.tau(i)))) << i;
}

void expect_same_violation(const Violation& a, const Violation& b) {
  for (int kind = 0; kind < 3; ++kind)
    for (int j = 0; j < core::kMaxLinks; ++j)
      EXPECT_EQ(a.ratio[kind][j], b.ratio[kind][j]) << kind << " " << j;
  EXPECT_EQ(a.worst, b.worst);
  EXPECT_EQ(a.joint, b.joint);
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.s, b.s);
  EXPECT_EQ(a.t, b.t);
  EXPECT_EQ(a.interval, b.interval);
  EXPECT_EQ(a.text, b.text);
}

TEST(TimeOptimalFastPaths, ResampleGivesTheReferenceSamplesAndLimitUsesBitwise) {
  // the exact profile on coarse grids with one check per interval overshoots its limits
  // between the nodes: the dense re-check's worst points are away from the nodes
  int overshot = 0;
  for (const Problem& pb : problems()) {
    for (int intervals : {9, 120}) {
      const SolverOutput o = solve_exact(pb, make_nodes(pb.path, intervals), 1);
      ASSERT_TRUE(o.solved) << o.message;
      for (int per : {1, 16}) {
        MotionSamples fs, rs;
        Violation fv, rv;
        std::vector<double> ft, rt, fw, rw;
        resample(pb, o.profile, per, 50, &fs, &fv, &ft, &fw);
        resample_reference(pb, o.profile, per, 50, &rs, &rv, &rt, &rw);
        expect_same_samples(fs, rs);
        expect_same_violation(fv, rv);
        EXPECT_EQ(ft, rt);
        ASSERT_EQ(fw.size(), rw.size());
        for (size_t k = 0; k < rw.size(); ++k) EXPECT_NEAR(fw[k], rw[k], 1e-12) << k;
        if (rv.worst > kExactTolerance) ++overshot;
      }
    }
  }
  EXPECT_GT(overshot, 4);
}

TEST(TimeOptimalFastPaths, MaximumVelocityCurveIsTheTaggedRowsOne) {
  for (const Problem& pb : problems()) {
    const std::vector<double> nodes = make_nodes(pb.path, 150);
    std::vector<double> all, vel;
    max_velocity_curve(pb, nodes, &all, &vel);
    for (size_t k = 0; k < nodes.size(); ++k) {
      const JointPoint jp = pb.at(nodes[k], k + 1 == nodes.size());
      std::vector<Row> rows;
      append_rows(jp, pb.limits, 0.0, static_cast<int>(k), &rows);
      const XInterval xi = feasible_x(rows);
      ASSERT_EQ(all[k], xi.empty() ? 0.0 : std::sqrt(std::max(0.0, xi.hi))) << k;
      double v = std::numeric_limits<double>::infinity();
      for (int j = 0; j < pb.limits.joints(); ++j)
        if (jp.dq[j] != 0) v = std::min(v, pb.limits.velocity[j] / std::abs(jp.dq[j]));
      ASSERT_EQ(vel[k], v) << k;
    }
    // the same from the points of a solve on the same nodes
    ExactPointCache cache(pb);
    solve_exact(pb, nodes, std::vector<int>(150, 2), &cache);
    std::vector<double> all_c, vel_c;
    max_velocity_curve(pb, nodes, &all_c, &vel_c, &cache);
    // (the solver's points: the same to rounding)
    expect_same_to_rounding(all_c, all);
    ASSERT_EQ(vel_c.size(), vel.size());
    for (size_t k = 0; k < vel.size(); ++k) {
      if (std::isinf(vel[k]))
        EXPECT_EQ(vel_c[k], vel[k]) << k;
      else
        EXPECT_NEAR(vel_c[k], vel[k], 1e-12 * std::max(1.0, vel[k])) << k;
    }
  }
}

TEST(TimeOptimalFastPaths, SolveExactWithMoreChecksInSomeIntervalsIsTheReferences) {
  for (const Problem& pb : problems()) {
    const std::vector<double> nodes = make_nodes(pb.path, 60);
    std::vector<int> checks(60, 2);
    for (int k = 10; k < 20; ++k) checks[k] = 8;
    checks[41] = 4;
    const SolverOutput fast = solve_exact(pb, nodes, checks);
    const SolverOutput ref = solve_exact_reference(pb, nodes, checks);
    ASSERT_TRUE(ref.solved) << ref.message;
    expect_same_to_rounding(fast.profile.sd, ref.profile.sd);
    // more check points only add limits: never faster than with fewer, never slower than with
    // the most everywhere
    EXPECT_GE(fast.duration, solve_exact(pb, nodes, 2).duration);
    EXPECT_LE(fast.duration, solve_exact(pb, nodes, 8).duration);
  }
}

// the grid with every interval halved, as the study's convergence check takes it
std::vector<double> halved(const std::vector<double>& nodes) {
  std::vector<double> fine;
  for (size_t k = 0; k < nodes.size(); ++k) {
    if (k > 0) fine.push_back(0.5 * (nodes[k - 1] + nodes[k]));
    fine.push_back(nodes[k]);
  }
  return fine;
}

TEST(TimeOptimalFastPaths, SolveExactWithThePointsOfEarlierSolvesGivesTheSameNumbers) {
  for (const Problem& pb : problems()) {
    const std::vector<double> nodes = make_nodes(pb.path, 80);
    const std::vector<double> fine = halved(nodes);
    ExactPointCache cache(pb);
    std::vector<int> checks(80, 2);
    const std::vector<double> first = solve_exact(pb, nodes, checks, &cache).profile.sd;
    EXPECT_EQ(first, solve_exact(pb, nodes, checks).profile.sd);
    for (int k = 30; k < 40; ++k) checks[k] = 4;
    EXPECT_EQ(solve_exact(pb, nodes, checks, &cache).profile.sd,
              solve_exact(pb, nodes, checks).profile.sd);
    std::vector<int> fine_checks(160);
    for (int i = 0; i < 160; ++i) fine_checks[i] = checks[i / 2];
    EXPECT_EQ(solve_exact(pb, fine, fine_checks, &cache).profile.sd,
              solve_exact(pb, fine, fine_checks).profile.sd);
    if (!pb.path.joint_space()) {
      // the halved grid's nodes are the grid's nodes and check points: found in the cache
      for (double s : fine) EXPECT_NE(cache.find(s, true), nullptr) << s;
    }
  }
}

// solve_exact's `previous`: a grid with some intervals bisected (as a grading round makes) or
// with more check points in some, solved taking the controllable sets of an earlier solve
// where its intervals are the same, gives the numbers of its solve without it bitwise (0.08 s
// at load 7 on 2 cores)
TEST(TimeOptimalFastPaths, SolveExactWithAnEarlierSolvesSetsGivesTheSameNumbers) {
  for (const Problem& pb : problems()) {
    const std::vector<double> nodes = make_nodes(pb.path, 80);
    const SolverOutput before = solve_exact(pb, nodes, std::vector<int>(80, 2));
    ASSERT_TRUE(before.solved);
    ASSERT_EQ(before.reach_hi.size(), nodes.size());
    std::vector<double> graded;
    for (size_t k = 0; k < nodes.size(); ++k) {
      if (k > 0 && ((k >= 30 && k < 40) || k == 61))
        graded.push_back(0.5 * (nodes[k - 1] + nodes[k]));
      graded.push_back(nodes[k]);
    }
    const std::vector<int> graded_checks(graded.size() - 1, 2);
    std::vector<int> more(80, 2);
    for (int k = 50; k < 55; ++k) more[k] = 4;
    for (const auto& [grid, checks] : {std::pair{graded, graded_checks}, std::pair{nodes, more}}) {
      const SolverOutput plain = solve_exact(pb, grid, checks);
      const SolverOutput taken = solve_exact(pb, grid, checks, nullptr, &before);
      ASSERT_TRUE(plain.solved);
      EXPECT_EQ(taken.profile.sd, plain.profile.sd);
      EXPECT_EQ(taken.reach_lo, plain.reach_lo);
      EXPECT_EQ(taken.reach_hi, plain.reach_hi);
      EXPECT_EQ(taken.duration, plain.duration);
    }
  }
}

TEST(TimeOptimalFastPaths, PrefetchedPointsOfTheHalvedGridGiveItsSolveWithoutNewPoints) {
  // the study's order: the halved grid's own points prefetched into a second cache while the
  // grid is solved, then taken into the solve's cache before the halved grid is solved
  for (const Problem& pb : problems()) {
    const std::vector<double> nodes = make_nodes(pb.path, 80);
    const std::vector<double> fine = halved(nodes);
    const std::vector<int> checks(80, 2), fine_checks(160, 2);
    ExactPointCache cache(pb), prefetched(pb);
    prefetch_points(pb, fine, fine_checks, nodes, checks, &prefetched);
    solve_exact(pb, nodes, checks, &cache);
    cache.absorb(prefetched);
    cache.merge();
    if (!pb.path.joint_space()) {
      // every point of the halved grid's solve (nodes, and check points at a quarter of each
      // interval of the grid) is there before it runs: the grid's solve gave the grid's
      // points, the prefetch the others
      for (size_t i = 0; i + 1 < fine.size(); ++i) {
        EXPECT_NE(cache.find(fine[i] + 0.5 * (fine[i + 1] - fine[i]), false), nullptr) << i;
        EXPECT_NE(cache.find(fine[i + 1], true), nullptr) << i;
      }
    }
    EXPECT_EQ(solve_exact(pb, fine, fine_checks, &cache).profile.sd,
              solve_exact(pb, fine, fine_checks).profile.sd);
    if (!pb.path.joint_space()) {
      ExactPointCache again(pb);
      prefetch_points(pb, nodes, checks, nodes, checks, &again);
      EXPECT_EQ(again.find(nodes[1], true), nullptr);  // (nothing new: nothing evaluated)
    }
  }
}

TEST(TimeOptimalFastPaths, SolveExactFailsWithTheReferenceMessage) {
  // torque too small to hold the arm against gravity, and velocity limits of zero
  std::vector<Problem> bad;
  bad.push_back(tip_problem(rich_arm(9.81), PathKind::kLine, {{0.55, 0.35}, {0.05, 0.8}},
                            joint_pair(3, 4), joint_pair(0.5, 0.5), std::nullopt));
  bad.push_back(tip_problem(default_arm(), PathKind::kLine, {{0.3, 0.1}, {-0.1, 0.8}},
                            joint_pair(0, 4), joint_pair(10, 4), std::nullopt));
  for (const Problem& pb : bad) {
    const std::vector<double> nodes = make_nodes(pb.path, 50);
    const SolverOutput fast = solve_exact(pb, nodes, 2);
    const SolverOutput ref = solve_exact_reference(pb, nodes, 2);
    EXPECT_FALSE(ref.solved);
    EXPECT_FALSE(fast.solved);
    EXPECT_FALSE(ref.message.empty());
    EXPECT_EQ(fast.message, ref.message);
  }
}

TEST(TimeOptimalFastPaths, TipPointsAreCoresInverseKinematicsAndThePathDynamicsBitwise) {
  // TipPointEvaluator takes sin q2 once; core::ik_2link_motion and path_dynamics, which take
  // it again each, give the same numbers, on both elbows and a rotated base with gravity
  int points = 0;
  for (const Problem& pb : problems()) {
    if (pb.path.joint_space()) continue;
    for (int configuration : {1, 2}) {
      const PathGeometry& path = pb.path.tip();
      const TipPointEvaluator eval(pb.chain, path, configuration);
      const TwoLinkDynamics dyn = make_two_link_dynamics(pb.chain);
      const double cb = std::cos(pb.chain.base_angle), sb = std::sin(pb.chain.base_angle);
      Eigen::Matrix2d rt;
      rt << cb, sb, -sb, cb;
      for (int i = 0; i <= 400; ++i) {
        const double s = path.length() * i / 400;
        JointPoint jp;
        const bool ok = eval.at(s, i == 400, &jp);
        const PathPoint pp = path.at(s, i == 400);
        const Eigen::Vector2d p = rt * (pp.p - pb.chain.base);
        const auto st = core::ik_2link_motion(pb.chain.links[0].length, pb.chain.links[1].length, p,
                                              rt * pp.dp, rt * pp.ddp, configuration);
        ASSERT_EQ(ok, st.has_value() && std::abs(st->sin_q2) >= 1e-9) << s;
        if (!ok) continue;
        ++points;
        EXPECT_EQ(jp.q[0], st->q[0]);
        EXPECT_EQ(jp.q[1], st->q[1]);
        EXPECT_EQ(jp.sin_q2, st->sin_q2);
        for (int j = 0; j < 2; ++j) {
          EXPECT_EQ(jp.dq[j], st->qd[j]);
          EXPECT_EQ(jp.ddq[j], st->qdd[j]);
        }
        core::JointVector a, b, c;
        path_dynamics(dyn, jp.q, jp.dq, jp.ddq, &a, &b, &c);
        EXPECT_EQ(jp.a, a);
        EXPECT_EQ(jp.b, b);
        EXPECT_EQ(jp.c, c);
      }
    }
  }
  EXPECT_GT(points, 2000);
}

TEST(TimeOptimalFastPaths, PathSpeedDpGivesTheFullRecursionsAnswerBitwise) {
  // the pruned recursion against core's staged DP with every transition of the bands
  // evaluated: the same duration, node speeds and transition count, on every problem
  // (acceleration limits, gravity, a polyline's stop, a joint-space path) and on grids with
  // few and many levels per node
  for (const Problem& pb : problems()) {
    for (const auto& [segments, levels, checks] :
         std::vector<std::tuple<int, int, int>>{{10, 200, 8}, {20, 400, 4}, {37, 150, 1}}) {
      const SolverOutput fast = solve_dp(pb, segments, levels, checks, DpState::kPathSpeed);
      const SolverOutput ref =
          solve_dp_reference(pb, segments, levels, checks, DpState::kPathSpeed);
      ASSERT_TRUE(ref.solved) << ref.message;
      ASSERT_TRUE(fast.solved) << fast.message;
      EXPECT_EQ(fast.duration, ref.duration);
      EXPECT_EQ(fast.profile.sd, ref.profile.sd);
      EXPECT_EQ(fast.evaluations, ref.evaluations);
      EXPECT_GT(ref.evaluations, 0);
    }
  }
}

TEST(TimeOptimalFastPaths, JointOneDpGivesTheFullRecursionsAnswerBitwise) {
  // the source's joint-1 velocity state: the source's line (joint 1 turns one way) and the
  // problems above (where it turns back both fail with the same message)
  std::vector<Problem> all = problems();
  all.push_back(tip_problem(default_arm(), PathKind::kLine, {{0.3, 0.1}, {-0.1, 0.8}},
                            joint_pair(3, 4), joint_pair(10, 4), std::nullopt));
  int solved = 0;
  for (const Problem& pb : all) {
    for (const auto& [segments, levels, checks] :
         std::vector<std::tuple<int, int, int>>{{10, 200, 8}, {23, 90, 2}}) {
      const SolverOutput fast = solve_dp(pb, segments, levels, checks, DpState::kJoint1Velocity);
      const SolverOutput ref =
          solve_dp_reference(pb, segments, levels, checks, DpState::kJoint1Velocity);
      ASSERT_EQ(fast.solved, ref.solved) << ref.message;
      EXPECT_EQ(fast.message, ref.message);
      EXPECT_EQ(fast.evaluations, ref.evaluations);
      if (!ref.solved) continue;
      ++solved;
      EXPECT_EQ(fast.duration, ref.duration);
      EXPECT_EQ(fast.profile.sd, ref.profile.sd);
      EXPECT_EQ(fast.profile.qd1, ref.profile.qd1);
    }
  }
  EXPECT_GE(solved, 2);
}

TEST(TimeOptimalFastPaths, PathSpeedDpFailsWithTheFullRecursionsMessage) {
  // too few levels to cross a short segment, and a joint that may not move
  std::vector<std::pair<Problem, int>> bad;
  bad.emplace_back(tip_problem(rich_arm(9.81), PathKind::kLine, {{0.55, 0.35}, {0.05, 0.8}},
                               joint_pair(3, 4), joint_pair(0.5, 0.5), std::nullopt),
                   40);
  bad.emplace_back(tip_problem(default_arm(), PathKind::kLine, {{0.3, 0.1}, {-0.1, 0.8}},
                               joint_pair(0, 4), joint_pair(10, 4), std::nullopt),
                   40);
  for (const auto& [pb, levels] : bad) {
    const SolverOutput fast = solve_dp(pb, 10, levels, 4, DpState::kPathSpeed);
    const SolverOutput ref = solve_dp_reference(pb, 10, levels, 4, DpState::kPathSpeed);
    EXPECT_FALSE(ref.solved);
    EXPECT_FALSE(fast.solved);
    EXPECT_FALSE(ref.message.empty());
    EXPECT_EQ(fast.message, ref.message);
    EXPECT_EQ(fast.evaluations, ref.evaluations);
  }
}

TEST(TimeOptimalFastPaths, TipPathJointPointsEqualTheGenericChainTo1e12) {
  // q checked by forward kinematics, q' by the Jacobian, a, b, c by the generic recursion
  for (const Problem& pb : problems()) {
    if (pb.path.joint_space()) continue;
    const PointSource source(pb);
    const std::vector<double> nodes = make_nodes(pb.path, 300);
    for (double s : nodes) {
      JointPoint jp;
      source.at(s, false, &jp);
      const Eigen::Vector2d tip = core::end_effector(pb.chain, jp.q);
      ASSERT_NEAR((tip - pb.path.tip().at(s).p).norm(), 0.0, 1e-12) << s;
      const core::PointJacobian J = core::end_effector_jacobian(pb.chain, jp.q);
      const PathPoint pp = pb.path.tip().at(s);
      ASSERT_TRUE(testing::near_rel_vec(Eigen::Vector2d(J * jp.dq), pp.dp, 1e-12)) << s;
      const core::JointVector zero = core::JointVector::Zero(2);
      const core::JointVector c_ref = core::inverse_dynamics(pb.chain, jp.q, zero, zero);
      ASSERT_TRUE(testing::near_rel_vec(jp.a, core::mass_matrix(pb.chain, jp.q) * jp.dq, 1e-12))
          << s;
      ASSERT_TRUE(testing::near_rel_vec(
          jp.b, core::inverse_dynamics(pb.chain, jp.q, jp.dq, jp.ddq) - c_ref, 1e-12))
          << s;
      ASSERT_TRUE(testing::near_rel_vec(jp.c, c_ref, 1e-12)) << s;
      // the dense re-check's scan: rates without angles, torques from their cosines and sines
      const TipRateEvaluator rates(pb.chain, pb.path.tip(), pb.configuration);
      TipRates r;
      ASSERT_TRUE(rates.at(s, false, &r)) << s;
      ASSERT_TRUE(testing::near_rel_vec(Eigen::Vector2d(r.dq[0], r.dq[1]), jp.dq, 1e-12)) << s;
      ASSERT_TRUE(testing::near_rel_vec(Eigen::Vector2d(r.ddq[0], r.ddq[1]), jp.ddq, 1e-12)) << s;
      const double t1 = pb.chain.base_angle + jp.q[0];
      ASSERT_TRUE(testing::near_rel_vec(
          Eigen::Vector4d(r.c1, r.s1, r.c2, r.s2),
          Eigen::Vector4d(std::cos(t1), std::sin(t1), std::cos(jp.q[1]), std::sin(jp.q[1])), 1e-12))
          << s;
      const double qd[2] = {0.7 * r.dq[0], 0.7 * r.dq[1]};
      const double qdd[2] = {0.3 * r.dq[0] + 0.49 * r.ddq[0], 0.3 * r.dq[1] + 0.49 * r.ddq[1]};
      double tau[2];
      inverse_dynamics_cs(make_two_link_dynamics(pb.chain), r.c1, r.s1, r.c2, r.s2, qd, qdd, tau);
      const core::JointVector tau_ref =
          core::inverse_dynamics(pb.chain, jp.q, jp.dq * 0.7, jp.dq * 0.3 + jp.ddq * 0.49);
      ASSERT_TRUE(testing::near_rel_vec(Eigen::Vector2d(tau[0], tau[1]), tau_ref, 1e-12)) << s;
    }
  }
}

}  // namespace
}  // namespace armstudy::studies::time_optimal

namespace armstudy::studies::time_optimal {
namespace {
TEST(TimeOptimalFastPaths, TipRatesInArraysAreThePointByPointOnesBitwise) {
  // the dense re-check's loop over arrays (TipRateEvaluator::at_points) against at_point, on
  // both elbows, with a point outside the workspace (ok = 0) and one at the straight elbow
  for (int elbow : {1, 2}) {
    for (const Problem& pb : problems()) {
      if (pb.path.joint_space()) continue;
      const TipRateEvaluator rates(pb.chain, pb.path.tip(), elbow);
      std::vector<PathPoint> pts;
      for (int i = 0; i <= 200; ++i) pts.push_back(pb.path.tip().at(pb.path.length() * i / 200));
      PathPoint far = pts.front();
      far.p = pb.chain.base + Eigen::Vector2d(5.0, 0.0);  // unreachable
      pts.push_back(far);
      PathPoint straight = pts.front();
      const double reach = pb.chain.links[0].length + pb.chain.links[1].length;
      straight.p = pb.chain.base + reach * Eigen::Vector2d(std::cos(0.3), std::sin(0.3));  // c2 = 1
      pts.push_back(straight);
      TipRateArrays a;
      a.resize(pts.size());
      for (size_t i = 0; i < pts.size(); ++i) {
        a.px[i] = pts[i].p.x();
        a.py[i] = pts[i].p.y();
        a.vx[i] = pts[i].dp.x();
        a.vy[i] = pts[i].dp.y();
        a.ax[i] = pts[i].ddp.x();
        a.ay[i] = pts[i].ddp.y();
      }
      rates.at_points(pts.size(), &a);
      int good = 0;
      for (size_t i = 0; i < pts.size(); ++i) {
        TipRates r;
        const bool ok = rates.at_point(pts[i], &r);
        ASSERT_EQ(ok, a.ok[i] != 0) << i;
        if (!ok) continue;
        ++good;
        EXPECT_EQ(r.dq[0], a.dq0[i]) << i;
        EXPECT_EQ(r.dq[1], a.dq1[i]) << i;
        EXPECT_EQ(r.ddq[0], a.ddq0[i]) << i;
        EXPECT_EQ(r.ddq[1], a.ddq1[i]) << i;
        EXPECT_EQ(r.c1, a.c1[i]) << i;
        EXPECT_EQ(r.s1, a.s1[i]) << i;
        EXPECT_EQ(r.c2, a.c2[i]) << i;
        EXPECT_EQ(r.s2, a.s2[i]) << i;
      }
      EXPECT_EQ(a.ok[pts.size() - 2],
                0);  // (the straight elbow's w rounds either way: equal above)
      EXPECT_GT(good, 150);
    }
  }
}
}  // namespace
}  // namespace armstudy::studies::time_optimal
