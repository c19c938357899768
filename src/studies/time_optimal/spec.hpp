// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The time-optimal study (Ozkipcak 1994): the fastest rest-to-rest motion along a given
/// path under joint velocity, torque and (optional) acceleration limits: the tip path of a
/// 2-link arm, or a path in joint space for a chain of 2 to core::kMaxLinks active joints.
/// SI units and radians throughout.

#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "core/planar_chain.hpp"
#include "core/types.hpp"
#include "studies/arm_origin.hpp"

namespace armstudy::studies::time_optimal {

/// Shape of the tip path.
enum class PathKind {
  kLine,      ///< straight line between two points
  kPolyline,  ///< straight pieces through the points; the arm stops at every corner
  kSpline,    ///< natural cubic spline through the points (chord-length knots)
};

struct PathSpec {
  PathKind kind = PathKind::kLine;
  std::vector<Eigen::Vector2d> points;  ///< m, world frame; >= 2 (line: exactly 2)
};

/// Where the path is given.
enum class PathSpace {
  kTip,    ///< a tip path (PathSpec) of a 2-link arm, joint path by inverse kinematics
  kJoint,  ///< a path in joint space (JointPathSpec), any number of joints
};

/// A path through joint configurations (joint_path.hpp: s is the joint-space chord length).
struct JointPathSpec {
  PathKind kind = PathKind::kLine;
  std::vector<core::JointVector> points;  ///< rad, one angle per joint; >= 2 (line: exactly 2)
  /// Optional range [lo, hi] (rad) per joint that the whole path must stay in (empty: none).
  std::vector<Eigen::Vector2d> range;
};

/// Which state the dynamic programme uses at its nodes.
enum class DpState {
  kPathSpeed,       ///< s' (m/s): works on any path (default)
  kJoint1Velocity,  ///< q1' (rad/s), the source's choice: needs q1 monotonic along the path
};

struct DpSettings {
  int segments = 10;           ///< N, the source's default
  int levels = 200;            ///< velocity levels per interior node
  int checks_per_segment = 8;  ///< points per segment where limits are checked (>= 1)
  std::vector<DpState> states{DpState::kPathSpeed};  ///< one DP run per entry
  /// N of the convergence table (path-speed state, levels x N / segments levels, at least
  /// `levels`); empty: no table
  std::vector<int> convergence_segments{10, 20, 50, 100, 200};
};

struct ComplexSettings {
  bool enabled = true;
  int max_iterations = 20000;
  double tolerance = 1e-10;  ///< relative spread of the complex's times at convergence
  unsigned seed = 1;
};

struct ExactSettings {
  int grid_points = 1000;       ///< nodes of the fine grid (>= 2)
  int checks_per_interval = 2;  ///< sub-intervals per grid interval where limits hold
  /// Grid convergence: the exact solver runs again on the grid with every interval halved;
  /// the relative change of the duration must stay within this (check
  /// exact_grid_converged, which fails the case otherwise). The discretisation error is
  /// first order in the interval, so the change estimates the refined duration's own error
  /// (and half the case grid's). Regular paths change by ~1e-4 at 1000 points.
  double grid_tolerance = 1e-3;
  /// The headline (converged) duration's relative error. On the case's uniform grid it is
  /// met when the extrapolation's error estimate (GridConvergence) is within this (without
  /// a coarser grid: when the duration changes by no more than this with every interval
  /// halved). Otherwise the solver grades the grid where the change arises (near a singular
  /// pose the maximum velocity curve falls to zero over a stretch far shorter than an
  /// interval, and a uniform grid converges like N^-1/2): it bisects the intervals that hold half
  /// of the summed change, again and again, until the change is within this; 0: the uniform grid is
  /// kept.
  double tolerance_rel = 1e-4;
  /// most nodes of the graded grid; the refinement stops there and says so
  int max_grid_points = 200000;
};

/// The whole problem, validated by the case loader (the solver re-checks its invariants).
/// A per-joint value of a 2-link arm, e.g. the default limits.
inline core::JointVector joint_pair(double a, double b) {
  return (core::JointVector(2) << a, b).finished();
}

struct Spec {
  core::PlanarChain chain;  ///< 2 links (tip path) or 2 to kMaxLinks (joint path), all active
  PathSpace space = PathSpace::kTip;
  PathSpec path;             ///< space kTip
  JointPathSpec joint_path;  ///< space kJoint: one angle per link in every waypoint
  int configuration = 1;     ///< tip path: 1: q2 in (0, pi), 2: q2 in (-pi, 0) (core::ik_2link)
  core::JointVector velocity_limit = joint_pair(3.0, 4.0);  ///< rad/s per joint, >= 0
  core::JointVector torque_limit = joint_pair(10.0, 4.0);   ///< N m per joint, >= 0
  std::optional<core::JointVector> acceleration_limit;      ///< rad/s^2 per joint, >= 0
  DpSettings dp;
  ComplexSettings complex;
  ExactSettings exact;
  int motion_steps = 200;          ///< equal time steps of the sampled motion (for the renderer)
  int resample_per_interval = 16;  ///< dense re-check points per solver interval
  /// where the arm and its limits came from (model.xml and the report say it)
  ArmOrigin arm_origin;
};

/// The source's arm: massless links with a 1.0 kg point mass at the end of each link,
/// horizontal plane (gravity 0). Link lengths (not given by the source) default to
/// L1 = 0.5 m, L2 = 0.4 m: unequal, so the workspace is the annulus [0.1, 0.9] m with
/// the singular root region small, and a bench-top scale like the other studies' arms.
core::PlanarChain default_arm(double L1 = 0.5, double L2 = 0.4);

}  // namespace armstudy::studies::time_optimal
