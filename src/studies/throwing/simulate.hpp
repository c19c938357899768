#pragma once
/// Simulation of the tray arm along a velocity profile of the active joints, its motor
/// electrics (003 eq. 5-7) and the criterion of eq. 9; and the open-loop replay of a voltage
/// history through the same model.
///
/// Planning model: joints 1 and 2 follow the profile exactly (their accelerations are given
/// stage by stage); the tray and the ball (joints 3, 4) follow core::passive_forward_dynamics,
/// which also returns the joint torques Q1, Q2 that realise the motion. Motor torques are
/// tau_m = B^-T Q (tray_arm.hpp), and eq. 5-6 give voltages and currents. Each stage is
/// integrated with `steps_per_stage` RK4 steps, so the accelerations never jump inside a step;
/// the consumed energy (eq. 7) is integrated as a fifth state by the same RK4 steps.

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/dc_motor.hpp"
#include "core/planar_chain.hpp"
#include "core/types.hpp"
#include "studies/throwing/profile.hpp"
#include "studies/throwing/tray_arm.hpp"

namespace armstudy::studies {

/// Everything a simulation of one profile needs besides the profile (SI, radians).
struct ThrowSetup {
  core::PlanarChain chain;                  ///< make_tray_arm()
  Motor2Mount mount = Motor2Mount::kOnLink1;
  core::DcMotor motor[2];                   ///< eq. 5-7 (Im = 0: rotors are in the chain)
  double theta3_0 = 0.0, theta4_0 = 0.0;    ///< rad, passive joints at t = 0 (at rest)
  double theta3_release = 0.0;              ///< rad, wanted tray angle at tf
  double half_width = 0.0;                  ///< rad, lambda / 2: the ball stays in the tray
  double voltage_max = 24.0;                ///< V
  double current_max = 2.5;                 ///< A
  double k_tray = 1000.0;                   ///< J/rad, eq. 9's k on max |theta4| - lambda/2
  double k_release = 10.0;                  ///< J/rad on |theta3(tf) - theta3_release|
  double k_voltage = 1000.0;                ///< J/V on max |e| - voltage_max
  double k_current = 1000.0;                ///< J/A on max |i| - current_max
  bool count_regeneration = true;           ///< eq. 7 as printed (signed e i)
  int steps_per_stage = 40;                 ///< RK4 steps in each stage
};

/// Scalar outcome of one profile.
struct ProfileEvaluation {
  double energy = 0;         ///< J, eq. 7 (or its positive part without regeneration)
  double criterion = 0;      ///< J, energy + penalties (eq. 9 extended)
  double max_abs_theta4 = 0; ///< rad
  double max_voltage = 0;    ///< V, max |e| over both motors
  double max_current = 0;    ///< A, max |i|
  double theta3_final = 0, theta4_final = 0;  ///< rad at tf
  double theta3_rate_final = 0, theta4_rate_final = 0;  ///< rad/s at tf
  bool finite = true;        ///< false if the simulation blew up (criterion is then huge)
  /// per stage: max |theta4| (rad), max |e| (V), max |i| (A), for stage-wise constraints
  std::vector<double> stage_theta4, stage_voltage, stage_current;
};

/// One recorded instant of a simulated throw.
struct ThrowSample {
  double t = 0;                 ///< s
  int stage = 0;                ///< stage whose accelerations the sample uses
  core::JointVector q, qd, qdd; ///< (4)
  core::JointVector tau;        ///< (4) generalized joint torques, N m (3, 4 are 0)
  Eigen::Vector2d tau_m;        ///< motor torques, N m
  Eigen::Vector2d motor_rate;   ///< rad/s
  core::MotorSample motor[2];   ///< eq. 5-7 per motor
  double energy = 0;            ///< J, consumed so far (eq. 7)
};

/// Simulates `profile` (planning model). If `samples` is given, it receives the start of
/// every RK4 step and the end of every stage (the end sample of a stage and the start
/// sample of the next share a time but differ in accelerations).
ProfileEvaluation simulate_profile(const ThrowSetup& setup, const VelocityProfile& profile,
                                   std::vector<ThrowSample>* samples = nullptr);

/// A voltage history: piecewise linear between samples, with possible jumps where two
/// samples share a time (the later one holds after the jump).
struct VoltageHistory {
  double tf = 0;                       ///< s, end of the history
  int stages = 1;                      ///< equal stages of [0, tf]; jumps only at their ends
  std::vector<double> t;               ///< s, non-decreasing
  std::vector<int> stage;              ///< stage of each sample (samples of a stage contiguous)
  std::vector<Eigen::Vector2d> e;      ///< V per motor
  /// Voltages at time t inside `stage`, linear between that stage's samples.
  Eigen::Vector2d at(int stage, double t) const;
};

/// The voltages of recorded samples.
VoltageHistory voltage_history(const std::vector<ThrowSample>& samples);

/// Result of an open-loop replay.
struct ReplayResult {
  std::vector<double> t;               ///< s, the requested times
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
