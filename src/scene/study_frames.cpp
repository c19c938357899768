// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/study_frames.hpp"

#include <algorithm>

#include "core/kinematics.hpp"
#include "scene/png_writer.hpp"

namespace armstudy::scene {

RenderSettings render_settings(const cases::RenderOptions& o) {
  RenderSettings s;
  s.frame = o.frame;
  s.shadows = o.shadows;
  return s;
}

ViewBox fit_view(const core::PlanarChain& chain, std::span<const core::JointVector> q,
                 std::span<const Eigen::Vector2d> points, double pad) {
  ViewBox v{chain.base.x(), chain.base.x(), chain.base.y(), chain.base.y()};
  auto grow = [&](const Eigen::Vector2d& p) {
    v.x_min = std::min(v.x_min, p.x());
    v.x_max = std::max(v.x_max, p.x());
    v.y_min = std::min(v.y_min, p.y());
    v.y_max = std::max(v.y_max, p.y());
  };
  for (const core::JointVector& qk : q) {
    const core::ChainPose pose = core::forward_kinematics(chain, qk);
    for (int j = 0; j < pose.p_WJ.cols(); ++j) grow(pose.p_WJ.col(j));
  }
  for (const Eigen::Vector2d& p : points) grow(p);
  v.x_min -= pad;
  v.x_max += pad;
  v.y_min -= pad;
  v.y_max += pad;
  return v;
}

std::string write_strip(SceneRenderer& sr, const SampledMotion& m, int frames,
                        const std::string& title, const std::filesystem::path& dir,
                        const std::string& name) {
  const std::vector<double> at = even_times(m.t.front(), m.t.back(), frames);
  const std::vector<PoseSample> samples = resample(m.t, m.q, m.qd, at);
  const std::string file = name + "_strip.png";
  write_png(dir / file, sr.strip(samples, title, strip_columns(frames)), sr.strip_threads());
  return file;
}

std::string write_locus(SceneRenderer& sr, const SampledMotion& m, int poses,
                        std::span<const Eigen::Vector2d> path,
                        std::span<const Eigen::Vector2d> flight, const FrameLabels& labels,
                        const std::filesystem::path& dir, const std::string& name,
                        const SceneRenderer::LocusStyle& style) {
  const std::vector<double> at = even_times(m.t.front(), m.t.back(), poses);
  const std::vector<PoseSample> samples = resample(m.t, m.q, m.qd, at);
  const std::string file = name + "_locus.png";
  write_png(dir / file, sr.locus(samples, path, flight, labels, style));
  return file;
}

}  // namespace armstudy::scene
