// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Everything the time-optimal report shows: per solver the duration, run time, the
/// profile s'(s) and s(t), joint velocities and torques over time, the largest limit
/// violation found by dense resampling; the maximum velocity curve; the DP convergence
/// table; the motion at equal time steps for the renderer. Plain data, SI units.

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/types.hpp"
#include "studies/common.hpp"
#include "studies/time_optimal/phase.hpp"
#include "studies/time_optimal/spec.hpp"

namespace armstudy::studies::time_optimal {

/// How a solution moves inside one interval between its nodes.
enum class SegmentLaw {
  kPathAcceleration,    ///< constant s'' (x = s'^2 linear in s): DP path-speed, Complex, exact
  kJoint1Acceleration,  ///< constant q1'' (the source's DP with the joint-1 velocity state)
};

/// Samples of a motion (columns are samples, ordered in s and t).
struct MotionSamples {
  std::vector<double> s;    ///< m (rad for a joint-space path, so are sd and sdd per s)
  std::vector<double> t;    ///< s
  std::vector<double> sd;   ///< m/s
  std::vector<double> sdd;  ///< m/s^2
  Eigen::MatrixXd q, qd, qdd,
      tau;  ///< (joints x samples) rad, rad/s, rad/s^2, N m (inverse dynamics)
};

/// The largest use of each limit over the densely resampled motion.
struct Violation {
  /// ratio[kind][joint] = max |value| / limit (> 1: violated); kind as LimitKind (entries
  /// beyond the arm's joints stay 0)
  double ratio[3][core::kMaxLinks] = {};
  double worst = 0;  ///< max over kinds and joints of ratio - 1 (<= 0: every limit met)
  int joint = 0;     ///< where the worst ratio occurs: joint (0-based)
  LimitKind kind = LimitKind::kVelocity;
  double s = 0;      ///< m
  double t = 0;      ///< s
  int interval = 0;  ///< solver interval (grid point at its start)
  std::string text;  ///< names the grid point, binding limit and margin
};

/// A solver's name ("exact", "dp", "dp_joint1", "complex") in words, for sentences and labels.
inline std::string solver_words(const std::string& name) {
  if (name == "dp") return "DP";
  if (name == "dp_joint1") return "DP, joint-1 velocity state";
  if (name == "complex") return "Complex method";
  return name;
}

struct SolverResult {
  std::string name;    ///< "exact", "dp", "dp_joint1", "complex"
  std::string method;  ///< a sentence
  bool solved = false;
  std::string message;  ///< why not, when not solved
  double duration = 0;  ///< s
  double run_time = 0;  ///< s, wall clock of the solver
  int intervals = 0;    ///< N
  int levels = 0;       ///< DP velocity levels (0 otherwise)
  SegmentLaw law = SegmentLaw::kPathAcceleration;
  std::vector<double> node_s, node_sd, node_t;  ///< the profile at the solver's nodes
  MotionSamples samples;                        ///< decimated dense samples for plots (<= ~600)
  Violation violation;                          ///< over the full dense resampling
  long evaluations = 0;                         ///< DP transitions / Complex objective calls
  int iterations = 0;                           ///< Complex reflections
  /// exact only: check points per grid interval the answer was solved with (the case's
  /// checks_per_interval, doubled where the dense re-check found a limit overshot)
  std::vector<int> checks_per_interval;

  /// The solver in words, for sentences and labels ("dp_joint1" is a results.json key).
  std::string words() const { return solver_words(name); }
};

struct ConvergenceRow {
  int segments = 0;
  int levels = 0;
  bool solved = false;
  double duration = 0;  ///< s
  double excess = 0;    ///< duration / exact - 1
  double run_time = 0;  ///< s
  double worst_violation = 0;
  std::string message;  ///< why not, when not solved (segment, place and binding limit)
};

/// The converged duration's error estimate is this many times the spread of the order-1
/// Richardson extrapolations one and two grids down (GridConvergence). For a clean order p
/// the extrapolation's error is 1 / (2^p - 1) times that spread, so 4 covers p >= 0.32
/// (a singular pose's N^-1/2 included). Measured on 648 random lines of the source's arm at
/// 300, 1000 and 2000 grid points against 32,000 and 64,000 (docs/derivations/time_optimal.md):
/// it covered all but one (at 300 points, 1.4 times its estimate); 3 left one line at 1000
/// points on the edge (1.0).
inline constexpr double kExtrapolationSafety = 4.0;

/// The exact solver's own grid convergence: the same problem on the grid with every
/// interval halved (2 N - 1 points), and where the duration changed.
struct GridConvergence {
  bool computed = false;
  int grid_points = 0;     ///< the case's grid
  int refined_points = 0;  ///< 2 grid_points - 1
  bool refined_solved = false;
  double duration = 0;          ///< s, on the case's grid
  double refined_duration = 0;  ///< s, on the refined grid
  double change = 0;     ///< |duration / refined_duration - 1| (inf if the refined solve failed)
  double tolerance = 0;  ///< ExactSettings::grid_tolerance
  /// the shortest stretch of the path holding 90 % of the change (summed |change| of the
  /// case grid's intervals), its share, the largest s' there (m/s) and the smallest |sin q2|
  /// there and along the whole path
  double s_lo = 0, s_hi = 0;       ///< m
  int point_lo = 0, point_hi = 0;  ///< grid points
  double share = 0;
  double max_sd = 0;
  double min_sin_q2 = 1, path_min_sin_q2 = 1;
  std::string text;  ///< the sentence for the check and the page
  /// The converged duration. The exact solver's discretisation is first order in the
  /// interval, T(I) = T_inf + C / I + ..., so the headline is Richardson's extrapolation at
  /// order 1 over the case's grid and the refined one, E = T(2I) - (T(I) - T(2I)). The same
  /// one grid down, over a coarser grid (about half the case's intervals) and the case's,
  /// gives E1, and two grids down, over a quarter grid and the coarser one, E2; the error
  /// estimate is kExtrapolationSafety max(|E - E1|, |E1 - E2| / 2) (the spread of the
  /// extrapolations, which the erratic part of the error and any other order show; without
  /// a quarter grid |E - E1| alone). The observed order p of T(I) = T_inf + C I^-p over the
  /// coarser, case and refined grids checks the first-order assumption; `asymptotic`: the
  /// two changes have one sign and p lies in [0.5, 4].
  bool extrapolation_computed = false;
  int coarse_points = 0;
  double coarse_duration = NAN;   ///< s
  int quarter_points = 0;         ///< 0: no quarter grid
  double quarter_duration = NAN;  ///< s
  double order = NAN;             ///< observed p (NaN when not in the asymptotic range)
  bool asymptotic = false;
  double extrapolated = NAN;          ///< s, E: the headline duration
  double extrapolated_coarse = NAN;   ///< s, E1
  double extrapolated_quarter = NAN;  ///< s, E2 (NaN: no quarter grid)
  double extrapolation_error = NAN;   ///< s
  /// The graded grid (ExactSettings::tolerance_rel): whether the case's uniform grid was
  /// refined where its halving change arose, the uniform grid's points and change, the
  /// bisection rounds, the target and whether the node cap (max_grid_points) stopped it.
  /// When graded, grid_points is the graded grid's and the coarser grid of the extrapolation
  /// is every other node of it (a nested coarsening).
  bool graded = false;
  int uniform_points = 0;
  double uniform_change = NAN;
  int graded_rounds = 0;
  double graded_tolerance = 0;
  int max_points = 0;
  bool capped = false;
  /// the converged duration when the extrapolation ran, else `grid_duration` (the exact
  /// solver's on its grid): what the other solvers' durations are compared with
  double reference_duration(double grid_duration) const {
    return extrapolation_computed && std::isfinite(extrapolated) ? extrapolated : grid_duration;
  }
};

struct Result {
  Status status = Status::kUnsolvable;
  std::string message;
  double path_length = 0;             ///< m (rad for a joint-space path)
  std::vector<SolverResult> solvers;  ///< exact first, then DP run(s), then Complex
  /// maximum velocity curve on the exact grid: the largest s' at which some s'' meets
  /// every limit at that point (m/s); and the speed allowed by velocity limits alone
  std::vector<double> mvc_s, mvc_sd, mvc_velocity_sd;
  std::vector<ConvergenceRow> convergence;
  GridConvergence grid;
  /// the exact solution at equal time steps (renderer): t, s, tip and joint angles
  std::vector<double> motion_t, motion_s;
  Eigen::Matrix2Xd motion_p;
  Eigen::MatrixXd motion_q;   ///< (joints x steps) rad
  Eigen::MatrixXd motion_qd;  ///< (joints x steps) rad/s
  /// the path at the exact grid (for plots): tip points
  Eigen::Matrix2Xd path_p;
  Limits limits;
  /// the path was given in joint space: s is in rad (joint-space chord length) and s' in
  /// rad/s, not m and m/s; the elbow's sin q2 means nothing there (reported as 1)
  bool joint_space = false;
  const char* s_unit() const { return joint_space ? "rad" : "m"; }
};

}  // namespace armstudy::studies::time_optimal
