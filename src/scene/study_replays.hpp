// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The placement and time-optimal plans as functions of time for MuJoCo's dynamic replay
/// (dynamic_replay.hpp): the time-optimal study's exact solution (constant s'' between its
/// grid points, torques by inverse dynamics along it), and each placement optimum's motion
/// program along its line (closed-form IK and inverse dynamics, studies/placement/arm2.hpp).

#include <vector>

#include "core/motion_program.hpp"
#include "scene/dynamic_replay.hpp"
#include "studies/placement/result.hpp"
#include "studies/placement/spec.hpp"
#include "studies/time_optimal/result.hpp"
#include "studies/time_optimal/spec.hpp"

namespace armstudy::scene {

/// MuJoCo's replay of the exact time-optimal solution (its node times are the breaks).
/// `torque_scale` multiplies the applied torques (1: the plan's; tests use others).
/// @throws std::invalid_argument unless the result is solved; SceneError from MuJoCo.
DynamicReplay replay_time_optimal(const studies::time_optimal::Spec& spec,
                                  const studies::time_optimal::Result& result,
                                  double torque_scale = 1.0);

/// The replay of one placement optimum.
struct PlacementReplay {
  core::MotionProgram program = core::MotionProgram::kCycloidal;
  int configuration = 1;
  DynamicReplay replay;
};

/// MuJoCo's replay of every found placement optimum (the refined one), in result order.
std::vector<PlacementReplay> replay_placement(const studies::placement::Spec& spec,
                                              const studies::placement::Result& result,
                                              double torque_scale = 1.0);

}  // namespace armstudy::scene
