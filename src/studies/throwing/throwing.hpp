#pragma once
/// The throwing study of Sato et al. Sec. 4: the tray arm moves from rest to
/// the release state in tf; joints 1, 2 follow a velocity profile optimised for the energy
/// the DC motors consume (eq. 7), the tray (joint 3) and the ball (joint 4) follow the
/// dynamics. IDP (Luus) is the paper's optimiser; SLSQP (NLopt) solves the same constrained
/// problem on the same parameterisation beside it (docs/throwing.md): the tray must push
/// the ball (normal force >= a margin), rolling must need no more friction than the
/// coefficient allows, the ball stays within the tray's width, the motors within their
/// voltage, current and power ratings, and the tray reaches its release angle. Both start
/// from a feasible reference: the eq. 8 trajectory when it is feasible, else the feasible
/// profile nearest to it (SLSQP repair). Every reported optimum is re-simulated with 4x the
/// steps and checked against every constraint. The ball flies ballistically after release
/// down (or up) to a given height.

#include <array>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/dc_motor.hpp"
#include "studies/common.hpp"
#include "studies/throwing/idp.hpp"
#include "studies/throwing/nlopt_solve.hpp"
#include "studies/throwing/profile.hpp"
#include "studies/throwing/simulate.hpp"
#include "studies/throwing/tray_arm.hpp"

namespace armstudy::studies {

/// Inputs of the throwing study (SI, radians). Defaults: Table 1 and Sec. 4 of 003, and
/// the choices of docs/assumptions.md where the paper is silent.
struct ThrowingSpec {
  TrayArmParams arm;                 ///< Table 1
  core::DcMotor motor;               ///< both motors (Table 1); Im is arm.rotor_inertia
  Eigen::Vector2d start = {-core::kPi / 4, -core::kPi / 4};             ///< rad, theta1, theta2
  double theta3_start = 0.0;         ///< rad (at rest)
  double theta4_start = 0.0;         ///< rad (at rest)
  Eigen::Vector2d release = {13 * core::kPi / 36, -7 * core::kPi / 36};  ///< rad
  Eigen::Vector2d release_rate = {13.9, -1.1};                          ///< rad/s
  double theta3_release = -7 * core::kPi / 24;  ///< rad, reached through the dynamics
  double tf = 0.8;                   ///< s
  double voltage_max = 24.0;         ///< V (Table 1: motors rated 24 V)
  double current_max = 5.0;          ///< A (chosen; 2.5 A is 60 W at 24 V)
  double power_max = 60.0;           ///< W, |e i| per motor (Table 1: rated 60 W)
  double tray_width = 2 * core::kPi / 3;  ///< rad, lambda of eq. 9 (|theta4| <= lambda/2)
  double contact_margin = 0.02;      ///< N, normal force of the tray on the ball >= this
  double friction_coefficient = 0.5; ///< mu, rolling needs |F_t| <= mu N
  double backoff = 0.02;             ///< optimisers keep constraints this far inside (normalised)
  bool allow_not_converged = false;  ///< a run ending on its budget fails the case unless true
  int check_refinement = 4;          ///< the optimum is re-checked with this many x the steps
  bool count_regeneration = true;    ///< eq. 7 as printed (signed e i)
  int stages = 16;                   ///< P
  int steps_per_stage = 20;          ///< RK4 steps per stage
  IdpSettings idp;
  bool run_nlopt = true;
  NloptSettings nlopt;
  double release_tolerance = core::kPi / 180;  ///< rad, allowed |theta3(tf) - release| (check)
  double landing_height = 0.0;       ///< m, height (y) at which the flight ends
  double replay_tolerance = 2e-3;    ///< rad, open-loop replay vs plan (check)
  int threads = 2;                   ///< evaluation threads
};

/// A time series of one simulated motion, sampled at every RK4 step start and every
/// stage end (two samples share each interior stage boundary).
struct ThrowSeries {
  std::vector<double> t;                       ///< s
  std::vector<core::JointVector> q, qd, qdd;   ///< (4) rad, rad/s, rad/s^2
  std::vector<Eigen::Vector2d> tau_m;          ///< N m, motor torques
  std::vector<Eigen::Vector2d> voltage, current, power;  ///< V, A, W per motor
  std::vector<double> energy;                  ///< J, consumed so far
  std::vector<Eigen::Vector2d> ball;           ///< m, ball centre
  std::vector<double> normal_force;            ///< N, tray on ball
  std::vector<double> tangential_force;        ///< N, tray on ball (what rolling needs)
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

/// Re-simulates `profile` with `refinement` x the setup's steps and checks every constraint
/// (no backoff).
Verification verify_profile(const ThrowSetup& setup, const VelocityProfile& profile,
                            int refinement);

/// Ballistic flight of the ball after release.
struct Flight {
  bool reaches = false;             ///< the ball reaches landing_height
  Eigen::Vector2d release_position, release_velocity;  ///< m, m/s
  double duration = 0;              ///< s
  Eigen::Vector2d landing = Eigen::Vector2d::Zero();   ///< m
  double apex = 0;                  ///< m, highest y
  std::vector<Eigen::Vector2d> path;  ///< m, 41 points from release to landing
  std::vector<double> path_t;       ///< s after release
};

/// Output of the throwing study (plain data).
struct ThrowingResult {
  Status status = Status::kUnsolvable;
  std::string message;
  ThrowMotion initial;  ///< eq. 8 profile (raw)
  bool initial_feasible = false;
  std::string reference_kind;  ///< "eq8" (feasible as it is), "repaired" or "none"
  ThrowMotion reference;       ///< the feasible reference the savings are measured from
  NloptOutcome repair_run;     ///< SLSQP nearest-feasible repair (when eq. 8 is infeasible)
  ThrowMotion idp;      ///< IDP optimum (best seed)
  IdpResult idp_run;    ///< the best seed's run
  std::vector<IdpResult> idp_seeds;  ///< every seed (energies, convergence)
  int idp_best_seed = 0;             ///< index into idp_seeds
  bool idp_converged = false;        ///< every seed converged
  double idp_time = 0;               ///< s, wall clock of all seeds
  Verification idp_check;
  bool nlopt_ran = false;
  ThrowMotion nlopt;    ///< SLSQP's answer (its final point)
  NloptOutcome nlopt_run;
  Verification nlopt_check;
  double saving_percent = 0;  ///< 100 (E_ref - E_idp) / E_ref
  Flight flight;
  double replay_error = 0;    ///< rad, max |q_replay - q_plan (16x steps)|, 4 joints
  std::vector<double> replay_t;
  std::vector<core::JointVector> replay_q;
  double rk4_energy_error = 0;   ///< relative |E(n) - E(16n)| of the optimum
  double rk4_theta3_error = 0;   ///< rad, |theta3(tf) at n - at 16n steps|
  double run_time = 0;           ///< s
};

/// Builds the simulation setup of a spec. @throws std::invalid_argument on bad parameters.
ThrowSetup make_throw_setup(const ThrowingSpec& spec);

/// Simulates one profile and records its series, split and release errors.
ThrowMotion record_motion(const ThrowSetup& setup, const ThrowingSpec& spec,
                          const VelocityProfile& profile);

/// Re-simulates `profile` with `refinement` x the setup's steps and checks every constraint
/// (no backoff).
Verification verify_profile(const ThrowSetup& setup, const VelocityProfile& profile,
                            int refinement);

/// Ballistic flight from (p, v) under gravity g (m/s^2, > 0) down or up to height h.
Flight ballistic_flight(const Eigen::Vector2d& p, const Eigen::Vector2d& v, double g, double h);

/// Solves the study: eq. 8 start, IDP, SLSQP (if enabled), replay, flight.
ThrowingResult solve_throwing(const ThrowingSpec& spec, const ProgressFn& progress = {});

}  // namespace armstudy::studies
