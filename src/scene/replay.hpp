// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Replaying a chain's motion in its MuJoCo model: kinematic (the computed qpos/qvel,
/// then mj_forward) and simulated (mj_step, for passive systems).

#include <vector>

#include "core/types.hpp"
#include "scene/chain_map.hpp"
#include "scene/mujoco_model.hpp"

namespace armstudy::scene {

/// One state of a motion.
struct PoseSample {
  double t = 0;          ///< s
  core::JointVector q;   ///< (N) rad
  core::JointVector qd;  ///< (N) rad/s (empty: zero)
};

/// Starts a replay: mj_resetData (clears warm starts, time and controls).
void begin_replay(MujocoModel& mm);

/// Kinematic replay of one sample: qpos = J q, qvel = J qd, time = t, then mj_forward.
void set_pose(MujocoModel& mm, const ChainMap& map, const PoseSample& s);

/// Simulated replay of a passive motion (zero controls): resets, starts from `start`, and
/// steps with the model's integrator and timestep; returns the chain state at each of
/// `times` (s, increasing, >= start.t; each rounded to the nearest step).
std::vector<PoseSample> simulate(MujocoModel& mm, const ChainMap& map, const PoseSample& start,
                                 const std::vector<double>& times);

}  // namespace armstudy::scene
