// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// What a study's render step hands back to the run (StudyRun::render, app/pipeline.hpp):
/// the frames' file names and the animations as typed values, nothing written for the run to
/// find. Light on purpose (no MuJoCo or OSMesa): the pipeline interface includes it.

#include <future>
#include <string>
#include <vector>

namespace armstudy::scene {

/// What one animation wrote (scene/animation.hpp), beside the frames.
struct Animation {
  std::string name;    ///< stem of its files, e.g. "throwing_idp"
  std::string title;   ///< which motion, in words
  std::string sprite;  ///< "<name>_anim.png": frames in a grid, left to right, top to bottom
  std::string video;   ///< "<name>.mp4" at real speed; empty when ffmpeg is missing
  std::string still;   ///< "<name>_still.png": the last frame (the print and no-motion view)
  int frames = 0;
  int columns = 0;                        ///< of the sprite grid
  int frame_width = 0, frame_height = 0;  ///< px of one sprite frame
  double fps = 0;         ///< frames per second of real time (frame k at t0 + k / fps)
  double duration_s = 0;  ///< of the motion
  std::string note;       ///< why a part is missing (e.g. no video: ffmpeg not found)
};

/// An animation whose sprite and still are written and whose video ffmpeg is encoding on a
/// thread of its own: get() waits for the video and gives the whole Animation (its `video`
/// or its `note` set). Destroying it waits for the video too, so no encoder outlives it.
using PendingAnimation = std::future<Animation>;

/// The output of a study's render step.
struct Rendered {
  std::vector<std::string> frames;           ///< the frame images written, relative to the folder
  std::vector<PendingAnimation> animations;  ///< in the order they were rendered
};

/// Waits for every video of `pending` and returns the animations in their order (a video
/// ffmpeg could not make is a note, not an error); `pending` is left empty.
/// @throws std::runtime_error when an animation's task failed (the first such error; every
/// video is waited for first).
std::vector<Animation> finish_animations(std::vector<PendingAnimation>& pending);

}  // namespace armstudy::scene
