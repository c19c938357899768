// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/pendulum_frames.hpp"
#include "scene/animation.hpp"

#include <algorithm>
#include <cstdio>

#include "core/kinematics.hpp"
#include "scene/arm_scene.hpp"
#include "scene/png_writer.hpp"
#include "scene/study_frames.hpp"

namespace armstudy::scene {

std::vector<PoseSample> pendulum_snapshots(const studies::PendulumResult& result) {
  std::vector<PoseSample> snaps;
  for (size_t k = 0; k < result.snapshot_index.size(); ++k) {
    const int i = result.snapshot_index[k];
    snaps.push_back({result.t[i], result.q[i], result.qd[i]});
  }
  return snaps;
}

ArmScene pendulum_scene(const studies::PendulumSpec& spec, const studies::PendulumResult& result,
                        const cases::RenderOptions& options) {
  const core::PlanarChain chain = studies::make_tray_arm(spec.arm);
  // frame the tray's swing: hinge, cup and ball over every sample, with room for the cup
  const double rb = spec.arm.rb, cup = spec.arm.r4 + spec.arm.rb;
  ViewBox v{1e9, -1e9, 1e9, -1e9};
  auto grow = [&](const Eigen::Vector2d& p, double pad) {
    v.x_min = std::min(v.x_min, p.x() - pad);
    v.x_max = std::max(v.x_max, p.x() + pad);
    v.y_min = std::min(v.y_min, p.y() - pad);
    v.y_max = std::max(v.y_max, p.y() + pad);
  };
  for (size_t i = 0; i < result.t.size(); ++i) {
    const core::ChainPose pose = core::forward_kinematics(chain, result.q[i]);
    grow(pose.p_WJ.col(2), 0.01);
    grow(pose.p_WJ.col(3), cup + 0.01);
    grow(pose.p_WJ.col(4), rb + 0.005);
  }
  TrayDecor decor;
  decor.ball_radius = rb;
  decor.cup_width = 2.0 * core::kPi / 3;
  decor.offscreen = options.frame;
  decor.view = v;
  return tray_arm_scene(chain, decor);
}

Rendered render_pendulum_frames(const studies::PendulumSpec& spec,
                                const studies::PendulumResult& result,
                                const cases::RenderOptions& options,
                                const std::filesystem::path& dir) {
  if (result.snapshot_index.empty()) return {};
  const std::vector<PoseSample> snaps = pendulum_snapshots(result);
  SceneRenderer sr(pendulum_scene(spec, result, options), "pendulum scene",
                   render_settings(options));

  Rendered out;
  std::vector<std::string>& files = out.frames;
  char title[160];
  std::snprintf(title, sizeof title,
                "pendulum (Sato et al. Sec. 3), joints 1, 2 locked; every %.2f s",
                spec.snapshot_step);
  const int columns = snaps.size() > 9 ? 4 : strip_columns(static_cast<int>(snaps.size()));
  write_png(dir / "pendulum_snapshots_strip.png", sr.strip(snaps, title, columns),
            sr.strip_threads());
  files.push_back("pendulum_snapshots_strip.png");
  FrameLabels labels;
  labels.top_left = std::string(title) + "\nball path traced; older snapshots fainter";
  labels.bottom_left = "side view, gravity down; " + grid_caption(kWallGridM);
  write_png(dir / "pendulum_snapshots_locus.png", sr.locus(snaps, result.ball, {}, labels));
  files.push_back("pendulum_snapshots_locus.png");
  {
    SampledMotion m;
    for (size_t i = 0; i < result.t.size(); ++i) {
      if (!m.t.empty() && result.t[i] <= m.t.back()) continue;
      m.t.push_back(result.t[i]);
      m.q.push_back(result.q[i]);
      m.qd.push_back(result.qd[i]);
    }
    if (m.t.size() >= 2)
      out.animations.push_back(write_animation(sr, m, "pendulum, free swing", dir, "pendulum"));
  }
  return out;
}

}  // namespace armstudy::scene
