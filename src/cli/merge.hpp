// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Merging case outputs into what CI reads: summary.md (a job summary), junit.xml (one
/// testcase per case and check) and, for sweeps, sweep.csv / sweep.json (one row per case:
/// its point and key figures). Built from results.json files only, independent of the
/// order in which cases ran or shards finished: rows are sorted by case name.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/sweep_manifest.hpp"
#include "report/results_record.hpp"
#include "report/sweep_table.hpp"

namespace armstudy::cli {

/// One case output found on disk.
struct CaseOutput {
  std::filesystem::path folder;  ///< DIR/<case name>
  nlohmann::json results;        ///< its results.json as read (empty when unreadable)
  /// its shared record, typed (what merge reads); for a file that cannot be used, status
  /// "unreadable", the folder's name and a message saying what is wrong
  report::ResultsRecord record;
};

/// Every DIR/<case>/results.json under the given folders, sorted by case name. Two results
/// of one case id are one failed case (status "duplicate") naming both folders, and a
/// warning. @throws InputLimitError beyond the limits above. A file that cannot be used
/// (truncated, not JSON, a wrong type, an unknown schema_version) is a failed case named
/// after its folder, with status "unreadable" and a message naming the file and what is
/// wrong; it is also reported in `warnings`. A folder that is not there is reported in
/// `warnings` (callers that take folders from the user check them first). @throws
/// cases::InputFileError when a results.json is no regular file of at most
/// cases::kMaxResultsJsonBytes (a FIFO, a device, a link): it is never opened for reading
/// then, and nothing can be merged.
std::vector<CaseOutput> collect_outputs(const std::vector<std::filesystem::path>& dirs,
                                        std::vector<std::string>* warnings);

/// What merge, diff and run read of output folders (docs/budgets.md): beyond a limit,
/// collect_outputs throws InputLimitError and the command writes nothing (exit 2).
inline constexpr size_t kMaxMergedCases = 100000;              ///< results.json files
inline constexpr std::uintmax_t kMaxResultsBytes = 16u << 20;  ///< bytes of one results.json
inline constexpr std::uintmax_t kMaxMergedBytes = 1ull << 30;  ///< bytes of all of them
inline constexpr size_t kMaxKeyFigures = 200;  ///< per case, and distinct names over all cases
inline constexpr size_t kMaxFrames = 1000;     ///< frames listed by one results.json

class InputLimitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A failed case of armstudy's own making: status "unreadable" (its results.json cannot be
/// used), "duplicate" (two results of one case id), "missing" (a case of the sweep without a
/// result) or "error" (the run ended in an error); `message` says what is wrong and is the
/// failure in summary.md and junit.xml.
CaseOutput failed_output(const std::filesystem::path& folder, const std::string& name,
                         const std::string& study, const std::string& status,
                         const std::string& message);

/// Checks `cases` against a sweep's manifest (found at `where`): a case of the sweep without
/// a result is added as a failed case (status "missing"), a result of a case that is not in
/// the sweep is left out (and named in `warnings`). Returns the number of missing cases.
size_t apply_manifest(const SweepManifest& manifest, const std::filesystem::path& where,
                      std::vector<CaseOutput>* cases, std::vector<std::string>* warnings);

/// Why `results` cannot be merged ("" if it can): an unknown schema_version, or the path
/// and expected type of the first field merge reads that has another type.
std::string results_problem(const nlohmann::json& results);

/// The run-level file or folder that an output folder's entry `name` would collide with
/// (report::run_level_outputs: index.html, summary.md, junit.xml, report.css, sweep,
/// sweep.csv, sweep.json, and each registered study's index-page figure, e.g.
/// placement_root_loci.svg), or nullptr: no case may have such a name.
const char* run_level_file(const std::string& name);

/// True if the case ended as its file expects (solved, unless it says `expect: unsolvable`)
/// and every one of its checks passed.
bool case_passed(const report::ResultsRecord& record);

/// GitHub-flavoured markdown: failures first, one table per study; at most max_bytes
/// (truncated with a note).
std::string summary_markdown(const std::vector<CaseOutput>& cases, size_t max_bytes = 1 << 20);

/// JUnit XML: one testsuite per study, a testcase "solve" per case and one per check.
std::string junit_xml(const std::vector<CaseOutput>& cases);

/// The sweep table of the cases that carry a sweep point (no rows if none): one row per
/// case, sorted by case id (report/sweep_table.hpp).
report::SweepTable sweep_table(const std::vector<CaseOutput>& cases);
/// The sweep table as sweep.csv ("" when no case carries a sweep point) and as sweep.json.
std::string sweep_csv(const std::vector<CaseOutput>& cases);
nlohmann::json sweep_json(const std::vector<CaseOutput>& cases);

/// Writes summary.md, junit.xml and (if any case is a sweep point) sweep.csv and
/// sweep.json into out_dir, each atomically. Returns the number of failed cases.
size_t write_merged(const std::vector<CaseOutput>& cases, const std::filesystem::path& out_dir);

}  // namespace armstudy::cli
