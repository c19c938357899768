// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Problem data shared by the solvers (arm, path, limits) and the dense resampling that
/// re-checks every solution between its nodes.

#include <optional>
#include <string>
#include <vector>

#include "studies/time_optimal/joint_path.hpp"
#include "studies/time_optimal/path.hpp"
#include "studies/time_optimal/phase.hpp"
#include "studies/time_optimal/result.hpp"
#include "studies/time_optimal/spec.hpp"

namespace armstudy::studies::time_optimal {

/// The path the solvers see: s in [0, length] with its stops, and q(s), q'(s), q''(s)
/// through Problem::at. Either a tip path of a 2-link arm (PathGeometry, s in m, the joint
/// path by closed-form inverse kinematics) or a path given in joint space
/// (JointPathGeometry, s in rad, any number of joints). Converts implicitly from both.
class SolverPath {
 public:
  SolverPath(PathGeometry tip) : tip_(std::move(tip)) {}             // NOLINT: implicit
  SolverPath(JointPathGeometry joint) : joint_(std::move(joint)) {}  // NOLINT: implicit
  bool joint_space() const { return joint_.has_value(); }
  double length() const { return joint_ ? joint_->length() : tip_->length(); }
  const std::vector<double>& stops() const { return joint_ ? joint_->stops() : tip_->stops(); }
  /// Unit of s: "m" (tip path) or "rad" (joint-space path).
  const char* unit() const { return joint_ ? "rad" : "m"; }
  /// @throws std::logic_error for the other kind of path.
  const PathGeometry& tip() const;
  const JointPathGeometry& joint() const;

 private:
  std::optional<PathGeometry> tip_;
  std::optional<JointPathGeometry> joint_;
};

struct Problem {
  core::PlanarChain chain;
  SolverPath path;
  int configuration = 1;  ///< tip paths only
  Limits limits;

  /// Joint point at s (the caller has checked the path). @throws std::logic_error if the
  /// point is unreachable or singular.
  JointPoint at(double s, bool from_left = false) const;
  /// The tip at s (world frame, m): the tip path itself, or the forward kinematics of a
  /// joint-space path.
  Eigen::Vector2d tip(double s, bool from_left = false) const;
  /// "s = 0.310 m, (x, y) = (0.512, 0.100) m", or for a joint-space path
  /// "s = 0.310 rad, q = (0.100, 1.200, -0.400) rad".
  std::string where(double s, bool from_left = false) const;
};

/// Problem::at for many points: a tip path's joint points through TipPointEvaluator (the
/// same numbers as Problem::at, the chain's constant parts computed once), a joint-space
/// path's through Problem::at. The problem must outlive it.
class PointSource {
 public:
  explicit PointSource(const Problem& problem);
  /// @throws std::logic_error as Problem::at does.
  void at(double s, bool from_left, JointPoint* jp) const;
  /// The numbers the solvers' limits take (s, p, q', q'', a, b, c, sin q2) of the same
  /// point: on a 2-link tip path without trigonometric functions (TipRateEvaluator and
  /// path_dynamics_abs: equal to `at`'s to rounding, 1e-12 relative in the tests), q left
  /// NaN; `at`'s numbers wherever TipRateEvaluator gives none (near the workspace's edge
  /// or a singular pose).
  void solver_at(double s, bool from_left, JointPoint* jp) const;

 private:
  const Problem* problem_;
  std::optional<TipPointEvaluator> tip_;
  std::optional<TipRateEvaluator> rates_;
  TwoLinkDynamics dyn_;
};

/// The problem of `spec`: its path in the spec's space, the spec's chain and `limits`.
/// @throws std::invalid_argument for an invalid path.
Problem make_problem(const Spec& spec, const Limits& limits);

/// Node arc lengths of `intervals` intervals over the path: uniform, except that every
/// stop (polyline corner) is a node, the intervals split over the pieces in proportion to
/// their length. @throws std::invalid_argument if intervals < number of pieces.
std::vector<double> make_nodes(const SolverPath& path, int intervals);

/// True at nodes where the arm must be at rest (both ends and every stop).
std::vector<bool> rest_nodes(const SolverPath& path, const std::vector<double>& nodes);

/// Joint points at the check points theta = m / checks (m = 0..checks) of every interval:
/// out[k][m]; the last point of an interval ending at a stop is taken from the left.
std::vector<std::vector<JointPoint>> interval_points(const Problem& problem,
                                                     const std::vector<double>& nodes, int checks);
/// The same with `checks[k]` check points in interval k (one entry per interval).
std::vector<std::vector<JointPoint>> interval_points(const Problem& problem,
                                                     const std::vector<double>& nodes,
                                                     const std::vector<int>& checks);

/// A solution described at its nodes.
struct Profile {
  SegmentLaw law = SegmentLaw::kPathAcceleration;
  std::vector<double> s;    ///< m, nodes
  std::vector<double> sd;   ///< m/s at the nodes
  std::vector<double> qd1;  ///< rad/s at the nodes (kJoint1Acceleration only)
};

/// Duration of a profile, s (infinite if two consecutive nodes are at rest).
double profile_duration(const Problem& problem, const Profile& profile);

/// The state of a path-acceleration profile (constant s'' per interval) at time t, clamped
/// to [0, duration]: inside interval k, s = s_k + s'_k tau + u tau^2 / 2 with
/// tau = t - t_k; joint velocities, accelerations and torques (core's inverse dynamics).
struct TimedState {
  double t = 0, s = 0, sd = 0, sdd = 0;  ///< s, m, m/s, m/s^2 (rad, rad/s, rad/s^2: joint path)
  core::JointVector q, qd, qdd, tau;     ///< rad, rad/s, rad/s^2, N m
};
/// `node_t` are the profile's node times (resample's). @throws std::invalid_argument for a
/// profile of another law or sizes that differ.
TimedState state_at_time(const Problem& problem, const Profile& profile,
                         const std::vector<double>& node_t, double t);

/// Resamples a profile at `per_interval` points per interval (from its own segment law),
/// with joint velocities, accelerations and torques from core's inverse dynamics, and finds
/// the largest use of each limit. `samples` keeps about `keep` evenly spaced samples; node
/// times go to `node_t`; the largest use of any limit inside each interval, as ratio - 1,
/// to `interval_worst` (one per interval) when given. On a 2-link tip path with constant
/// s'' the closed-form inverse dynamics find the worst points, and core's generic inverse
/// dynamics give the torques at them (the same numbers as core's everywhere, the tests
/// check); the kept samples' torques come from the closed form (1e-12 relative).
void resample(const Problem& problem, const Profile& profile, int per_interval, int keep,
              MotionSamples* samples, Violation* violation, std::vector<double>* node_t,
              std::vector<double>* interval_worst = nullptr);

/// resample's plain implementation, for any path and law: core's inverse dynamics at every
/// point. resample gives its numbers (the tests compare the two bitwise, the kept samples'
/// torques to 1e-12 relative).
void resample_reference(const Problem& problem, const Profile& profile, int per_interval, int keep,
                        MotionSamples* samples, Violation* violation, std::vector<double>* node_t,
                        std::vector<double>* interval_worst = nullptr);

}  // namespace armstudy::studies::time_optimal
