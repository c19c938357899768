// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// MuJoCo's own dynamics on a planned motion: the plan's joint torques applied open loop
/// (actuators `motor<i>`, gear 1) through mj_step in the MJCF generated from the case's
/// chain, starting from the plan's initial state, and the joint deviation from the plan
/// recorded over time.
///
/// Torque hold. MuJoCo holds ctrl constant over a step. Each step gets the MEAN of the
/// planned torque over that step (3-point Gauss-Legendre on every piece between the plan's
/// break times, where its torque may jump), so every step's impulse is the plan's.
///
/// Tolerance rule. With the impulse exact, the hold only moves the torque within a step:
/// the position error it leaves per step is at most h^2 / 8 times the variation of
/// M(q)^-1 tau within that step, so over the motion at most h^2 / 8 times the total
/// variation V of M(q)^-1 tau (rad/s^2, summed over the step means) -- second order in h.
/// The check's tolerance is the larger of h^2 V (8 times that bound, room for RK4's O(h^4))
/// and the step's error measured: the open-loop error can grow beyond h^2 V / 8 on a long or
/// many-jointed arm (a 6-link arm of point masses: 3.2e-4 rad against h^2 V = 1.4e-4, falling
/// at order 2.14), so the same replay at 2 h estimates it: an error of order 2 at h is
/// (coarse - fine) / 3, and twice that is tolerated. A wrong torque (e.g. 5 % too large)
/// leaves an error of the order of its effect on the motion, which does not shrink with h:
/// the coarse and fine deviations nearly agree and their difference stays far below it.
///
/// What MuJoCo simulates itself: the rigid-body dynamics of the generated model (mass
/// matrix, Coriolis and centrifugal forces, gravity; masses, centres of mass and inertias
/// are the case's, mjcf_writer.hpp), integrated with RK4 at the step h. What it does not:
/// motors and their electrics (torques are ideal sources), friction, joint limits and
/// contacts (geoms are visual only); nothing holds the tip on the path but the torques.
/// The derivation and the measured deviations: docs/dynamic_replay.md.

#include <functional>
#include <string>
#include <vector>

#include "core/planar_chain.hpp"
#include "core/types.hpp"
#include "studies/common.hpp"

namespace armstudy::scene {

/// The plan at one time: joint angles, rates and torques (chain coordinates).
struct PlannedState {
  core::JointVector q, qd, tau;  ///< (N) rad, rad/s, N m
};
using PlanFunction = std::function<PlannedState(double t)>;

struct DynamicReplayOptions {
  int steps = 2000;   ///< MuJoCo steps over the motion: h = duration / steps (even)
  int records = 201;  ///< samples kept for plots and frames (equal time steps)
  /// times (s) where the planned torque may jump: step means are split there
  std::vector<double> breaks;
  double torque_scale = 1.0;  ///< multiplies every applied torque (1: the plan's)
};

struct DynamicReplay {
  std::string integrator = "RK4";
  double duration = 0;  ///< s
  double timestep = 0;  ///< s, h
  int steps = 0;
  double torque_scale = 1.0;
  std::vector<double> t;                         ///< s, recorded times
  std::vector<core::JointVector> q_plan, q_sim;  ///< rad, at t
  double max_deviation = 0;     ///< rad, max over every step and joint of |q_sim - q_plan|
  double max_deviation_t = 0;   ///< s
  int max_deviation_joint = 0;  ///< 0-based
  double variation = 0;         ///< rad/s^2, V: total variation of M(q)^-1 tau over the step means
  /// rad, the larger of h^2 V and `step_error` (the tolerance rule above)
  double tolerance = 0;
  double excursion = 0;             ///< rad, the plan's largest joint excursion (max - min)
  double coarse_timestep = 0;       ///< s, 2 h
  double coarse_max_deviation = 0;  ///< rad, the same replay at 2 h
  double observed_order = 0;        ///< log2(coarse / fine deviation)
  /// rad, the step's error measured from the two replays: 2 (coarse - fine) / 3 (0 when the
  /// coarse replay deviates less)
  double step_error = 0;
};

/// Replays `plan` over [0, duration] in the chain's generated MJCF (RK4).
/// @throws SceneError when MuJoCo cannot load the model; std::invalid_argument for
/// non-positive duration or fewer than 2 steps.
DynamicReplay replay_torques(const core::PlanarChain& chain, double duration,
                             const PlanFunction& plan, const DynamicReplayOptions& options = {});

/// The check: max deviation <= tolerance (h^2 V), named `name`, `what` naming the motion.
studies::Check replay_check(const DynamicReplay& replay, const std::string& name,
                            const std::string& what);

/// The tolerance rule in one sentence (for results.json and the page).
std::string replay_tolerance_rule();
/// What MuJoCo simulates itself in the replay, and what it does not (one sentence each).
std::string replay_simulates();
std::string replay_does_not_simulate();

}  // namespace armstudy::scene
