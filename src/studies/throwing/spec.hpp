// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The throwing study of Sato et al. Sec. 4: the tray arm moves from rest to
/// the release state in tf; joints 1, 2 follow a velocity profile optimised for the energy
/// the DC motors consume (eq. 7), the tray (joint 3) and the ball (joint 4) follow the
/// dynamics. IDP (Luus) is the paper's optimiser; SLSQP (NLopt) solves the same constrained
/// problem on the same parameterisation from several starts, IDP's optimum among them
/// (docs/throwing.md): the tray must push the ball (normal force >= a margin), rolling must
/// need no more friction than the coefficient allows, the ball stays within the tray's
/// width, the motors within their voltage, current and power ratings, and the tray reaches
/// its release angle. The answer is the lowest throw that is converged (first order, and a
/// restart gains nothing) and feasible when re-simulated with 4x the steps; the saving is
/// against the eq. 8 start. IDP starts from eq. 8 when it is feasible, else from its
/// repair. The ball flies ballistically after release down (or up) to a given height.
///
/// This header: the study's validated input. result.hpp holds its answer, solve.hpp the
/// computation.

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "core/dc_motor.hpp"
#include "core/types.hpp"
#include "studies/throwing/idp.hpp"
#include "studies/throwing/nlopt_solve.hpp"
#include "studies/tray_arm.hpp"

namespace armstudy::studies {

/// The control grid's refinement (grid_sequence.hpp): the answer of the continuous problem.
struct GridSettings {
  int refinements = 2;      ///< doublings of the stages after the first grid (16 -> 32 -> 64)
  double tolerance = 0.01;  ///< converged: the energy changes by at most this (relative) per
                            ///< doubling
  int refine_best = 2;      ///< distinct local optima of the first grid refined (the best few)
  bool require_converged = false;  ///< a sequence still falling at its last grid fails the
                                   ///< case (false: it is reported "not converged" only)
  /// SLSQP on the finer grids with the exact derivatives of throw_gradient.hpp: 4.3x cheaper
  /// than central differences at 64 stages, 8.3x at 256 (BM_ThrowGradient); the first grid
  /// and the sensitivity part's warm re-solves keep nlopt.exact_gradient. Off by default: a
  /// warm step from an answer refined this way can end short of the first-order test
  /// (docs/throwing.md, "Exact derivatives")
  bool exact_gradient = false;
};

/// A throw met elsewhere in a run (a sensitivity step's answer, app/sensitivity.hpp) that meets
/// the case's limits for less than its answer: the control grids try it too
/// (grid_sequence.hpp, "offered starts"). No case key sets it; the program does.
struct OfferedStart {
  std::string name;         ///< where it was met, in words
  VelocityProfile profile;  ///< its node rates (any grid)
};

/// Inputs of the throwing study (SI, radians). Defaults: Table 1 and Sec. 4 of 003, and
/// the choices of docs/assumptions.md where the paper is silent.
struct ThrowingSpec {
  TrayArmParams arm;    ///< Table 1
  core::DcMotor motor;  ///< both motors (Table 1); Im is arm.rotor_inertia
  Eigen::Vector2d start = {-core::kPi / 4, -core::kPi / 4};              ///< rad, theta1, theta2
  double theta3_start = 0.0;                                             ///< rad (at rest)
  double theta4_start = 0.0;                                             ///< rad (at rest)
  Eigen::Vector2d release = {13 * core::kPi / 36, -7 * core::kPi / 36};  ///< rad
  Eigen::Vector2d release_rate = {13.9, -1.1};                           ///< rad/s
  double theta3_release = -7 * core::kPi / 24;  ///< rad, reached through the dynamics
  double tf = 0.8;                              ///< s
  double voltage_max = 24.0;                    ///< V (Table 1: motors rated 24 V)
  double current_max = 5.0;                     ///< A (chosen; 2.5 A is 60 W at 24 V)
  double power_max = 60.0;                      ///< W, |e i| per motor (Table 1: rated 60 W)
  double tray_width = 2 * core::kPi / 3;        ///< rad, lambda of eq. 9 (|theta4| <= lambda/2)
  double contact_margin = 0.02;                 ///< N, normal force of the tray on the ball >= this
  double friction_coefficient = 0.5;            ///< mu, rolling needs |F_t| <= mu N
  double backoff = 0.02;             ///< optimisers keep constraints this far inside (normalised)
  bool allow_not_converged = false;  ///< a run ending on its budget fails the case unless true
  int check_refinement = 4;          ///< the optimum is re-checked with this many x the steps
  bool count_regeneration = true;    ///< eq. 7 as printed (signed e i)
  int stages = 16;                   ///< P
  int steps_per_stage = 20;          ///< RK4 steps per stage
  IdpSettings idp;
  GridSettings grid;  ///< the control grids after the first (SLSQP only)
  bool run_nlopt = true;
  NloptSettings nlopt;
  double release_tolerance = core::kDeg;  ///< rad, allowed |theta3(tf) - release| (check)
  double landing_height = 0.0;            ///< m, height (y) at which the flight ends
  double replay_tolerance = 2e-3;         ///< rad, open-loop replay vs plan (check)
  int threads = 2;                        ///< evaluation threads
  /// throws the run met elsewhere that meet these limits for less than the answer (the
  /// program's, not the case file's): SLSQP starts from each on the answer's control grid
  std::vector<OfferedStart> offered_starts;
};

}  // namespace armstudy::studies
