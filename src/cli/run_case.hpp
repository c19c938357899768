#pragma once
/// Runs one loaded case into DIR/<case name>/, atomically.

#include <filesystem>
#include <string>
#include <vector>

#include "cli/pipeline.hpp"
#include "studies/common.hpp"

namespace armstudy::app {

struct RunOptions {
  std::filesystem::path out_dir = "reports/out";
  bool render = true;
  bool pdf = false;
};

/// How one case ended. exit_code: 0 done, 1 unsolvable or a failed check, 3 a runtime
/// failure (rendering, writing output, internal error).
struct CaseOutcome {
  int exit_code = 0;
  std::string message;  ///< one line for the user
  std::filesystem::path folder;
  double seconds = 0;
};

/// Solves, renders and reports `c` into out_dir/<name>/: the output is built in a
/// temporary sibling folder and renamed into place only when complete, so a failure
/// leaves an earlier report untouched and writes nothing half-done. An unsolvable study
/// still gets its results.json (status "unsolvable") so CI can read why.
CaseOutcome run_case(LoadedCase& c, const RunOptions& options, const studies::ProgressFn& progress);

/// The fields of results.json every study shares (version, study, case, status, checks).
nlohmann::json results_header(const cases::CaseInfo& info, studies::Status status,
                              const std::string& message,
                              const std::vector<studies::Check>& checks);

/// After every case of a run: with options.pdf, prints each case report in out_dir that has
/// no report.pdf at least as new as its index.html (headless Chromium, up to `jobs` at a
/// time), then writes out_dir/index.html over every case folder there. Returns one line per
/// problem (empty: all written).
std::vector<std::string> finish_reports(const RunOptions& options, int jobs);

/// "<host>-<pid>" of this process: names temporary outputs so that runs on several hosts
/// sharing one output folder (Slurm, GNU Parallel --sshlogin) never touch each other's.
std::string process_tag();

/// Removes what killed runs of this host left in out_dir: hidden `.<name>.tmp-<host>-<pid>`
/// and `.<name>.old-<host>-<pid>` entries whose process is gone (or is a zombie). Other hosts' entries are left
/// alone (their processes cannot be checked from here). Returns how many were removed.
size_t remove_stale_outputs(const std::filesystem::path& out_dir);

/// Writes `text` to `path` through a hidden temporary sibling and a rename.
void write_file_atomic(const std::filesystem::path& path, const std::string& text);

}  // namespace armstudy::app
