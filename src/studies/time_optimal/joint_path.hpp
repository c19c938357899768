// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// A path given in joint space, for a chain of any number of joints: q(s) through
/// configurations (waypoints) as a line, a polyline (the arm stops at every corner) or a
/// natural cubic spline, parameterised by s, the chord length in joint space (rad): the
/// knots of waypoints i and i+1 lie |q_i+1 - q_i| apart (Euclidean norm of the joint
/// angles). On a line or polyline piece s is the joint-space arc length; on a spline it
/// is the spline's own parameter (close to the arc length), so q(s), q'(s) and q''(s) are
/// exact polynomials with no arc-length inversion. The solvers need no more than q, q'
/// and q'' along s (TOPP-RA's path interface, Pham & Pham 2018).

#include <optional>
#include <string>
#include <vector>

#include "core/planar_chain.hpp"
#include "core/types.hpp"
#include "studies/time_optimal/path.hpp"
#include "studies/time_optimal/spec.hpp"

namespace armstudy::studies::time_optimal {

/// A joint-space point of the path: q, dq/ds, d2q/ds2 (rad, rad/rad, rad/rad^2).
struct JointPathPoint {
  core::JointVector q, dq, ddq;
};

class JointPathGeometry {
 public:
  /// @throws std::invalid_argument for fewer than 2 waypoints, a line with other than 2,
  /// waypoints of different sizes (or of none, or more than core::kMaxLinks) or two
  /// consecutive waypoints closer than 1e-9 rad.
  explicit JointPathGeometry(const JointPathSpec& spec);
  /// Number of joints.
  int dof() const { return dof_; }
  /// Path parameter range [0, length], rad.
  double length() const { return length_; }
  /// The path at s in [0, length]. At a polyline corner, `from_left` picks the piece that
  /// ends there (true) or the one that starts there (false).
  JointPathPoint at(double s, bool from_left = false) const;
  /// Path parameters where q' jumps (interior polyline corners): the arm must stop there.
  const std::vector<double>& stops() const { return stops_; }
  /// Parameter of waypoint i (its knot), rad.
  double knot(int i) const { return knot_[i]; }
  int waypoints() const { return static_cast<int>(pts_.size()); }

 private:
  PathKind kind_;
  int dof_ = 0;
  std::vector<core::JointVector> pts_;
  std::vector<double> knot_;          // chord-length knots
  std::vector<core::JointVector> m_;  // spline second derivatives at the knots
  std::vector<double> stops_;
  double length_ = 0;
};

/// Where a joint-space path leaves a joint's range (rad, lo <= hi per joint): the first
/// point of a dense sampling (at most 1e-3 of the length apart, refined by bisection to
/// 1e-9 rad of s) outside it. `range` has one [lo, hi] per joint.
struct RangeExcursion {
  int joint = 0;     ///< 0-based
  double s = 0;      ///< rad, first point found outside
  double q = 0;      ///< rad, the joint's angle there
  double worst = 0;  ///< rad, the joint's most extreme angle outside the range
  double lo = 0, hi = 0;
  int piece = 0;     ///< waypoint index at the start of the piece holding s (0-based)
  std::string text;  ///< a sentence naming joint, s, the angle and the range
};
std::optional<RangeExcursion> range_excursion(const JointPathGeometry& path,
                                              const std::vector<Eigen::Vector2d>& range);

/// The joint point of `chain` at s of a joint-space path with the path-projected dynamics
/// tau = a s'' + b s'^2 + c (as joint_point for a tip path); p is the tip (forward
/// kinematics) and sin_q2 is 1 (a joint-space path has no inverse-kinematics singularity).
/// @throws std::invalid_argument if the path's joints differ from the chain's links.
JointPoint joint_space_point(const core::PlanarChain& chain, const JointPathGeometry& path,
                             double s, bool from_left);

}  // namespace armstudy::studies::time_optimal
