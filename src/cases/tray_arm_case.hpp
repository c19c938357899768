// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The keys of the tray arm (studies/tray_arm.hpp) that the pendulum and the throwing case
/// files share: `link1`, `link2`, `tray`, `ball` and `gravity_m_s2`.

#include "cases/yaml_reader.hpp"
#include "studies/tray_arm.hpp"

namespace armstudy::cases {

/// Reads `link1`, `link2`, `tray`, `ball` and `gravity_m_s2` of a section into `arm` (keys
/// absent keep `arm`'s values). If `width` is given, `tray.width_deg` is read into it (rad;
/// absent keeps its value); otherwise that key is unknown. Errors go to the Diagnostics.
void read_tray_arm(Map& section, studies::TrayArmParams& arm, double* width);

}  // namespace armstudy::cases
