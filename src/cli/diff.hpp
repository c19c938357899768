// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// `armstudy diff BASE NEW`: what changed between two output folders of `run` or `merge`
/// (e.g. the main branch's report artefact and a pull request's), case by case: added and
/// removed cases, status changes, key figures against their tolerances, checks whose
/// verdict changed, frames pixel by pixel, provenance, and the sweep table row by row.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/diff_tolerances.hpp"
#include "cli/merge.hpp"
#include "report/diff_report.hpp"

namespace armstudy::cli {

/// A folder that is not an output folder, or a results.json that cannot be read; the
/// message names the folder or file and what was expected.
class DiffInputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Every case output in `dir` (DIR/<case>/results.json), each checked for the fields the
/// diff reads. @throws DiffInputError when dir is missing, holds no results.json, or one of
/// them is unreadable or malformed (every such file is named).
std::vector<CaseOutput> read_run(const std::filesystem::path& dir);

struct FrameOptions {
  int channel_tolerance = 0;       ///< a pixel is beyond when a channel differs by more (0-255)
  std::size_t pixels_allowed = 0;  ///< a frame is beyond when more pixels are
  /// Where frame copies and difference images go (FrameDiff paths are relative to it),
  /// as frames_root/diff-frames/<case>/...; empty: frames are compared by bytes only.
  std::filesystem::path frames_root;
};

/// Compares two runs read by read_run. Cases are matched by name.
/// @throws scene::SceneError when a difference image cannot be written.
report::RunDiff diff_runs(const std::vector<CaseOutput>& base, const std::vector<CaseOutput>& now,
                          const DiffTolerances& tolerances, const FrameOptions& frames);

struct DiffOptions {
  std::filesystem::path base, now;
  std::filesystem::path out = "reports/diff";
  std::string tolerances_file;                ///< empty: built-in tolerances
  std::optional<int> pixel_tolerance;         ///< overrides the file's frames.channel
  std::optional<std::size_t> pixels_allowed;  ///< overrides the file's frames.pixels
};

/// The command: reads both folders, writes out/diff.html, out/diff.md (and the frames they
/// show under out/diff-frames/), prints a short verdict on stderr. Returns the exit code:
/// 0 nothing moved beyond its tolerance, 1 something did, 2 bad input (a missing folder, an
/// unreadable results.json or tolerances file: named), 3 the output could not be written.
int run_diff(const DiffOptions& options);

}  // namespace armstudy::cli
