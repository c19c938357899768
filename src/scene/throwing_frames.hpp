// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Frames of the throwing study (003 Sec. 4, Fig. 7): the optimised (IDP) motion of the tray
/// arm from rest to release, as a strip and as a stroboscopic locus with the ball's path,
/// and the locus again framing the ball's ballistic flight after release.

#include <filesystem>
#include <string>
#include <vector>

#include "cases/case_info.hpp"
#include "scene/arm_scene.hpp"
#include "scene/rendered.hpp"
#include "scene/study_frames.hpp"
#include "studies/throwing/solve.hpp"

namespace armstudy::scene {

/// A motion's series with strictly increasing times (the series repeats every interior
/// stage boundary), as the strip and locus show it.
SampledMotion throwing_motion(const studies::ThrowSeries& series);

/// The scene of the IDP motion's strip and locus (the tray arm framing the motion).
ArmScene throwing_scene(const studies::ThrowingSpec& spec, const studies::ThrowingResult& result,
                        const cases::RenderOptions& options);

/// Writes throwing_idp_{strip,locus}.png and throwing_flight_locus.png (when the flight
/// has a path) into `dir`; returns the file names and the animation of each motion.
/// @throws SceneError.
Rendered render_throwing_frames(const studies::ThrowingSpec& spec,
                                const studies::ThrowingResult& result,
                                const cases::RenderOptions& options,
                                const std::filesystem::path& dir);

}  // namespace armstudy::scene
