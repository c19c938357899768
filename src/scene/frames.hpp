// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Frame strips (N poses at given times, one PNG, time labels) and stroboscopic loci
/// (several poses superimposed, older ones fainter, the end-effector path traced).

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "scene/arm_scene.hpp"
#include "scene/chain_map.hpp"
#include "scene/frame_worker.hpp"
#include "scene/image.hpp"
#include "scene/mujoco_model.hpp"
#include "scene/phase_times.hpp"
#include "scene/renderer.hpp"
#include "scene/replay.hpp"

namespace armstudy::scene {

/// A loaded arm scene with its renderer: everything needed to draw poses of one motion.
class SceneRenderer {
 public:
  /// Loads `scene` (source names it in errors) and opens a renderer of width x height px.
  /// @throws SceneError (MuJoCo's message, OSMesa failures suggesting --no-render).
  SceneRenderer(const ArmScene& scene, const std::string& source, const RenderSettings& settings);
  /// Gives its frame helpers back to this thread's pool (FrameWorker::release).
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  /// One frame of pose `s` (kinematic replay) with labels.
  Image frame(const PoseSample& s, const FrameLabels& labels);

  /// Frames of `samples` labelled `labels` (one each), in order, after a replay begins
  /// (mj_resetData). They render on strip_threads() processes: this one and helpers
  /// (frame_worker.hpp) started at the first call and kept, each with its own model, OSMesa
  /// context and llvmpipe; a frame is a function of its pose alone, so the frames are the
  /// same on any number of processes. Where no helper starts, all render here.
  std::vector<Image> frames(std::span<const PoseSample> samples,
                            std::span<const FrameLabels> labels);
  /// A strip: one frame per sample (frames()), labelled "t = 0.130 s" (plus `title` on the
  /// first), tiled `columns` per row.
  Image strip(std::span<const PoseSample> samples, const std::string& title, int columns);
  /// Processes frames() and strip() render on (default 1; at most 8). llvmpipe rasterises
  /// every context of a process through one queue (the screen's LP_NUM_THREADS threads),
  /// so a second drawing thread in this process measured only ~1.1x; a helper process has
  /// a rasteriser of its own (tests/bench/scene_bench.cpp BM_Strip16Frames640x480).
  int strip_threads() const { return strip_threads_; }
  void set_strip_threads(int threads);

  /// Colours of the locus's extra drawings (RGBA, 0-1).
  struct LocusStyle {
    float path_rgba[4] = {0.10f, 0.10f, 0.12f, 1.0f};
    float flight_rgba[4] = {0.86f, 0.14f, 0.14f, 1.0f};
    double faintest = 0.22;    ///< colour weight of the oldest pose (1: full colour)
    double path_radius = 0.3;  ///< of the traced path, in link radii (4% of the longest link)
  };

  /// A stroboscopic locus: every pose of `samples` superimposed, the oldest faintest and
  /// the last in full colour, the end-effector `path` (world, m) traced as a dark line and
  /// an optional `flight` (world, m) drawn as a dotted trail of the thrown object.
  Image locus(std::span<const PoseSample> samples, std::span<const Eigen::Vector2d> path,
              std::span<const Eigen::Vector2d> flight, const FrameLabels& labels,
              const LocusStyle& style);
  Image locus(std::span<const PoseSample> samples, std::span<const Eigen::Vector2d> path,
              std::span<const Eigen::Vector2d> flight, const FrameLabels& labels) {
    return locus(samples, path, flight, labels, LocusStyle{});
  }

  /// The loaded model, its coordinate map and the renderer (camera of the last frame).
  MujocoModel& model() { return model_; }
  const ChainMap& map() const { return map_; }
  Renderer& renderer() { return renderer_; }

 private:
  std::optional<PhaseScope> load_phase_;  // times the members' construction (phase_times.hpp)
  core::PlanarChain chain_;
  MujocoModel model_;
  ChainMap map_;
  Renderer renderer_;
  ArmScene scene_;  // what the helpers load
  std::string source_;
  RenderSettings settings_;
  int strip_threads_ = 1;
  std::vector<std::unique_ptr<FrameWorker>> workers_;
  bool workers_failed_ = false;  // a helper did not start: draw here from then on

  // frames() with each frame handed to `take` (index, image) as it is drawn or received,
  // from the thread that has it: different frames may be taken at once, each once
  void draw_frames(std::span<const PoseSample> samples, std::span<const FrameLabels> labels,
                   const std::function<void(size_t, Image&&)>& take);
};

/// The processes a SceneRenderer made from now on draws its frames on (its initial
/// strip_threads()): 1 until set. armstudy run sets it to the cores each of its parallel
/// cases has (2 for one case on two cores, 1 with --jobs 2 there).
void set_default_frame_processes(int processes);
int default_frame_processes();

/// Segments of a traced path and dots of a flight a locus draws at most (longer ones are
/// drawn through evenly spaced points of them): the scene holds a few thousand geoms.
inline constexpr size_t kMaxTracedSegments = 1000;
inline constexpr size_t kMaxFlightDots = 500;

/// Indices of at most `at_most` points of n spread evenly, first and last included (all
/// of 0..n-1 when n <= at_most).
std::vector<size_t> evenly_spaced(size_t n, size_t at_most);

/// "t = 0.130 s".
std::string time_label(double t);

/// The motion sampled at increasing times `t` with states q (and qd, optional: empty or the
/// same size), evaluated at the times `at` by linear interpolation between neighbouring
/// samples; times outside [t.front(), t.back()] take the end state but keep their own time.
/// @throws SceneError if there are no samples or q and t differ in size.
std::vector<PoseSample> resample(std::span<const double> t, std::span<const core::JointVector> q,
                                 std::span<const core::JointVector> qd, std::span<const double> at);

/// n times spread evenly over [t0, t1] (both included; n >= 2, or {t0} for n == 1).
std::vector<double> even_times(double t0, double t1, int n);

/// Columns for a strip of n frames: up to 3 per row.
int strip_columns(int n);

}  // namespace armstudy::scene
