// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Moving pictures of a motion: frames at equal time steps rendered once and written as a
/// sprite sheet (one PNG of every frame in a grid, which the report's stylesheet steps
/// through with CSS, no script) and as a video at the motion's real speed (H.264 MP4
/// through ffmpeg, for slides). write_animation returns the animation as a typed value
/// (scene/rendered.hpp), which the study's render step hands to the run for results.json
/// "animations" (app/run_case.cpp).

#include <filesystem>
#include <string>

#include "scene/rendered.hpp"
#include "scene/study_frames.hpp"

namespace armstudy::scene {

/// Frames an animation renders at most (and at least): the sprite sheet stays a few MB.
inline constexpr int kAnimationMaxFrames = 40;
inline constexpr int kAnimationMinFrames = 8;
/// Frame rate aimed at (frames per second of the motion's own time); a long motion gets
/// fewer, never more than kAnimationMaxFrames in all.
inline constexpr double kAnimationFps = 30;

/// The number of frames and frame rate of an animation of a motion lasting `duration` s:
/// about kAnimationFps, within [kAnimationMinFrames, kAnimationMaxFrames] frames.
int animation_frames(double duration);

/// Renders the animation of `motion` with `sr` into `dir`: the sprite and the still at once,
/// the video by ffmpeg on a thread of its own while this one goes on (the returned
/// animation's get() waits for it). Each frame is labelled with its time and `title`.
/// @throws SceneError when rendering fails; std::runtime_error when a file cannot be written.
PendingAnimation write_animation(SceneRenderer& sr, const SampledMotion& motion,
                                 const std::string& title, const std::filesystem::path& dir,
                                 const std::string& name);

/// The ffmpeg executable: $ARMSTUDY_FFMPEG if set, else "ffmpeg" when it is on PATH
/// (sys::find_on_path); empty when none is found.
std::string find_ffmpeg();

}  // namespace armstudy::scene
