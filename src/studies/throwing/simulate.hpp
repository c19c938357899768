// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Simulation of the tray arm along a velocity profile of the active joints, its motor
/// electrics (003 eq. 5-7) and the constraints of the throw (eq. 9's tray width and the
/// contact, friction and motor limits of docs/throwing.md); and the open-loop replay of a voltage
/// history through the same model.
///
/// Planning model: joints 1 and 2 follow the profile exactly (their accelerations are given
/// stage by stage); the tray and the ball (joints 3, 4) follow core::passive_forward_dynamics,
/// which also returns the joint torques Q1, Q2 that realise the motion. Motor torques are
/// tau_m = B^-T Q (studies/tray_arm.hpp), and eq. 5-6 give voltages and currents. Each stage is
/// integrated with `steps_per_stage` RK4 steps (core::rk4_step, handed the first stage that the
/// constraints are read at), so the accelerations never jump inside a step;
/// the consumed energy (eq. 7) is integrated as a fifth state by the same RK4 steps.
///
/// Constraints (docs/throwing.md derives the contact forces). At the start of every RK4 step
/// and at every stage end the simulation evaluates the ball's contact with the tray from the
/// ball's own equation of motion, m4 a_ball = -N n + F_t t + m4 g (n the unit vector from the
/// centre C of the ball's circle to the ball's centre, t = n rotated by +90 deg):
///   N   = m4 (g - a_ball) . n   (normal force of the tray on the ball, must stay >= margin),
///   F_t = m4 (a_ball - g) . t   (tangential force rolling needs, |F_t| <= mu N),
/// and the motor ratings |e| <= voltage_max, |i| <= current_max, |e i| <= power_max. The tray
/// angle |theta4| <= lambda/2 and |theta3(tf) - theta3_release| <= release_tolerance complete
/// the constraint set. constraint_values() turns them into normalised values g <= 0.

#include <array>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/dc_motor.hpp"
#include "core/integrators.hpp"
#include "core/planar_chain.hpp"
#include "core/types.hpp"
#include "studies/throwing/profile.hpp"
#include "studies/tray_arm.hpp"

namespace armstudy::studies {

/// Everything a simulation of one profile needs besides the profile (SI, radians).
struct ThrowSetup {
  core::PlanarChain chain;  ///< make_tray_arm()
  Motor2Mount mount = Motor2Mount::kOnLink1;
  core::DcMotor motor[2];                 ///< eq. 5-7 (Im = 0: rotors are in the chain)
  double theta3_0 = 0.0, theta4_0 = 0.0;  ///< rad, passive joints at t = 0 (at rest)
  double theta3_release = 0.0;            ///< rad, wanted tray angle at tf
  double release_tolerance = 0.0175;      ///< rad, allowed |theta3(tf) - theta3_release|
  double half_width = 0.0;                ///< rad, lambda / 2: the ball stays in the tray
  double voltage_max = 24.0;              ///< V
  double current_max = 2.5;               ///< A
  double power_max = 60.0;                ///< W, |e i| per motor
  double contact_margin = 0.02;           ///< N, the tray's normal force on the ball >= this
  double friction_coefficient = 0.5;      ///< mu: rolling needs |F_t| <= mu N
  double ball_mass = 0.012;               ///< kg, m4 (forces from the ball's equation)
  bool count_regeneration = true;         ///< eq. 7 as printed (signed e i)
  int steps_per_stage = 40;               ///< RK4 steps in each stage
  /// true: the planning model's dynamics through the generic chain (core/dynamics.hpp and
  /// ball_contact_forces), the reference of the one-pass fast path (tray_dynamics.hpp) that
  /// simulations of a 4-joint chain use otherwise; both give the same results
  bool generic_dynamics = false;
  /// how simulations without recorded samples run, all with the same results bit for bit:
  /// 2 to 5: simulate_kernel.hpp, and evaluate_profiles, evaluate_neighbours and
  /// run_idp_seeds (idp.hpp) that many profiles at once (4 the fastest on the bundled
  /// cases); 1: the kernel one profile at a time; 0: the Planner of simulate.cpp one
  /// evaluation at a time (the kernel's reference). Only for the tray arm's joints
  /// (kernel_applies); other chains and generic_dynamics use the Planner.
  int kernel_lanes = 4;
};

/// Scalar outcome of one profile.
struct ProfileEvaluation {
  double energy = 0;               ///< J, eq. 7 (or its positive part without regeneration)
  double max_abs_theta4 = 0;       ///< rad
  double max_voltage = 0;          ///< V, max |e| over both motors
  double max_current = 0;          ///< A, max |i|
  double max_power = 0;            ///< W, max |e i| over both motors
  double min_normal_force = 0;     ///< N, smallest normal force of the tray on the ball
  double max_friction_ratio = 0;   ///< max |F_t| / N (infinite if N <= 0 somewhere)
  double max_friction_excess = 0;  ///< N, max (|F_t| - mu N)
  double theta3_final = 0, theta4_final = 0;            ///< rad at tf
  double theta3_rate_final = 0, theta4_rate_final = 0;  ///< rad/s at tf
  bool finite = true;  ///< false if the simulation blew up (energy is then huge)
  /// per stage: max |theta4| (rad), max |e| (V), max |i| (A), max |e i| (W), min N (N),
  /// max |F_t| - mu N (N): the stage-wise constraints
  std::vector<double> stage_theta4, stage_voltage, stage_current, stage_power, stage_normal,
      stage_friction;
  double violation = 0;   ///< sum of the positive parts of constraint_values(.., backoff)
  bool feasible = false;  ///< violation == 0
  /// simulate_profile(.., stop_when_infeasible = true) stopped at the first stage constraint
  /// that is certainly violated: the profile is infeasible (feasible false, violation
  /// +infinity, energy huge); the later stages are not simulated
  bool stopped = false;
};

/// Names of the constraint kinds, in the order of ConstraintKind.
enum class ConstraintKind { kContact, kFriction, kTray, kVoltage, kCurrent, kPower, kRelease };
inline constexpr int kConstraintKinds = 7;
const char* constraint_name(ConstraintKind k);

/// Normalised constraint values g <= 0 of an evaluation: per stage k (P each, in the order
/// of ConstraintKind) (margin - N_min) / (m4 g), (|F_t| - mu N)_max / (m4 g),
/// (|theta4|_max - lambda/2) / (lambda/2), (|e|_max - V) / V, (|i|_max - I) / I,
/// (|e i|_max - P) / P, then one (|theta3(tf) - target| - tol) / tol. `backoff` (>= 0) is
/// added to every value: the optimisers hold each constraint that far inside its limit so
/// that a finer re-simulation (which samples between their steps) still meets it.
/// An evaluation that is not finite gives 1e3 everywhere.
std::vector<double> constraint_values(const ThrowSetup& setup, const ProfileEvaluation& e,
                                      double backoff);

/// Worst normalised value of each constraint kind (max over stages), without backoff.
std::array<double, kConstraintKinds> worst_constraints(const ThrowSetup& setup,
                                                       const ProfileEvaluation& e);

/// The per-stage extremes of P stages at their neutral values (0 for the maxima, +infinity
/// for the smallest normal force, -infinity for the friction excess): where a simulation of
/// P stages starts them.
void reset_stage_extremes(int P, ProfileEvaluation& e);

/// Sets e.violation and e.feasible for the given backoff.
void classify(const ThrowSetup& setup, ProfileEvaluation& e, double backoff);

/// The end of a simulation that stayed finite: the largest (smallest normal force) of the
/// stage values, the final state x = (theta3, theta4, theta3', theta4', energy) and classify.
void finish_finite(const ThrowSetup& setup, const double* x, double backoff, ProfileEvaluation& e);

/// One recorded instant of a simulated throw.
struct ThrowSample {
  double t = 0;                  ///< s
  int stage = 0;                 ///< stage whose accelerations the sample uses
  core::JointVector q, qd, qdd;  ///< (4)
  core::JointVector tau;         ///< (4) generalized joint torques, N m (3, 4 are 0)
  Eigen::Vector2d tau_m;         ///< motor torques, N m
  Eigen::Vector2d motor_rate;    ///< rad/s
  core::MotorSample motor[2];    ///< eq. 5-7 per motor
  double energy = 0;             ///< J, consumed so far (eq. 7)
  double normal_force = 0;       ///< N, tray on ball (along -n; > 0 pushes the ball)
  double tangential_force = 0;   ///< N, tray on ball along t (what rolling needs)
};

/// Simulates `profile` (planning model). If `samples` is given, it receives the start of
/// every RK4 step and the end of every stage (the end sample of a stage and the start
/// sample of the next share a time but differ in accelerations). The evaluation is
/// classified with `backoff` (see constraint_values).
///
/// stop_when_infeasible: stop as soon as a stage constraint value (with `backoff`) is > 0.
/// The stage-wise maxima only grow (the minimum normal force only falls) as a stage is
/// simulated, so that value is > 0 at the end too and the full simulation would be
/// infeasible; the evaluation is then marked `stopped` (see ProfileEvaluation). For a caller
/// that only needs to know whether a profile beats a feasible one (IDP's candidates), this
/// decides exactly as the full simulation does.
ProfileEvaluation simulate_profile(const ThrowSetup& setup, const VelocityProfile& profile,
                                   std::vector<ThrowSample>* samples = nullptr,
                                   double backoff = 0.0, bool stop_when_infeasible = false);

/// A simulation's state at the start of every stage (simulate_profile's `save`): a profile
/// that differs from it only in later nodes resumes there (simulate_profile_from).
struct SimulationCheckpoints {
  VelocityProfile profile;             ///< the profile simulated
  std::vector<core::OdeState> x;       ///< (5) passive angles, rates and energy at stage k's start
  std::vector<double> friction_ratio;  ///< max |F_t| / N over the stages before k
  ProfileEvaluation evaluation;        ///< the full simulation's (its stage-wise maxima)
};

/// simulate_profile(setup, profile, nullptr, backoff) that also stores, in `save`, the
/// state at the start of every stage it reaches.
ProfileEvaluation simulate_profile(const ThrowSetup& setup, const VelocityProfile& profile,
                                   SimulationCheckpoints& save, double backoff = 0.0);

/// simulate_profile(setup, profile, nullptr, backoff) for a profile whose nodes 0 ..
/// first_stage are those of base.profile: stages 0 .. first_stage - 1 are then the same
/// computation, so the simulation resumes at stage first_stage from base's state and gives
/// the full simulation's evaluation bit for bit (a central-difference neighbour of node k
/// resumes at stage k - 1). Simulates from t = 0 if base did not reach that stage.
/// @throws std::invalid_argument if those nodes (or tf, q0) differ from base.profile's.
ProfileEvaluation simulate_profile_from(const ThrowSetup& setup, const VelocityProfile& profile,
                                        const SimulationCheckpoints& base, int first_stage,
                                        double backoff = 0.0);

/// simulate_profile_from for profiles with the same first_stage (out[i] of profiles[i]),
/// setup.kernel_lanes of them at once in the kernel when that is 2 or more.
/// @throws std::invalid_argument as simulate_profile_from.
void simulate_group_from(const ThrowSetup& setup,
                         const std::vector<const VelocityProfile*>& profiles,
                         const SimulationCheckpoints& base, int first_stage, double backoff,
                         ProfileEvaluation* out);

/// Contact forces of the tray on the ball (N) at state (q, qd, qdd) of the chain
/// (docs/throwing.md): {normal N, tangential F_t}.
Eigen::Vector2d ball_contact_forces(const core::PlanarChain& chain, double ball_mass,
                                    const core::JointVector& q, const core::JointVector& qd,
                                    const core::JointVector& qdd);

/// A voltage history: piecewise linear between samples, with possible jumps where two
/// samples share a time (the later one holds after the jump).
struct VoltageHistory {
  double tf = 0;                   ///< s, end of the history
  int stages = 1;                  ///< equal stages of [0, tf]; jumps only at their ends
  std::vector<double> t;           ///< s, non-decreasing
  std::vector<int> stage;          ///< stage of each sample (samples of a stage contiguous)
  std::vector<Eigen::Vector2d> e;  ///< V per motor
  /// Voltages at time t inside `stage`, linear between that stage's samples.
  Eigen::Vector2d at(int stage, double t) const;
};

/// The voltages of recorded samples.
VoltageHistory voltage_history(const std::vector<ThrowSample>& samples);

/// Result of an open-loop replay.
struct ReplayResult {
  std::vector<double> t;                 ///< s, the requested times
  std::vector<core::JointVector> q, qd;  ///< (4) each
  long steps = 0;
};

/// Applies the voltages open loop to the model: all four joints free, motor torques
/// tau_m = (kt/Ra)(e - kv qd_m) - Dm qd_m - tau_f sgn(qd_m) (eq. 5-6 solved for the
/// torque), Q = B^T tau_m, forward dynamics of the chain; DOPRI5 at (rtol, atol) with steps
/// that never cross a stage end (where voltages may jump). sgn is tanh(qd_m / sign_band)
/// (rad/s; 0 gives the exact sign, which chatters where a motor comes to rest).
/// Returns the states at `times`.
/// @throws std::runtime_error if the integration fails.
ReplayResult replay_voltages(const ThrowSetup& setup, const VoltageHistory& voltages,
                             const core::JointVector& q0, const core::JointVector& qd0,
                             const std::vector<double>& times, double rtol, double atol,
                             double sign_band = 1e-3);

}  // namespace armstudy::studies
