// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// What every case has, whatever its study.

#include <string>
#include <utility>
#include <vector>

#include "cases/sensitivity_spec.hpp"
#include "cases/source_spec.hpp"

namespace armstudy::cases {

/// The size of a rendered frame, px: the one place its default is written. The case's
/// `render:` options carry it to the renderer (scene::RenderSettings) and to the model's
/// off-screen buffer (scene::MjcfOptions, via the scenes' decor).
struct FrameSize {
  int width = 640;   ///< px
  int height = 480;  ///< px
};

/// Frame rendering settings of a case (`render:` in YAML).
struct RenderOptions {
  FrameSize frame;  ///< `width`, `height`
  int frames = 6;   ///< frames in a strip
  bool shadows = false;
};

struct CaseInfo {
  std::string name;         ///< `name:`, also the output folder name
  std::string study;        ///< `study:`
  std::string description;  ///< `description:` (optional)
  std::string path;         ///< the case file as given
  std::string sha256;       ///< of the file's bytes, hex
  std::string yaml;         ///< the file's text
  RenderOptions render;
  /// `expect:` solved (default) or unsolvable: a case that documents an impossible task
  /// (a regression test that it stays impossible) expects to be unsolvable.
  bool expect_unsolvable = false;
  /// `sweep:` of a case written by `armstudy sweep expand`: the sweep's name and the
  /// point's values by parameter path (values as YAML text), in axis order.
  std::string sweep_name;
  std::vector<std::pair<std::string, std::string>> sweep_point;
  /// `source:`: what the case's source printed, to set beside armstudy's numbers
  SourceSpec source;
  /// `sensitivity:`: the keys re-solved at -step and +step (app/sensitivity.hpp)
  SensitivitySpec sensitivity;
};

/// SHA-256 of bytes, lowercase hex.
std::string sha256_hex(const std::string& bytes);

}  // namespace armstudy::cases
