// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The MJCF files of models/: both arms generated from their default parameters (the
/// thesis arm of 000 Ch. 9 with an example task line; the tray arm of 003 Table 1 with the
/// throwing study's defaults). tests/scene/models_test.cpp checks that the committed files
/// equal what this code generates (ARMSTUDY_UPDATE_MODELS=1 rewrites them).

#include <string>

#include "scene/arm_scene.hpp"

namespace armstudy::scene {

/// The horizontal 2-link arm of 000 Ch. 9 (L1 = 0.4 m, m1 = 4 kg, L2 = 0.2 m, m2 = 2 kg,
/// rods, 1 kg payload) on its table, with an example line of length 0.5 Lmax from (0.3, 0)
/// m at 100 deg.
ArmScene default_horizontal_scene();

/// The tray arm of 003 (Table 1, ball rolling in a cup of width 2 pi / 3) in its plane.
ArmScene default_tray_scene();

/// File names in models/.
inline constexpr const char* kHorizontalModelFile = "horizontal_arm.xml";
inline constexpr const char* kTrayModelFile = "tray_arm.xml";

}  // namespace armstudy::scene
