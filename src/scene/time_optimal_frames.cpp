// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/time_optimal_frames.hpp"
#include "scene/animation.hpp"

#include <cstdio>

#include "scene/arm_scene.hpp"
#include "scene/study_frames.hpp"

namespace armstudy::scene {
namespace to = studies::time_optimal;

ArmScene time_optimal_scene(const to::Spec& spec, const to::Result& result,
                            const cases::RenderOptions& options) {
  TableDecor decor;
  for (int k = 0; k < result.path_p.cols(); ++k) decor.task_path.push_back(result.path_p.col(k));
  decor.offscreen = options.frame;
  // the limits the study used, for model.xml
  decor.torque_limit.assign(spec.torque_limit.data(),
                            spec.torque_limit.data() + spec.torque_limit.size());
  decor.velocity_limit.assign(spec.velocity_limit.data(),
                              spec.velocity_limit.data() + spec.velocity_limit.size());
  if (spec.space == to::PathSpace::kJoint) decor.joint_range = spec.joint_path.range;
  decor.origin = spec.arm_origin;
  return horizontal_arm_scene(spec.chain, decor);
}

SampledMotion time_optimal_motion(const to::Result& result) {
  SampledMotion m;
  m.t = result.motion_t;
  for (int k = 0; k < result.motion_q.cols(); ++k)
    m.q.push_back(core::JointVector(result.motion_q.col(k)));
  if (result.motion_qd.cols() == result.motion_q.cols())
    for (int k = 0; k < result.motion_qd.cols(); ++k)
      m.qd.push_back(core::JointVector(result.motion_qd.col(k)));
  return m;
}

Rendered render_time_optimal_frames(const to::Spec& spec, const to::Result& result,
                                    const cases::RenderOptions& options,
                                    const std::filesystem::path& dir) {
  const int n = static_cast<int>(result.motion_t.size());
  if (n < 2 || result.motion_q.cols() != n) return {};
  SceneRenderer sr(time_optimal_scene(spec, result, options), "time-optimal scene",
                   render_settings(options));
  const SampledMotion m = time_optimal_motion(result);
  std::vector<Eigen::Vector2d> path;
  for (int k = 0; k < result.motion_p.cols(); ++k) path.push_back(result.motion_p.col(k));
  char title[160];
  // (the motion shown is the exact solver's on its grid; the converged duration, the
  // headline, is extrapolated from it and finer and coarser grids)
  std::snprintf(title, sizeof title, "exact, %d-point %sgrid: %.4f s",
                static_cast<int>(result.solvers.empty() ? 0 : result.solvers.front().node_s.size()),
                result.grid.graded ? "graded " : "",
                result.motion_t.back() - result.motion_t.front());
  Rendered out;
  std::vector<std::string>& files = out.frames;
  files.push_back(write_strip(sr, m, options.frames, title, dir, "time_optimal"));
  FrameLabels labels;
  labels.top_left = std::string(title) + "\nequal time steps: dense where slow";
  labels.bottom_left =
      (spec.chain.gravity != 0.0 ? "vertical plane, gravity down the image; " : "top view; ") +
      grid_caption(kTableGridM);
  files.push_back(write_locus(sr, m, 15, path, {}, labels, dir, "time_optimal"));
  out.animations.push_back(write_animation(sr, m, "time-optimal (exact)", dir, "time_optimal"));
  return out;
}

}  // namespace armstudy::scene
