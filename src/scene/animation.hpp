#pragma once
/// Moving pictures of a motion: frames at equal time steps rendered once and written as a
/// sprite sheet (one PNG of every frame in a grid, which the report's stylesheet steps
/// through with CSS, no script) and as a video at the motion's real speed (H.264 MP4
/// through ffmpeg, for slides). Each animation leaves a manifest `<name>.anim.json` beside
/// its files, which the run collects into results.json "animations" (app/run_case.cpp).

#include <filesystem>
#include <string>

#include "scene/study_frames.hpp"

namespace armstudy::scene {

/// Frames an animation renders at most (and at least): the sprite sheet stays a few MB.
inline constexpr int kAnimationMaxFrames = 40;
inline constexpr int kAnimationMinFrames = 8;
/// Frame rate aimed at (frames per second of the motion's own time); a long motion gets
/// fewer, never more than kAnimationMaxFrames in all.
inline constexpr double kAnimationFps = 30;

/// What one animation wrote.
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

/// The number of frames and frame rate of an animation of a motion lasting `duration` s:
/// about kAnimationFps, within [kAnimationMinFrames, kAnimationMaxFrames] frames.
int animation_frames(double duration);

/// Renders the animation of `motion` with `sr` into `dir`: the sprite and the still at once;
/// the video (ffmpeg, on a thread of its own while this one goes on) and the manifest by
/// the time finish_animations() returns. Each frame is labelled with its time and `title`.
/// @throws SceneError when rendering fails; std::runtime_error when a file cannot be written.
void write_animation(SceneRenderer& sr, const SampledMotion& motion, const std::string& title,
                     const std::filesystem::path& dir, const std::string& name);

/// Waits for the videos and manifests this thread's write_animation calls left (a video
/// ffmpeg could not make is a note in its manifest, not an error). Call it before the
/// manifests are read and before their folder goes. @throws std::runtime_error when a
/// manifest could not be written (the first such error; every video is waited for).
void finish_animations();

/// The ffmpeg executable: $ARMSTUDY_FFMPEG if set, else "ffmpeg" when it is on PATH
/// (sys::find_on_path); empty when none is found.
std::string find_ffmpeg();

}  // namespace armstudy::scene
