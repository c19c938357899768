// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Frames of the placement study: for every program and configuration with an optimum,
/// the arm at its optimal root carrying the payload along the fixed line (drawn in the
/// line's frame P, so the line lies along x from the origin): a strip and a locus.

#include <filesystem>
#include <string>
#include <vector>

#include "cases/case_info.hpp"
#include "scene/arm_scene.hpp"
#include "scene/rendered.hpp"
#include "scene/study_frames.hpp"
#include "studies/placement/result.hpp"
#include "studies/placement/spec.hpp"

namespace armstudy::scene {

/// The scene one optimum's frames are drawn in (line frame P, the arm at its optimal root).
ArmScene placement_scene(const studies::placement::Spec& spec,
                         const studies::placement::ProgramConfig& pc,
                         const cases::RenderOptions& options);

/// The optimum's motion as its strip and locus show it.
SampledMotion placement_motion(const studies::placement::ProgramConfig& pc);

/// Writes placement_<program>_c<configuration>_{strip,locus}.png into `dir` and returns
/// the file names and the animation of each optimum. @throws SceneError (ModelError for an
/// unloadable model).
Rendered render_placement_frames(const studies::placement::Spec& spec,
                                 const studies::placement::Result& result,
                                 const cases::RenderOptions& options,
                                 const std::filesystem::path& dir);

}  // namespace armstudy::scene
