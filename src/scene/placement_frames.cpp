// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/placement_frames.hpp"
#include "scene/animation.hpp"

#include <cmath>
#include <cstdio>

#include "scene/arm_scene.hpp"
#include "scene/study_frames.hpp"

namespace armstudy::scene {
namespace pl = studies::placement;

ArmScene placement_scene(const pl::Spec& spec, const pl::ProgramConfig& pc,
                         const cases::RenderOptions& options) {
  // the line frame P: origin at S, x along the line; the arm frame A is rotated by phi
  const Eigen::Vector2d S = pc.placement.start, F = pc.placement.end;
  const double phi = std::atan2(F.y() - S.y(), F.x() - S.x());
  const Eigen::Rotation2Dd to_P(-phi);
  core::PlanarChain chain = spec.chain;
  chain.base = to_P * (chain.base - S);
  chain.base_angle = chain.base_angle - phi;
  TableDecor decor;
  decor.task_start = Eigen::Vector2d::Zero();
  decor.task_end = to_P * (F - S);
  decor.offscreen = options.frame;
  if (spec.torque_limit) decor.torque_limit = {(*spec.torque_limit)[0], (*spec.torque_limit)[1]};
  decor.origin = spec.arm_origin;
  return horizontal_arm_scene(chain, decor);
}

SampledMotion placement_motion(const pl::ProgramConfig& pc) {
  SampledMotion m;
  m.t = pc.series.t;
  for (size_t k = 0; k < pc.series.t.size(); ++k) {
    m.q.push_back(core::JointVector(pc.series.q[k]));
    m.qd.push_back(core::JointVector(pc.series.qd[k]));
  }
  return m;
}

Rendered render_placement_frames(const pl::Spec& spec, const pl::Result& result,
                                 const cases::RenderOptions& options,
                                 const std::filesystem::path& dir) {
  Rendered out;
  std::vector<std::string>& files = out.frames;
  for (const pl::ProgramConfig& pc : result.cases) {
    if (!pc.found || pc.series.t.size() < 2) continue;
    const Eigen::Vector2d S = pc.placement.start, F = pc.placement.end;
    const double phi = std::atan2(F.y() - S.y(), F.x() - S.x());
    const Eigen::Rotation2Dd to_P(-phi);
    SceneRenderer sr(placement_scene(spec, pc, options), "placement scene",
                     render_settings(options));
    const SampledMotion m = placement_motion(pc);
    std::vector<Eigen::Vector2d> path;
    for (const Eigen::Vector2d& p : pc.series.tip) path.push_back(to_P * (p - S));

    const std::string name = "placement_" + std::string(core::program_name(pc.program)) + "_c" +
                             std::to_string(pc.configuration);
    // a withheld energy is never printed (a line on the inner circle, or not converged)
    char energy[48];
    if (pc.refined.convergence.energy_withheld())
      std::snprintf(energy, sizeof energy, "singular: energy not converged");
    else
      std::snprintf(energy, sizeof energy, "%.3f J", pc.refined.reported_metrics().energy);
    char title[200];
    // short enough for the frame at print size (the locus names the root)
    std::snprintf(title, sizeof title, "%s, config. %d: %s",
                  std::string(core::program_label(pc.program)).c_str(), pc.configuration, energy);
    files.push_back(write_strip(sr, m, options.frames, title, dir, name));
    FrameLabels labels;
    char line2[160];
    std::snprintf(line2, sizeof line2, "optimal root (%.3f, %.3f) m: %s", pc.refined.root.x(),
                  pc.refined.root.y(), energy);
    labels.top_left = std::string(core::program_label(pc.program)) + ", configuration " +
                      std::to_string(pc.configuration) + "\n" + line2;
    labels.bottom_left = "top view; line fixed, root chosen; " + grid_caption(kTableGridM);
    // the path is the task line: trace it thin so that the red line shows around it
    SceneRenderer::LocusStyle style;
    style.path_radius = 0.12;
    files.push_back(write_locus(sr, m, 9, path, {}, labels, dir, name, style));
    out.animations.push_back(write_animation(sr, m,
                                             std::string(core::program_label(pc.program)) +
                                                 ", configuration " +
                                                 std::to_string(pc.configuration),
                                             dir, name));
  }
  return out;
}

}  // namespace armstudy::scene
