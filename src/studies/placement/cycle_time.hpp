// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The cycle-time objective of the placement study at one placement: the task
/// line (x_s, phi) of a placement spec, placed at its root, is a tip path of the
/// time-optimal study; its least traversal time under the spec's CycleTimeSpec limits is
/// that study's exact (reachability) solver's. Nothing here solves a time-optimal problem
/// of its own: it builds the time-optimal study's Spec and calls its solvers.
///
/// Frames as geometry.hpp: the arm's frame A (root at the origin), the line from
/// S = (x_s, 0) along (cos phi, sin phi), length spec.length.

#include "studies/placement/cycle_time_result.hpp"
#include "studies/placement/spec.hpp"
#include "studies/time_optimal/spec.hpp"

namespace armstudy::studies::placement {

/// The time-optimal study's problem of the line (x_s, phi) in `configuration`: the spec's
/// chain with its root at the origin of A, the straight tip path from S to S + L u, the
/// cycle-time limits, the exact solver on `grid_points` nodes (checks and tolerance from
/// spec.cycle_time) and none of the study's other solvers (no DP, no Complex method, no
/// DP convergence table). spec.cycle_time must be set.
time_optimal::Spec cycle_time_problem(const Spec& spec, int configuration, double x_s, double phi,
                                      int grid_points);

/// The least traversal time (s) of the line on `grid_points` uniform nodes: the exact
/// solver once (time_optimal::solve_exact), without its dense re-check or the grid
/// extrapolation; NaN when it finds no motion (or the path leaves the workspace). The
/// map's and the refinement's objective.
double cycle_time_on_grid(const Spec& spec, int configuration, double x_s, double phi,
                          int grid_points);

/// The fastest motion on `grid_points` uniform nodes (the exact solver once, as
/// cycle_time_on_grid): its time (s) and its energy (J, FastMotionEnergy's measure); both
/// NaN when it finds no motion.
struct FastMotionOnGrid {
  double duration = 0, energy = 0;
};
FastMotionOnGrid fastest_motion_on_grid(const Spec& spec, int configuration, double x_s, double phi,
                                        int grid_points);

/// The energy of the fastest motion at one placement on spec.cycle_time->grid_points nodes
/// and on the grid with every interval halved (FastMotionEnergy).
FastMotionEnergy fastest_motion_energy(const Spec& spec, int configuration, double x_s, double phi);

/// The converged least traversal time at one placement: the time-optimal study solved on
/// the line (cycle_time_problem at spec.cycle_time->grid_points), its exact solution
/// re-checked densely and its duration extrapolated over the grids with its error.
ConvergedCycleTime converged_cycle_time(const Spec& spec, int configuration, double x_s,
                                        double phi);

}  // namespace armstudy::studies::placement
