#pragma once
/// The pendulum test of Sato et al. Sec. 3: joints 1 and 2 locked, the tray
/// (passive) and the rolling ball swing freely from rest. A passive system: its mechanical
/// energy K + U must stay constant, which checks the model and the integrator (Fig. 3).

#include <string>
#include <vector>

#include "core/types.hpp"
#include "studies/common.hpp"
#include "studies/throwing/tray_arm.hpp"

namespace armstudy::studies {

/// Inputs of the pendulum study, SI and radians.
struct PendulumSpec {
  TrayArmParams arm;              ///< see default_pendulum_spec()
  double theta1 = 0.0;            ///< rad, locked joint 1
  double theta2 = 0.0;            ///< rad, locked joint 2
  double theta3 = -core::kPi / 2; ///< rad, initial tray angle
  double theta4 = -core::kPi / 5; ///< rad, initial ball angle
  double theta3_rate = 0.0;       ///< rad/s
  double theta4_rate = 0.0;       ///< rad/s
  double duration = 2.0;          ///< s
  double sample_step = 0.005;     ///< s, time series spacing
  double snapshot_step = 0.13;    ///< s, snapshot spacing (Fig. 2)
  double rtol = 1e-12;            ///< DOPRI5 relative tolerance
  double atol = 1e-12;            ///< DOPRI5 absolute tolerance (rad, rad/s)
  double drift_tolerance = 1e-8;  ///< allowed relative energy drift (check)
};

/// Sec. 3's parameters: m3 = 0.109 kg, m4 = 0.122 kg, r4 = 0.075 m, r_b = 0.015 m. What
/// the paper leaves open (docs/assumptions.md) is: joints 1 and 2 locked at 0, 0; ball a solid
/// sphere (2/5 m4 r_b^2); the ball's circle centre 0.015 m from the hinge (Table 1's l3);
/// the tray's centre of mass at the bottom of the cup (0.015 + r4 + r_b = 0.105 m) and its
/// inertia that of a 2 (r4 + r_b) = 0.18 m rod, m3 (r4 + r_b)^2 / 3.
PendulumSpec default_pendulum_spec();

/// Output of the pendulum study (plain data).
struct PendulumResult {
  Status status = Status::kUnsolvable;
  std::string message;
  std::string integrator;  ///< e.g. "DOPRI5 (Dormand-Prince 5(4), adaptive)"
  double rtol = 0, atol = 0;
  long steps_accepted = 0, steps_rejected = 0, evaluations = 0;
  std::vector<double> t;                        ///< s
  std::vector<core::JointVector> q, qd;         ///< (4) rad, rad/s: all four coordinates
  std::vector<double> kinetic, potential, total;  ///< J
  std::vector<Eigen::Vector2d> ball;            ///< m, ball centre
  std::vector<Eigen::Vector2d> circle_centre;   ///< m, the centre C of the ball's circle
  std::vector<double> snapshot_t;               ///< s, every snapshot_step
  std::vector<int> snapshot_index;              ///< index into t of each snapshot
  double energy_initial = 0;                    ///< J
  double energy_scale = 0;   ///< J, largest kinetic energy (the energy exchanged)
  double energy_drift = 0;   ///< J, max |E(t) - E(0)|
  double energy_drift_rel = 0;  ///< energy_drift / energy_scale
  double run_time = 0;       ///< s, wall clock
};

/// Simulates the locked-arm pendulum with DOPRI5 at (rtol, atol); joints 1 and 2 get zero
/// acceleration and the passive joints follow core::passive_forward_dynamics.
/// Invalid arm parameters give status kUnsolvable with the reason.
PendulumResult solve_pendulum(const PendulumSpec& spec, const ProgressFn& progress = {});

}  // namespace armstudy::studies
