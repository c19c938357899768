// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Frames of the time-optimal study: the exact (reachability) solution at equal time steps
/// along its path (a strip), and a locus of all of them with the path traced.

#include <filesystem>
#include <string>
#include <vector>

#include "cases/case_info.hpp"
#include "scene/arm_scene.hpp"
#include "scene/rendered.hpp"
#include "scene/study_frames.hpp"
#include "studies/time_optimal/result.hpp"
#include "studies/time_optimal/spec.hpp"

namespace armstudy::scene {

/// The scene the frames are drawn in: the case's arm with the path traced (model.xml).
ArmScene time_optimal_scene(const studies::time_optimal::Spec& spec,
                            const studies::time_optimal::Result& result,
                            const cases::RenderOptions& options);

/// The exact solution at equal time steps, as the strip and locus show it.
SampledMotion time_optimal_motion(const studies::time_optimal::Result& result);

/// Writes time_optimal_{strip,locus}.png into `dir`; returns the file names and its
/// animation (time_optimal). @throws SceneError.
Rendered render_time_optimal_frames(const studies::time_optimal::Spec& spec,
                                    const studies::time_optimal::Result& result,
                                    const cases::RenderOptions& options,
                                    const std::filesystem::path& dir);

}  // namespace armstudy::scene
