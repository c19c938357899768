// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The placement study's input (Kopmaz 2016): where to put the root of a
/// 2-link arm in a horizontal plane so that carrying a payload along a fixed straight line
/// costs the least actuator energy. SI units and radians; filled and validated by
/// cases::load_placement (src/cases/placement_case.hpp documents every key and default).

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/motion_program.hpp"
#include "core/planar_chain.hpp"
#include "studies/arm_origin.hpp"

namespace armstudy::studies::placement {

/// A fixed placement to evaluate: the thesis's line (x_s, phi) in the arm's frame.
struct EvaluationSpec {
  std::string label;  ///< a person's name for it ("" for none)
  double x_s = 0;     ///< m, start point (x_s, 0) in the arm's frame
  double phi = 0;     ///< rad, direction angle of the line
};

/// The cycle-time objective: the least time in which the arm can carry its tip
/// along the task line, rest to rest, under joint velocity, torque and (optional)
/// acceleration limits, found by the time-optimal study's exact solver (cycle_time.hpp).
struct CycleTimeSpec {
  core::JointVector velocity_limit;                     ///< rad/s per joint, > 0
  core::JointVector torque_limit;                       ///< N m per joint, > 0
  std::optional<core::JointVector> acceleration_limit;  ///< rad/s^2 per joint, > 0
  int map_grid_points = 100;    ///< the exact solver's grid at each map node (the coarse grid)
  int grid_points = 1000;       ///< its grid in the refinement and at the optimum (converged)
  int checks_per_interval = 2;  ///< points per grid interval where the limits hold
  /// the optimum's duration: the relative error the time-optimal study's extrapolation
  /// is asked for (time_optimal::ExactSettings::tolerance_rel)
  double tolerance_rel = 1e-5;
};

struct Spec {
  core::PlanarChain chain;  ///< 2 active links, gravity 0
  double length = 0;        ///< m, line length L (0 < L <= Lmax)
  double duration = 1;      ///< s, T
  std::vector<core::MotionProgram> programs = {core::MotionProgram::kCycloidal,
                                               core::MotionProgram::kPoly345};
  std::vector<int> configurations = {1, 2};
  int nx_s = 50;                                   ///< start-point steps: nx_s + 1 start points
  double phi_step = 3.14159265358979323846 / 180;  ///< rad, direction-angle step (1 deg)
  /// the thesis's own grid (its candidates, `thesis_search`): x_s over its interval and phi
  /// over [phi_init, phi_fin] at each x_s, each in this many equal steps (every printed
  /// optimum of Kopmaz's Ch. 9 sits on the 10-step grid, 11 x 11 candidates)
  int thesis_divisions = 10;
  int samples = 401;                 ///< samples per trajectory (uniform in time, both ends)
  double singularity_margin = 0.01;  ///< m, least distance of the line to either boundary
  std::optional<std::array<double, 2>> torque_limit;  ///< N m, per joint
  std::optional<std::array<double, 2>> power_limit;   ///< W, per joint
  std::vector<EvaluationSpec> evaluations;
  int map_nx = 200;  ///< map nodes along X (line direction)
  int map_ny = 100;  ///< map nodes along Y >= 0 (Y < 0 is the mirror image, configs swapped)
  bool refine = true;
  /// m, margins at which an optimum set by a clearance is re-solved (the sensitivity curve;
  /// the spec's own margin is added; margins the annulus cannot take are skipped)
  std::vector<double> sensitivity_margins = {0.005, 0.0075, 0.0125, 0.015, 0.02, 0.03, 0.04, 0.05};
  double refine_xtol = 1e-5;                                   ///< m
  double refine_phitol = 1e-3 * 3.14159265358979323846 / 180;  ///< rad
  int threads = 0;  ///< worker threads for the sweeps (0: all hardware threads)
  /// the cycle-time objective beside the energy's (none: energy only)
  std::optional<CycleTimeSpec> cycle_time;
  /// where the arm and its limits came from (model.xml and the report say it)
  ArmOrigin arm_origin;
};

}  // namespace armstudy::studies::placement
