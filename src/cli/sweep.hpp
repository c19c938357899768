// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Parameter sweeps: a sweep file names a base case and axes over case parameters (by
/// path, e.g. `arm.links[2].length`, 1-based list indices as in error messages); expand()
/// writes one case file per point, named by a content hash, with the point recorded in
/// the case's `sweep:` mapping.
///
/// ```yaml
/// sweep: placement-link-ratio      # the sweep's name
/// base: placement-example-2.yaml  # relative to this file, inside its folder (or --base-dir)
/// mode: grid                       # grid (every combination) or zip (i-th with i-th)
/// axes:
///   - path: arm.links[2].length
///     values: [0.1, 0.2, 0.3]      # a list of values (any YAML), or
///   - path: placement.length_fraction
///     range: {from: 0.2, to: 0.8, steps: 7}   # evenly spaced numbers, ends included
/// ```

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace armstudy::cli {

struct SweepAxis {
  std::string path;
  std::vector<YAML::Node> values;
  YAML::Mark mark;  ///< of the axis in the sweep file
};

struct SweepPoint {
  std::string case_name;  ///< base name + "-" + 10 hex of the content hash
  std::string yaml;       ///< the case file's text
};

struct Sweep {
  std::string name;
  std::string path;       ///< the sweep file
  std::string base_path;  ///< the base case file
  YAML::Node base;
  bool zip = false;
  std::vector<SweepAxis> axes;
  /// Every point's case, in axis order (grid: last axis fastest).
  std::vector<SweepPoint> points;
};

/// Points a sweep may have (grid: the product of the axes' value counts; zip: the first
/// axis's count); more is refused before any is generated.
inline constexpr size_t kMaxSweepPoints = 10000;
/// YAML nodes all of a sweep's generated cases may hold together (points x base nodes).
inline constexpr double kMaxSweepNodes = 2e7;

/// The number of points of a sweep's axes, without overflow (SIZE_MAX when it is more
/// than size_t holds).
size_t sweep_point_count(const Sweep& sweep);

/// Reads and validates a sweep file and every case it generates; refuses more than
/// kMaxSweepPoints points. `base:` is taken from the sweep file's folder and must lie,
/// symlinks resolved, inside that folder or inside one of `base_dirs` (--base-dir); a base
/// that is not a case file is named, never quoted. Refused too: an axis over `name` or into
/// `sweep`, two axes over one path, and one value twice on an axis (0.5 and 0.50).
/// @throws cases::CaseErrors (file:line:col), e.g. for a path that names no parameter.
Sweep load_sweep(const std::string& path, const std::vector<std::filesystem::path>& base_dirs = {});

/// Why expansion wrote nothing: the folder holds another sweep's manifest, or a file that
/// expansion did not write where a case goes.
class ExpandRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ExpandResult {
  size_t written = 0;                ///< case files written (new or changed)
  std::vector<std::string> removed;  ///< case ids of earlier expansions no longer in the sweep
};

/// Writes each point's case file to out_dir/<case_name>.yaml (existing files with the same
/// content are left alone), removes the case files an earlier expansion wrote that are no
/// longer points of the sweep (only files beginning with kGeneratedHeader) and writes the
/// manifest (sweep_manifest.hpp). @throws ExpandRefused before writing anything when the
/// folder is another sweep's or holds a foreign file where a case goes.
ExpandResult expand_sweep(const Sweep& sweep, const std::filesystem::path& out_dir);

/// Sets the value at `path` in a clone of `root` (missing mapping keys are created).
/// Returns "" or a complaint ("'links[9]' is past the end of a list of 2").
std::string set_path(YAML::Node root, const std::string& path, const YAML::Node& value);

}  // namespace armstudy::cli
