// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Tolerances of `armstudy diff`, from a YAML file (errors as file:line:col, like case files):
///
///     default: {rel: 1.0e-6}            # every key figure not named below
///     frames: {channel: 2, pixels: 0}   # a frame matches when at most `pixels` pixels have
///                                       # a channel differing by more than `channel` (0-255)
///     studies:
///       placement:
///         default: {abs: 1.0e-4}        # the study's other key figures
///         figures:
///           min_energy_J: {abs: 1.0e-3, rel: 1.0e-4}
///           "root_*_m[*]": {abs: 1.0e-3}  # patterns: * any text, ? one character (brackets
///                                           # are literal); first match in file order
///       throwing:
///         figures:
///           idp_run_time_s: {ignore: true}
///
/// A key figure moved when |new - base| > max(abs, rel * |base|) (a missing abs or rel is 0).
/// Lookup order: the study's figures (exact name, then patterns), the study's default, the
/// file's default, then built-in: exact equality, and wall-clock run times (figures named
/// *run_time*) ignored unless the file names them.

#include <optional>
#include <string>
#include <vector>

#include "report/diff_report.hpp"

namespace armstudy::cli {

struct DiffTolerances {
  struct Entry {
    std::string pattern;  ///< figure name or glob pattern
    report::FigureTolerance tolerance;
  };
  struct Study {
    std::string name;
    std::optional<report::FigureTolerance> fallback;
    std::vector<Entry> figures;
  };
  std::string file;  ///< empty: built-in only
  std::optional<report::FigureTolerance> fallback;
  std::vector<Study> studies;
  std::optional<int> pixel_channel;   ///< frames.channel
  std::optional<std::size_t> pixels;  ///< frames.pixels

  /// The tolerance of key figure `figure` of study `study`.
  report::FigureTolerance lookup(const std::string& study, const std::string& figure) const;
};

/// Reads a tolerances file. @throws cases::CaseErrors with every problem (file:line:col).
DiffTolerances load_diff_tolerances(const std::string& path);

}  // namespace armstudy::cli
