// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Tip path geometry parameterised by arc length s (m): p(s), p'(s) (the unit tangent) and
/// p''(s) (the curvature vector), and the joint path q(s), q'(s), q''(s) of a 2-link arm
/// from core's closed-form inverse kinematics.

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/planar_chain.hpp"
#include "core/types.hpp"
#include "studies/time_optimal/spec.hpp"
#include "studies/time_optimal/two_link_dynamics.hpp"

namespace armstudy::studies::time_optimal {

/// A point of the tip path (world frame, m).
struct PathPoint {
  Eigen::Vector2d p;    ///< m
  Eigen::Vector2d dp;   ///< dp/ds, unit tangent
  Eigen::Vector2d ddp;  ///< d2p/ds2, 1/m (curvature vector; zero on straight pieces)
};

class PathGeometry {
 public:
  /// @throws std::invalid_argument for fewer than 2 points, a line with other than 2, or
  /// two consecutive points closer than 1e-9 m.
  explicit PathGeometry(const PathSpec& spec);
  /// Arc length, m.
  double length() const { return length_; }
  /// The path at arc length s in [0, length]. At a polyline corner, `from_left` picks the
  /// piece that ends there (true) or the one that starts there (false).
  PathPoint at(double s, bool from_left = false) const;
  /// at(s[i], false) for the n points s[0] <= s[1] <= ... (the same numbers): the piece of
  /// each found from the one before instead of by bisection.
  void at_increasing(const double* s, size_t n, PathPoint* out) const;
  /// Arc lengths where the tangent jumps (interior polyline corners): the arm must stop.
  const std::vector<double>& stops() const { return stops_; }
  /// True when at(s, true) and at(s, false) may differ: s is where two pieces meet.
  bool joins_pieces(double s) const;

 private:
  /// at(s) in piece i (s clamped to [0, length]).
  PathPoint at_piece(double s, int i) const;
  PathKind kind_;
  std::vector<Eigen::Vector2d> pts_;
  double length_ = 0;
  std::vector<double> stops_;
  std::vector<double> piece_s_;       // arc length at the start of each piece (+ total)
  std::vector<Eigen::Vector2d> dir_;  // line and polyline: unit direction of each piece
  // spline: knots tau (chord length), second derivatives per point, and an arc-length
  // table per piece (tau, s) for inversion
  std::vector<double> tau_;
  std::vector<Eigen::Vector2d> m_;
  std::vector<std::vector<double>> tab_tau_, tab_s_;
  Eigen::Vector2d spline_d(int piece, double tau, int order) const;
  double spline_arc(int piece, double t0, double t1) const;
};

/// The arm's joint path at one point, with the path-projected dynamics
/// tau = a s'' + b s'^2 + c (N m per joint).
struct JointPoint {
  double s = 0;           ///< m
  Eigen::Vector2d p;      ///< m, tip
  core::JointVector q;    ///< (2) rad, relative joint angles
  core::JointVector dq;   ///< (2) dq/ds, rad/m
  core::JointVector ddq;  ///< (2) d2q/ds2, rad/m^2
  core::JointVector a;    ///< (2) M q', kg m
  core::JointVector b;    ///< (2) M q'' + C(q, q') q', kg
  core::JointVector c;    ///< (2) gravity torque, N m
  double sin_q2 = 0;      ///< 0 at the singular (straight or folded) elbow
};

/// Why a path point cannot be followed: unreachable or singular. Empty if it can.
struct PathTrouble {
  std::string message;  ///< names the point: s, (x, y), and the reason with numbers
};

/// Signed distance (m) of the path point at s from the nearer boundary of the 2-link
/// chain's reachable annulus [|L1 - L2|, L1 + L2] (core::Reach::margin): > 0 inside, < 0
/// outside. @throws std::invalid_argument if the chain does not have 2 links.
double workspace_margin(const core::PlanarChain& chain, const PathGeometry& path, double s);

/// "7.31e-04 m (0.731 mm)": a small length with enough digits to see it.
std::string length_text(double metres);

/// joint_point's evaluation with the chain's constant parts (base rotation, dynamics
/// parameters) computed once, for the solvers' many points: the same numbers as
/// joint_point (the same operations in the same order), no allocation. The chain and the
/// path must outlive it.
class TipPointEvaluator {
 public:
  /// @throws std::invalid_argument if the chain does not have 2 links.
  TipPointEvaluator(const core::PlanarChain& chain, const PathGeometry& path, int configuration);
  /// The joint point at s into `jp`; false (jp unspecified) where joint_point gives nullopt.
  bool at(double s, bool from_left, JointPoint* jp) const;

 private:
  const PathGeometry* path_;
  Eigen::Vector2d base_;
  Eigen::Matrix2d rt_;  // world -> base frame rotation
  double L1_, L2_;
  int configuration_;
  TwoLinkDynamics dyn_;
};

/// The joint rates of a tip path at one point without trigonometric functions, for scans
/// over many points: q' and q'' from the elbow's cosine and sine, c2 = (r^2 - L1^2 - L2^2)
/// / (2 L1 L2) and s2 = +-sqrt(1 - c2^2), and link 1's direction as an algebraic function
/// of the tip; no angles. Equal to joint_point's to rounding (the tests: 1e-12 relative).
struct TipRates {
  double dq[2], ddq[2];  ///< q'(s), q''(s): rad/m, rad/m^2
  double c1, s1;         ///< cos, sin of link 1's absolute angle base_angle + q1
  double c2, s2;         ///< cos q2, sin q2
};

/// Path points (world frame: p, p', p'') and their TipRates in structure-of-arrays form,
/// for TipRateEvaluator::at_points; ok[i] = 0 where at_point gives false.
struct TipRateArrays {
  std::vector<double> px, py, vx, vy, ax, ay;
  std::vector<double> dq0, dq1, ddq0, ddq1, c1, s1, c2, s2;
  std::vector<char> ok;
  void resize(size_t n);
};

class TipRateEvaluator {
 public:
  /// @throws std::invalid_argument if the chain does not have 2 links.
  TipRateEvaluator(const core::PlanarChain& chain, const PathGeometry& path, int configuration);
  /// false where joint_point gives nullopt (unreachable or singular), or on its edge.
  bool at(double s, bool from_left, TipRates* r) const {
    return at_point(path_->at(s, from_left), r);
  }
  /// The same at a point of the path.
  bool at_point(const PathPoint& pp, TipRates* r) const;
  /// at_point at the first n points of `a` (px..ay in; the rates and ok out): the same
  /// operations, so the same numbers, in one loop without branches the compiler vectorises.
  void at_points(size_t n, TipRateArrays* a) const;

 private:
  const PathGeometry* path_;
  Eigen::Vector2d base_;
  Eigen::Matrix2d rt_;
  double cb_, sb_, L1_, L2_, c2_shift_, c2_scale_, inv_l1l2_;
  int configuration_;
};

inline bool TipRateEvaluator::at_point(const PathPoint& pp, TipRates* out) const {
  const Eigen::Vector2d p = rt_ * (pp.p - base_);
  const Eigen::Vector2d v = rt_ * pp.dp, a = rt_ * pp.ddp;
  const double r2 = p.squaredNorm();
  const double c2 = (r2 - c2_shift_) * c2_scale_;
  // inside the annulus with the elbow clearly bent (joint_point's test is |sin q2| >= 1e-9)
  const double w = (1.0 - c2) * (1.0 + c2);
  if (!(w > 1e-16)) return false;
  const double ir2 = 1.0 / r2;  // (independent of the square root: both run at once)
  const double root = std::sqrt(w);
  const double s2 = configuration_ == 1 ? root : -root;
  // p = R(q1) (k1, k2) with |(k1, k2)| = |p|: link 1's direction (base frame)
  const double k1 = L1_ + L2_ * c2, k2 = L2_ * s2;
  const double c1 = (p.x() * k1 + p.y() * k2) * ir2, s1 = (p.y() * k1 - p.x() * k2) * ir2;
  const double c12 = c1 * c2 - s1 * s2, s12 = s1 * c2 + c1 * s2;
  const double idet = inv_l1l2_ / s2;
  const double j11 = -L1_ * s1 - L2_ * s12, j12 = -L2_ * s12;
  const double j21 = L1_ * c1 + L2_ * c12, j22 = L2_ * c12;
  const double qd1 = (j22 * v.x() - j12 * v.y()) * idet, qd2 = (-j21 * v.x() + j11 * v.y()) * idet;
  const double w1 = qd1, w12 = qd1 + qd2;
  const double bx = a.x() + L1_ * c1 * w1 * w1 + L2_ * c12 * w12 * w12;
  const double by = a.y() + L1_ * s1 * w1 * w1 + L2_ * s12 * w12 * w12;
  out->dq[0] = qd1;
  out->dq[1] = qd2;
  out->ddq[0] = (j22 * bx - j12 * by) * idet;
  out->ddq[1] = (-j21 * bx + j11 * by) * idet;
  out->c1 = cb_ * c1 - sb_ * s1;  // base_angle + q1
  out->s1 = sb_ * c1 + cb_ * s1;
  out->c2 = c2;
  out->s2 = s2;
  return true;
}

/// Joint point of a 2-link `chain` at s; nullopt and `trouble` set when the point lies
/// outside the reachable annulus or at a singular pose (|sin q2| < 1e-9).
/// @throws std::invalid_argument if the chain does not have 2 links.
std::optional<JointPoint> joint_point(const core::PlanarChain& chain, const PathGeometry& path,
                                      int configuration, double s, bool from_left,
                                      PathTrouble* trouble);

}  // namespace armstudy::studies::time_optimal
