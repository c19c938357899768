// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The cycle-time objective's answer, plain data: at one placement
/// (cycle_time.hpp), over the map's root locations and at the refined optimum
/// (cycle_time_map.hpp). SI units; the root (X, Y) in the line frame (geometry.hpp).

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/motion_program.hpp"

namespace armstudy::studies::placement {

enum class CandidateStatus : std::uint8_t;  // (result.hpp)

/// A limit the fastest motion reaches.
struct LimitUse {
  std::string kind;      ///< "velocity", "torque", "acceleration"
  int joint = 0;         ///< 1-based
  double ratio = 0;      ///< largest |value| / limit over the densely resampled motion
  bool binding = false;  ///< ratio >= 1 - kBindingSlack: the motion runs on this limit
};

/// A limit whose largest use is within this of 1 binds the fastest motion.
inline constexpr double kBindingSlack = 1e-3;

/// The converged least traversal time at one placement: the time-optimal study solved on
/// the line (cycle_time_problem at spec.cycle_time->grid_points), its exact solution
/// re-checked densely and its duration extrapolated over the grids with its error.
struct ConvergedCycleTime {
  bool solved = false;
  std::string message;       ///< the time-optimal study's summary, or why no motion exists
  double duration = 0;       ///< s, the extrapolated duration (the grid's when not extrapolated)
  double error = 0;          ///< s, its stated error (the extrapolation's)
  double grid_duration = 0;  ///< s, the exact solver's on its grid
  int grid_points = 0;       ///< that grid's nodes (graded when the uniform one was too coarse)
  std::vector<LimitUse> limits;  ///< every limit of the problem, joint by joint
};

/// The energy of a fastest motion: E = integral of |tau1 qd1| + |tau2 qd2| dt (eq. 8.1), the
/// energy objective's measure, over the time-optimal motion (constant s'' per interval of the
/// exact solver's grid; 4 Gauss-Legendre points per interval, the placement's closed-form
/// inverse dynamics, arm2.hpp) on spec.cycle_time->grid_points nodes and on the grid with
/// every interval halved: the finer grid's energy, the change as its error (the exact
/// solver's switching points move by a grid interval: first order).
struct FastMotionEnergy {
  bool computed = false;
  double energy = 0;    ///< J, on the halved grid
  double error = 0;     ///< J, |E(halved) - E(grid)|
  int grid_points = 0;  ///< the halved grid's nodes
  double duration = 0;  ///< s, that motion's time on the halved grid
};

/// One placement of the trade-off between the cycle-time and the energy objective (one
/// program and configuration): the least cycle time there (the exact solver on the uniform
/// spec.cycle_time->grid_points grid, not extrapolated), the energy objective's energy of the
/// program's motion in T (the sweep's sampled energy, spec.samples) and the energy of the
/// fastest motion there (the same solve). Every point is admissible for both objectives.
struct CycleEnergyPoint {
  Eigen::Vector2d root = Eigen::Vector2d::Zero();  ///< m, (X, Y) in the line frame
  double x_s = 0, phi = 0;                         ///< m, rad
  double time = 0;                                 ///< s
  double energy = 0;                               ///< J, the program's motion in T
  double fast_energy = 0;                          ///< J, the fastest motion's
  std::string kind;  ///< "energy_optimum", "time_optimum" or "map_node"
};

/// The least traversal time over root locations (X, Y) in the line frame, one
/// configuration: the energy map's nodes (row-major, row j is Y = y[j], column i X = x[i]).
struct CycleTimeMap {
  std::vector<double> x, y;  ///< m
  /// s, on spec.cycle_time->map_grid_points nodes; NaN where not admissible or unsolved
  std::vector<double> time;
  std::vector<CandidateStatus> status;  ///< unreachable, singular (inside the margin), feasible
  int solved = 0;                       ///< admissible nodes with a motion
  double seconds = 0;                   ///< wall time of the map
  int threads = 1;                      ///< the threads it ran on
};

/// The cycle-time optimum of one configuration.
struct CycleTimeOptimum {
  int configuration = 1;
  bool found = false;
  std::string reason;                                   ///< why not, when !found
  Eigen::Vector2d grid_root = Eigen::Vector2d::Zero();  ///< m, the map's fastest node (X, Y)
  double grid_time = 0;                                 ///< s, its time on the map's coarse grid
  double x_s = 0, phi = 0;                              ///< m, rad: the refined line
  Eigen::Vector2d root = Eigen::Vector2d::Zero();       ///< m, its root (X, Y) in the line frame
  /// m: the compass search's last step, at which none of the 8 points around the optimum
  /// (the admissible ones) was faster on the converged grid: the location's resolution
  double root_error = 0;
  double fine_time = 0;                     ///< s, the optimum's time on the refinement's grid
  int evaluations = 0;                      ///< exact solves of the refinement
  double inner_slack = 0, outer_slack = 0;  ///< m, clearances to the circles minus the margin
  bool set_by_margin = false;               ///< a clearance slack is within root_error of 0
  ConvergedCycleTime converged;  ///< the duration, its error and the limits at the optimum
  FastMotionEnergy fast_energy;  ///< what the fastest motion at the optimum costs
  /// s: how far the printed duration may lie above the least one, the extrapolation's error
  /// plus the largest time difference over the last compass ring on the converged grid (the
  /// objective's change within root_error)
  double duration_error = 0;
};

/// The energy optimum of one program in the same configuration, and its least cycle time:
/// the trade-off's other end.
struct EnergyOptimumCycleTime {
  core::MotionProgram program = core::MotionProgram::kCycloidal;
  double x_s = 0, phi = 0;                         ///< m, rad
  Eigen::Vector2d root = Eigen::Vector2d::Zero();  ///< m
  double energy = 0;                               ///< J, of its fixed-duration motion
  ConvergedCycleTime time;
  FastMotionEnergy fast_energy;  ///< the fastest motion at this placement
  /// the energy objective at the cycle-time optimum of the configuration: this program's
  /// motion in T there (adaptive quadrature, quadrature.hpp), its error and the placement's
  /// status for the energy objective (a torque or power limit of it may exclude it)
  double energy_at_time_optimum = 0, energy_at_time_optimum_error = 0;
  bool has_energy_at_time_optimum = false;
  CandidateStatus status_at_time_optimum{};
  /// the non-dominated placements of (least cycle time, this program's energy in T) over
  /// the map's nodes admissible for both objectives and both optima, by increasing time
  std::vector<CycleEnergyPoint> front;
};

/// The cycle-time objective of one configuration.
struct CycleTime {
  int configuration = 1;
  CycleTimeMap map;
  CycleTimeOptimum optimum;
  std::vector<EnergyOptimumCycleTime> at_energy_optima;
};

}  // namespace armstudy::studies::placement
