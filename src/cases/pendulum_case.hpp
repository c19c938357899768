// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// `pendulum:` section of a case file -> studies::PendulumSpec. Every key is optional;
/// defaults are Sec. 3 of Sato et al. and the choices documented in
/// studies::default_pendulum_spec().
///
/// ```yaml
/// pendulum:
///   gravity_m_s2: 9.81              # m/s^2 along -y, > 0
///   locked_deg: [0, 0]              # theta1, theta2 held fixed
///   start_deg: [-90, -36]           # theta3, theta4 at t = 0
///   start_rate_deg_s: [0, 0]        # theta3', theta4' at t = 0
///   duration_s: 2.0                 # > 0, <= 60
///   sample_s: 0.005                 # time series spacing, > 0
///   snapshot_s: 0.13                # snapshot spacing (Fig. 2), > 0
///   rtol: 1.0e-12                   # DOPRI5 relative tolerance, in [1e-14, 1e-3]
///   atol: 1.0e-12                   # DOPRI5 absolute tolerance, in [1e-16, 1e-3]
///   drift_tolerance: 1.0e-8         # allowed relative energy drift (check), > 0
///   link1: {length_m: 0.080, mass_kg: 0.020, com_m: 0.044, inertia_kg_m2: 1.7e-5}
///   link2: {length_m: 0.115, mass_kg: 0.047, com_m: 0.078, inertia_kg_m2: 8.4e-5}
///   tray:                           # m3 = 0.109 kg (Sec. 3); the rest is chosen
///     circle_offset_m: 0.015        # hinge to the ball circle's centre
///     mass_kg: 0.109
///     com_m: 0.105                  # the bottom of the cup: 0.015 + r4 + r_b
///     com_lateral_m: 0.0
///     inertia_kg_m2: 2.943e-4       # a 0.18 m rod: m3 (r4 + r_b)^2 / 3
///   ball:
///     mass_kg: 0.122                # m4 (Sec. 3)
///     circle_radius_m: 0.075        # r4 (Sec. 3)
///     radius_m: 0.015               # r_b (Sec. 3)
///     inertia: solid_sphere         # or kg m^2
/// ```

#include "cases/yaml_reader.hpp"
#include "studies/pendulum/solve.hpp"

namespace armstudy::cases {

/// Snapshots (duration_s / snapshot_s + 1) a pendulum case may ask for: the strip and the
/// locus draw each one.
inline constexpr int kMaxPendulumSnapshots = 100;

/// Reads the `pendulum:` section (absent: all defaults). Errors go to root's Diagnostics;
/// its work (samples) and its strip's frames are recorded as a Demand (cases/budget.hpp).
studies::PendulumSpec load_pendulum_spec(Map& root);

}  // namespace armstudy::cases
