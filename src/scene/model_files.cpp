// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/model_files.hpp"

#include <cmath>

#include "studies/throwing/solve.hpp"

namespace armstudy::scene {

ArmScene default_horizontal_scene() {
  core::PlanarChain c;
  c.links = {{0.4, 4.0, 0.2, 0.0, core::uniform_rod_inertia(4.0, 0.4), true},
             {0.2, 2.0, 0.1, 0.0, core::uniform_rod_inertia(2.0, 0.2), true}};
  c.point_masses = {{1, 0.2, 0.0, 1.0}};
  c = core::make_chain(c);
  // an example task: L = 0.5 Lmax, Lmax = 4 sqrt(L1 L2) (4.6), from (0.3, 0) at 100 deg
  const double L = 0.5 * 4 * std::sqrt(0.4 * 0.2);
  const double phi = 100.0 * core::kDeg;
  TableDecor d;
  d.task_start = Eigen::Vector2d(0.3, 0.0);
  d.task_end = *d.task_start + L * Eigen::Vector2d(std::cos(phi), std::sin(phi));
  return horizontal_arm_scene(c, d);
}

ArmScene default_tray_scene() {
  const studies::ThrowingSpec spec;
  TrayDecor d;
  d.ball_radius = spec.arm.rb;
  d.cup_width = spec.tray_width;
  return tray_arm_scene(studies::make_tray_arm(spec.arm), d);
}

}  // namespace armstudy::scene
