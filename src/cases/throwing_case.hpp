// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// `throwing:` section of a case file -> studies::ThrowingSpec (and the tray-arm readers
/// shared with the pendulum case). Every key is optional; defaults are Table 1 and Sec. 4
/// of Sato et al. and the choices of docs/assumptions.md where the paper is silent.
///
/// ```yaml
/// throwing:
///   gravity_m_s2: 9.81                 # m/s^2 along -y, > 0 (default 9.81)
///   link1:                             # Table 1 (defaults shown)
///     length_m: 0.080                  # l1, > 0
///     mass_kg: 0.020                   # m1, >= 0
///     com_m: 0.044                     # r1, joint to centre of mass along the link
///     inertia_kg_m2: 1.7e-5            # I_G1 about the centre of mass, >= 0
///   link2: {length_m: 0.115, mass_kg: 0.047, com_m: 0.078, inertia_kg_m2: 8.4e-5}
///   tray:
///     circle_offset_m: 0.015           # hinge to the centre of the ball's circle (l3), > 0
///     mass_kg: 0.018                   # m3, >= 0
///     com_m: 0.028                     # r3, along the tray axis
///     com_lateral_m: 0.0               # r3', off the axis
///     inertia_kg_m2: 1.2e-6            # I_G3, >= 0
///     width_deg: 120                   # lambda of eq. 9: the ball stays in |theta4| <= lambda/2
///   ball:
///     mass_kg: 0.012                   # m4, > 0
///     circle_radius_m: 0.005           # r4, radius of the ball centre's circle, > 0
///     radius_m: 0.010                  # r_b, > 0
///     inertia: solid_sphere            # kg m^2, or solid_sphere = 2/5 m4 r_b^2 (default)
///   motors:                            # both DC motors, eq. 5-7, Table 1
///     kt_Nm_per_A: 0.046               # torque constant, > 0
///     kv_V_s_per_rad: 0.046            # back-emf constant, > 0
///     resistance_ohm: 3.5              # Ra, > 0
///     viscous_Nm_s_per_rad: 7.9e-5     # Dm, >= 0
///     coulomb_Nm: 0.0013               # tau_f, >= 0
///     rotor_inertia_kg_m2: 0.0         # Im (missing from Table 1), >= 0
///     motor2: on_link1                 # on_link1 (drives theta2) or on_base (theta1+theta2)
///     voltage_max_V: 24                # limit, > 0 (motors rated 24 V)
///     current_max_A: 5.0               # limit, > 0 (about twice the 2.5 A of 60 W at 24 V)
///     power_max_W: 60                  # limit on |e i| per motor, > 0 (motors rated 60 W)
///     count_regeneration: true         # eq. 7 signed (true) or only e i > 0 counted
///   task:
///     start_deg: [-45, -45, 0, 0]      # theta1..theta4 at rest
///     release_deg: [65, -35, -52.5]    # theta1, theta2 met exactly; theta3 via the dynamics
///     release_rate_rad_s: [13.9, -1.1] # theta1', theta2' at release
///     duration_s: 0.8                  # tf, > 0
///     landing_height_m: 0.0            # the flight ends at this height (y)
///   constraints:                       # both optimisers and the checks (docs/throwing.md)
///     contact_margin_N: 0.02           # tray's normal force on the ball >= this, >= 0
///     friction_coefficient: 0.5        # mu: rolling needs |F_t| <= mu N, 0.001..10
///     release_tolerance_deg: 1.0       # |theta3(tf) - release| allowed, > 0
///     backoff: 0.02                    # optimisers keep each normalised constraint this far
///                                      # inside its limit, 0..0.2
///   idp:
///     stages: 16                       # P, 2..64
///     steps_per_stage: 20              # RK4 steps per stage, 1..400
///     iterations: 6                    # per pass, 1..1000
///     max_passes: 40                   # budget: passes at most, 1..1000
///     tolerance: 1.0e-3                # converged: a pass gains less than this (relative)
///     quiet_passes: 2                  # ... in this many passes in a row, 1..100
///     restore: 0.8                     # region factor between passes, (0, 1]
///     candidates: 5                    # R per stage node, 1..200
///     shrink: 0.7                      # region factor per iteration, (0, 1)
///     region_rad_s: [1, 1]             # initial half-width per joint, > 0
///     seed: 1                          # std::mt19937 seed of the first run
///     seeds: 4                         # runs with seeds seed, seed + 1, ..., 1..64
///   nlopt:
///     enabled: true                    # SLSQP beside IDP
///     max_evaluations: 400             # budget: SLSQP iterations, 1..10000
///     max_time_s: 900                  # wall-clock safety net (a run ending on it is not
///     converged), > 0 ftol_rel: 1.0e-6                 # converged: relative energy change below
///     this xtol_rel: 1.0e-6                 # or relative rate change below this
///     fd_step_rad_s: 1.0e-5            # central-difference step, > 0
///     exact_gradient: false            # exact derivatives in place of central differences
///   checks:
///     replay_tolerance_rad: 0.002      # open-loop replay vs plan, > 0
///     allow_not_converged: false       # true: a run ending on its budget does not fail
///     refinement: 4                    # optimum re-checked with this many x the steps, 2..16
///   threads: 2                         # 1..64
/// ```

#include "cases/tray_arm_case.hpp"
#include "cases/yaml_reader.hpp"
#include "studies/throwing/solve.hpp"

namespace armstudy::cases {

/// The work and memory `spec` asks for (cases/budget.hpp), reported at `mark`.
Demand throwing_demand(const studies::ThrowingSpec& spec, const YAML::Mark& mark);

/// Reads the `throwing:` section (absent: all defaults). Errors go to root's Diagnostics.
studies::ThrowingSpec load_throwing_spec(Map& root);

}  // namespace armstudy::cases
