// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
// A moving pose of the default tray arm (4 joints: both links, the tray and the ball) at
// time t, for the scene tests and benchmarks: every joint moves, the tray and ball swing.

#include <cmath>

#include "scene/replay.hpp"

namespace armstudy::testing {

inline scene::PoseSample tray_arm_pose(double t) {
  scene::PoseSample s;
  s.t = t;
  s.q = core::JointVector(4);
  s.q << -0.8 + 1.5 * t, -0.8 + 0.4 * t, 0.3 * std::sin(6 * t), 0.5 * std::sin(9 * t);
  return s;
}

}  // namespace armstudy::testing
