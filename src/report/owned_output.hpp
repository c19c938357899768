// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// What in an output folder armstudy wrote, and so may replace: a case folder holds
/// armstudy's results.json for that case (every version writes one: an object with
/// `schema_version` and `case.name`); a run-level file carries the mark armstudy writes into
/// it (the generator meta of index.html, the first line of summary.md and junit.xml, ...).
/// Anything else of those names is the user's: a run refuses to touch it.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "sys/scratch_dir.hpp"

namespace armstudy::report {

/// Why `dir` (a case folder for the case `name`) is not armstudy's: "" when it is
/// missing or armstudy's (a real folder, not a link, holding a results.json of armstudy's
/// for `name`), else what it is ("a folder armstudy did not write (...)", "a file", "a
/// symbolic link").
std::string foreign_case_folder(const std::filesystem::path& dir, const std::string& name);

/// The run-level outputs armstudy writes directly in an output folder: index.html,
/// report.css, summary.md, junit.xml, sweep.csv, sweep.json, the index page's figures
/// (`figures`, e.g. placement_root_loci.svg) and the sweep report's folder `sweep`.
std::vector<std::string> run_level_outputs(const std::vector<std::string>& figures);

/// The outputs `armstudy diff` writes in its --out folder.
inline const std::vector<std::string> kDiffOutputs = {"diff.md", "diff.html", "report.css",
                                                      "diff-frames"};

/// Why `out_dir`/`name` (one of run_level_outputs or kDiffOutputs) is not armstudy's: ""
/// when it is missing or carries armstudy's mark, else what it is.
std::string foreign_run_level_output(const std::filesystem::path& out_dir, const std::string& name);

/// Every entry in `out_dir` a run would replace and may not: the case folders of `cases`
/// and the run-level outputs `run_level`, each as "<path>: <why>; expected ...".
std::vector<std::string> foreign_outputs(const std::filesystem::path& out_dir,
                                         const std::vector<std::string>& cases,
                                         const std::vector<std::string>& run_level);

/// Throws ForeignOutput when `out_dir`/`name` is a run-level output armstudy did not write
/// (the last check before it is written, for a file that appeared during the run).
void check_run_level_output(const std::filesystem::path& out_dir, const std::string& name);

/// sys::remove_stale_scratch with armstudy's outputs: the sub-folders looked into are its
/// case folders and the sweep report; directly in `dir` an old-style part file is removed
/// only beside a run-level output or a figure (.svg). Defined in report/stale_scratch.cpp.
sys::StaleCleanup remove_stale_scratch(const std::filesystem::path& dir);

/// A file or folder of a name armstudy writes that armstudy did not write.
struct ForeignOutput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace armstudy::report
