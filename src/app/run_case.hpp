// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Runs one loaded case into DIR/<case name>/, atomically.

#include <filesystem>
#include <string>
#include <vector>

#include "app/pipeline.hpp"
#include "report/results_record.hpp"
#include "studies/common.hpp"
#include "sys/scratch_dir.hpp"

namespace armstudy::report {
class PdfPrinter;
}

namespace armstudy::app {

/// Where `armstudy run` writes without --out: a folder named after armstudy in the current
/// folder (never a tracked folder of armstudy's repository: its .gitignore ignores it).
inline constexpr const char* kDefaultOutDir = "armstudy-out";

struct RunOptions {
  std::filesystem::path out_dir = kDefaultOutDir;
  bool render = true;
  bool pdf = false;
  /// Re-solves each key of the case's `sensitivity:` part (app/sensitivity.hpp); false with
  /// --no-sensitivity.
  bool sensitivity = true;
  /// With --pdf: prints each case's page as soon as the case is in place (one browser for
  /// the run, beside the cases still solving); finish_reports prints what it did not.
  report::PdfPrinter* printer = nullptr;
};

/// How one case ended. exit_code: 0 done, 1 unsolvable or a failed check, 3 a runtime
/// failure (rendering, writing output, internal error).
struct CaseOutcome {
  int exit_code = 0;
  std::string message;  ///< one line for the user
  std::filesystem::path folder;
  double seconds = 0;
};

/// Solves, renders and reports `c` into out_dir/<name>/: the output is built in this
/// process's scratch folder in out_dir and swapped into place only when complete, so a
/// failure or a kill leaves an earlier report untouched and writes nothing half-done. An unsolvable
/// study still gets its results.json (status "unsolvable") so CI can read why.
CaseOutcome run_case(LoadedCase& c, const RunOptions& options, const studies::ProgressFn& progress);

/// The fields of results.json every study shares (version, study, case, status, checks);
/// run_case adds the rest (key figures, frames, exports, animations, files).
report::ResultsRecord results_header(const cases::CaseInfo& info, studies::Status status,
                                     const std::string& message,
                                     const std::vector<studies::Check>& checks);

/// After every case of a run: with options.pdf, prints the report of each of the run's
/// `cases` (names) that has no report.pdf at least as new as its index.html (headless
/// Chromium, up to `jobs` at a time), only a page armstudy wrote (its results.json lists it
/// with its sha256), then writes out_dir/index.html over every case folder there. Returns
/// one line per problem (empty: all written).
std::vector<std::string> finish_reports(const RunOptions& options, int jobs,
                                        const std::vector<std::string>& cases);

/// "<host>-<pid>-<random>" of this process (sys::process_tag): names its scratch folder.
std::string process_tag();

/// Before a run: removes what killed runs left in out_dir (scratch folders whose lock no
/// live process holds, see sys/scratch_dir.hpp), first putting back any earlier report
/// a kill left in one. Live runs' folders, on this host or any other, are left alone.
sys::StaleCleanup remove_stale_outputs(const std::filesystem::path& out_dir);

/// Writes `text` to `path` through a temporary file and a rename (sys::write_file_atomic).
void write_file_atomic(const std::filesystem::path& path, const std::string& text);

}  // namespace armstudy::app
