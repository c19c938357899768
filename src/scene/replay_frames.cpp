// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/replay_frames.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/kinematics.hpp"
#include "scene/arm_scene.hpp"
#include "scene/png_writer.hpp"
#include "scene/study_frames.hpp"

namespace armstudy::scene {
namespace {
constexpr float kSimRgba[4] = {0.85f, 0.05f, 0.80f, 1.0f};  // magenta: the task line is red

std::string sci(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2g", v);
  return b;
}
}  // namespace

std::string write_replay_strip(SceneRenderer& sr, const core::PlanarChain& chain,
                               const DynamicReplay& r, int frames, const std::string& title,
                               const std::filesystem::path& dir, const std::string& name) {
  const std::vector<double> at = even_times(r.t.front(), r.t.back(), std::max(2, frames));
  const std::vector<core::JointVector> none;
  const std::vector<PoseSample> plan = resample(r.t, r.q_plan, none, at);
  const std::vector<PoseSample> sim = resample(r.t, r.q_sim, none, at);
  double rad = 0;
  for (const auto& l : chain.links) rad = std::max(rad, 0.04 * l.length);
  begin_replay(sr.model());
  std::vector<Image> tiles;
  for (size_t k = 0; k < at.size(); ++k) {
    set_pose(sr.model(), sr.map(), plan[k]);
    // the simulated pose above the planned arm
    const core::ChainPose pose = core::forward_kinematics(chain, sim[k].q);
    const double z = 2.5 * rad;
    std::vector<mjvGeom> extra;
    for (int j = 0; j + 1 < pose.p_WJ.cols(); ++j) {
      const Eigen::Vector3d a(pose.p_WJ(0, j), pose.p_WJ(1, j), z),
          b(pose.p_WJ(0, j + 1), pose.p_WJ(1, j + 1), z);
      extra.push_back(segment_geom(a, b, 0.22 * rad, kSimRgba));
    }
    for (int j = 0; j < pose.p_WJ.cols(); ++j)
      extra.push_back(
          sphere_geom(Eigen::Vector3d(pose.p_WJ(0, j), pose.p_WJ(1, j), z), 0.5 * rad, kSimRgba));
    FrameLabels l;
    l.top_left = time_label(at[k]) +
                 ", |dq| = " + sci((sim[k].q - plan[k].q).cwiseAbs().maxCoeff()) + " rad";
    if (k == 0) l.bottom_left = title;
    tiles.push_back(sr.renderer().render(sr.model().data(), l, extra));
  }
  const std::string file = name + "_strip.png";
  write_png(dir / file,
            tile(tiles, strip_columns(static_cast<int>(at.size())), 8, Rgb{255, 255, 255}),
            sr.strip_threads());
  return file;
}

std::vector<std::string> render_time_optimal_replay(const studies::time_optimal::Spec& spec,
                                                    const studies::time_optimal::Result& result,
                                                    const DynamicReplay& replay,
                                                    const cases::RenderOptions& options,
                                                    const std::filesystem::path& dir) {
  if (replay.t.size() < 2) return {};
  TableDecor decor;
  for (int k = 0; k < result.path_p.cols(); ++k) decor.task_path.push_back(result.path_p.col(k));
  decor.offscreen = options.frame;
  SceneRenderer sr(horizontal_arm_scene(spec.chain, decor), "time-optimal replay scene",
                   render_settings(options));
  char title[200];
  std::snprintf(title, sizeof title, "planned (arm); MuJoCo mj_step in magenta\nmax |dq| %.2g rad",
                replay.max_deviation);
  return {write_replay_strip(sr, spec.chain, replay, options.frames, title, dir,
                             "time_optimal_planned-and-simulated")};
}

std::vector<std::string> render_placement_replay(const studies::placement::Spec& spec,
                                                 const studies::placement::Result& result,
                                                 const std::vector<PlacementReplay>& replays,
                                                 const cases::RenderOptions& options,
                                                 const std::filesystem::path& dir) {
  std::vector<std::string> files;
  for (const PlacementReplay& rp : replays) {
    const studies::placement::ProgramConfig* pc = nullptr;
    for (const auto& c : result.cases)
      if (c.found && c.program == rp.program && c.configuration == rp.configuration) pc = &c;
    if (!pc || rp.replay.t.size() < 2) continue;
    // the line frame P, as the placement frames draw it (root at the origin of frame A)
    const Eigen::Vector2d S = pc->placement.start, F = pc->placement.end;
    const double phi = std::atan2(F.y() - S.y(), F.x() - S.x());
    const Eigen::Rotation2Dd to_P(-phi);
    core::PlanarChain chain = spec.chain;
    chain.base = to_P * (Eigen::Vector2d::Zero() - S);
    chain.base_angle = -phi;
    TableDecor decor;
    decor.task_start = Eigen::Vector2d::Zero();
    decor.task_end = to_P * (F - S);
    decor.offscreen = options.frame;
    SceneRenderer sr(horizontal_arm_scene(chain, decor), "placement replay scene",
                     render_settings(options));
    char title[200];
    std::snprintf(
        title, sizeof title,
        "%s, configuration %d: planned (arm)\nMuJoCo mj_step in magenta: max |dq| %.2g rad",
        std::string(core::program_label(rp.program)).c_str(), rp.configuration,
        rp.replay.max_deviation);
    files.push_back(write_replay_strip(sr, chain, rp.replay, options.frames, title, dir,
                                       "placement_" + std::string(core::program_name(rp.program)) +
                                           "_c" + std::to_string(rp.configuration) +
                                           "_planned-and-simulated"));
  }
  return files;
}

}  // namespace armstudy::scene
