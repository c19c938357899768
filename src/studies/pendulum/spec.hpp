// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The pendulum test of Sato et al. Sec. 3: joints 1 and 2 locked, the tray
/// (passive) and the rolling ball swing freely from rest. A passive system: its mechanical
/// energy K + U must stay constant, which checks the model and the integrator (Fig. 3).
///
/// This header: the study's validated input. result.hpp holds its answer, solve.hpp the
/// computation.

#include "core/types.hpp"
#include "studies/tray_arm.hpp"

namespace armstudy::studies {

/// Inputs of the pendulum study, SI and radians.
struct PendulumSpec {
  TrayArmParams arm;               ///< see default_pendulum_spec()
  double theta1 = 0.0;             ///< rad, locked joint 1
  double theta2 = 0.0;             ///< rad, locked joint 2
  double theta3 = -core::kPi / 2;  ///< rad, initial tray angle
  double theta4 = -core::kPi / 5;  ///< rad, initial ball angle
  double theta3_rate = 0.0;        ///< rad/s
  double theta4_rate = 0.0;        ///< rad/s
  double duration = 2.0;           ///< s
  double sample_step = 0.005;      ///< s, time series spacing
  double snapshot_step = 0.13;     ///< s, snapshot spacing (Fig. 2)
  double rtol = 1e-12;             ///< DOPRI5 relative tolerance
  double atol = 1e-12;             ///< DOPRI5 absolute tolerance (rad, rad/s)
  double drift_tolerance = 1e-8;   ///< allowed relative energy drift (check)
  long max_steps = 10'000'000;     ///< DOPRI5 steps (accepted + rejected) before it gives up
};

/// Sec. 3's parameters: m3 = 0.109 kg, m4 = 0.122 kg, r4 = 0.075 m, r_b = 0.015 m. What
/// the paper leaves open (docs/assumptions.md) is: joints 1 and 2 locked at 0, 0; ball a solid
/// sphere (2/5 m4 r_b^2); the ball's circle centre 0.015 m from the hinge (Table 1's l3);
/// the tray's centre of mass at the bottom of the cup (0.015 + r4 + r_b = 0.105 m) and its
/// inertia that of a 2 (r4 + r_b) = 0.18 m rod, m3 (r4 + r_b)^2 / 3.
PendulumSpec default_pendulum_spec();

}  // namespace armstudy::studies
