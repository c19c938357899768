// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The throwing study's answer (plain data): the eq. 8 start, the feasible reference, the
/// IDP and SLSQP optima with their independent re-checks, the replay and the flight.

#include <array>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/types.hpp"
#include "studies/common.hpp"
#include "studies/throwing/idp.hpp"
#include "studies/throwing/nlopt_solve.hpp"
#include "studies/throwing/profile.hpp"
#include "studies/throwing/simulate.hpp"

namespace armstudy::studies {

/// A time series of one simulated motion, sampled at every RK4 step start and every
/// stage end (two samples share each interior stage boundary).
struct ThrowSeries {
  std::vector<double> t;                                 ///< s
  std::vector<core::JointVector> q, qd, qdd;             ///< (4) rad, rad/s, rad/s^2
  std::vector<Eigen::Vector2d> tau_m;                    ///< N m, motor torques
  std::vector<Eigen::Vector2d> voltage, current, power;  ///< V, A, W per motor
  std::vector<double> energy;                            ///< J, consumed so far
  std::vector<Eigen::Vector2d> ball;                     ///< m, ball centre
  std::vector<double> normal_force;                      ///< N, tray on ball
  std::vector<double> tangential_force;                  ///< N, tray on ball (what rolling needs)
};

/// Electrical energy split of one motion (integrals over [0, tf], J, both motors).
struct EnergySplit {
  double electrical = 0;  ///< sum of e i (eq. 7, trapezoid over the samples)
  double mechanical = 0;  ///< tau_m qd_m: work into the arm (and rotors)
  double copper = 0;      ///< Ra i^2
  double friction = 0;    ///< (Dm qd_m + tau_f sign qd_m) qd_m
  double rest = 0;        ///< electrical - (mechanical + copper + friction): 0 when kt = kv
};

/// One optimised (or initial) motion with everything a report shows.
struct ThrowMotion {
  VelocityProfile profile;
  ProfileEvaluation evaluation;
  ThrowSeries series;
  EnergySplit split;
  Eigen::Vector3d angle_error = Eigen::Vector3d::Zero();  ///< rad, theta1..3 at tf - wanted
  Eigen::Vector2d rate_error = Eigen::Vector2d::Zero();   ///< rad/s, theta1', theta2' at tf
  std::array<double, kConstraintKinds> worst{};  ///< normalised worst value per kind (<= 0 met)
};

/// An optimum re-simulated independently of the optimiser with `refinement` x the steps.
struct Verification {
  int refinement = 4;
  ProfileEvaluation evaluation;                  ///< at the finer steps, backoff 0
  std::array<double, kConstraintKinds> worst{};  ///< normalised, <= 0 met
  double release_error = 0;                      ///< rad, |theta3(tf) - release|
  bool feasible = false;
};

/// Ballistic flight of the ball after release.
struct Flight {
  bool reaches = false;                                ///< the ball reaches landing_height
  Eigen::Vector2d release_position, release_velocity;  ///< m, m/s
  double duration = 0;                                 ///< s
  Eigen::Vector2d landing = Eigen::Vector2d::Zero();   ///< m
  double apex = 0;                                     ///< m, highest y
  std::vector<Eigen::Vector2d> path;                   ///< m, 41 points from release to landing
  std::vector<double> path_t;                          ///< s after release
};

/// Output of the throwing study (plain data).
struct ThrowingResult {
  Status status = Status::kUnsolvable;
  std::string message;
  ThrowMotion initial;  ///< eq. 8 profile (raw)
  bool initial_feasible = false;
  std::string reference_kind;        ///< "eq8" (feasible as it is), "repaired" or "none"
  ThrowMotion reference;             ///< the feasible reference the savings are measured from
  NloptOutcome repair_run;           ///< SLSQP nearest-feasible repair (when eq. 8 is infeasible)
  ThrowMotion idp;                   ///< IDP optimum (best seed)
  IdpResult idp_run;                 ///< the best seed's run
  std::vector<IdpResult> idp_seeds;  ///< every seed (energies, convergence)
  int idp_best_seed = 0;             ///< index into idp_seeds
  bool idp_converged = false;        ///< every seed converged
  double idp_time = 0;               ///< s, wall clock of all seeds
  Verification idp_check;
  /// SLSQP from several starts ("reference", "idp", "eq8", "perturbed 1", ...): each local
  /// optimum, its first-order measure and its re-check
  struct SlsqpStart {
    std::string name;
    NloptOutcome run;
    Verification check;
  };
  std::vector<SlsqpStart> slsqp_starts;
  int slsqp_best_start = -1;  ///< the answer's start: lowest converged, re-checked feasible
  /// One control grid of the answer's sequence (grid_sequence.hpp), coarsest first.
  struct GridLevel {
    int stages = 0, steps_per_stage = 0;
    double energy = NAN;     ///< J, the lowest feasible throw on this grid
    bool feasible = false;   ///< that throw meets every limit, also in the re-check
    bool converged = false;  ///< first-order converged (SLSQP's test) on this grid
    double kkt_residual = NAN;
    std::string from;              ///< the start of that throw ("reference", "prolonged ...")
    double run_time = 0;           ///< s, wall clock of this grid's searches (the first: from
                                   ///< the study's start, IDP and every SLSQP start)
    long simulations = 0;          ///< of this grid's SLSQP searches
    std::vector<SlsqpStart> runs;  ///< SLSQP on this grid from each prolonged start
  };
  std::vector<GridLevel> grids;  ///< the answer's control grids (empty: SLSQP did not run)
  /// the last doubling changed the energy by at most grid.tolerance (relative)
  bool grid_converged = false;
  double grid_change = NAN;        ///< J, energy of the finest grid minus the one before
  double grid_error = NAN;         ///< J, estimated distance of the answer to the limit
  double grid_extrapolated = NAN;  ///< J, the answer's energy minus grid_error
  ThrowMotion first_grid;          ///< SLSQP's answer on the first grid (IDP's grid)
  Verification first_grid_check;
  int answer_steps_per_stage = 0;  ///< RK4 steps per stage of the answer's grid
  Optimality idp_optimality;       ///< the first-order measure at IDP's optimum
  bool nlopt_ran = false;
  ThrowMotion nlopt;  ///< SLSQP's answer (the best start's local optimum)
  NloptOutcome nlopt_run;
  Verification nlopt_check;
  double saving_percent = NAN;      ///< 100 (E_eq8 - E_answer) / E_eq8 (NaN: no feasible answer)
  double idp_saving_percent = NAN;  ///< 100 (E_eq8 - E_idp) / E_eq8 (NaN: IDP's is infeasible)
  std::string answer = "idp";       ///< "slsqp" when its converged, re-checked throw costs less
  Flight flight;                    ///< after the answer's release
  Flight idp_flight;                ///< after IDP's release
  Flight nlopt_flight;              ///< after SLSQP's release (when it ran)
  double replay_error = 0;          ///< rad, max |q_replay - q_plan (16x steps)|, 4 joints
  std::vector<double> replay_t;
  std::vector<core::JointVector> replay_q;
  double rk4_energy_error = 0;  ///< relative |E(n) - E(16n)| of the optimum
  double rk4_theta3_error = 0;  ///< rad, |theta3(tf) at n - at 16n steps|
  double run_time = 0;          ///< s
};

}  // namespace armstudy::studies
