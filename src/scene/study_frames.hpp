// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// What the per-study frame writers share: render settings from the case, and writing a
/// strip and a locus of one motion.

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "cases/case_info.hpp"
#include "scene/frames.hpp"

namespace armstudy::scene {

/// RenderSettings of a case's `render:` options.
RenderSettings render_settings(const cases::RenderOptions& options);

/// A motion sampled at increasing times (chain coordinates), with an optional traced path.
struct SampledMotion {
  std::vector<double> t;                 ///< s
  std::vector<core::JointVector> q, qd;  ///< (N) rad, rad/s (qd may be empty)
};

/// The rectangle holding every joint and the tip of `chain` over the poses `q`, the
/// `points` and the base, padded by `pad` m on every side.
ViewBox fit_view(const core::PlanarChain& chain, std::span<const core::JointVector> q,
                 std::span<const Eigen::Vector2d> points, double pad);

/// Renders `frames` frames of `motion` at equal time steps into `dir`/`name`_strip.png and
/// returns the file name. `title` labels the first frame.
std::string write_strip(SceneRenderer& sr, const SampledMotion& motion, int frames,
                        const std::string& title, const std::filesystem::path& dir,
                        const std::string& name);

/// Writes `dir`/`name`_locus.png: `poses` poses at equal time steps superimposed (older
/// fainter), `path` traced and `flight` dotted; returns the file name.
std::string write_locus(SceneRenderer& sr, const SampledMotion& motion, int poses,
                        std::span<const Eigen::Vector2d> path,
                        std::span<const Eigen::Vector2d> flight, const FrameLabels& labels,
                        const std::filesystem::path& dir, const std::string& name,
                        const SceneRenderer::LocusStyle& style = {});

}  // namespace armstudy::scene
