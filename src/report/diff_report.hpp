// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// What changed between two runs (`armstudy diff BASE NEW`): the comparison, filled by
/// app::diff_runs from the two output folders, and its two renderings, DIR/diff.html (a
/// report page, same template and Content-Security-Policy as the case reports) and
/// DIR/diff.md (a CI job summary, changes beyond tolerance first).

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace armstudy::report {

/// The tolerance a key figure was held to: it moved when |new - base| > max(abs, rel |base|).
struct FigureTolerance {
  double abs = 0;
  double rel = 0;
  bool ignore = false;  ///< shown, never counted (e.g. wall-clock run times)
  std::string source;   ///< where it came from, e.g. "tolerances.yaml:4:7" or "built-in"
};

/// One key figure of a case present in both runs (or in one of them).
struct FigureDiff {
  std::string name;
  std::string unit;
  std::optional<double> base, now;  ///< missing on a side: the figure was added or removed
  FigureTolerance tolerance;
  bool beyond = false;  ///< moved beyond its tolerance (or appeared / disappeared)
  /// new - base (NaN unless both sides have a number)
  double abs_change() const;
  /// (new - base) / |base| (NaN unless both sides have a number; inf when base is 0)
  double rel_change() const;
  bool changed() const { return base != now; }
};

/// A check whose verdict differs between the runs (or that exists in one run only).
struct CheckDiff {
  std::string name;
  std::optional<bool> base_passed, new_passed;
  std::optional<double> base_value, new_value, base_tolerance, new_tolerance;
};

/// One frame (PNG) the runs have in common, or that one of them lacks.
struct FrameDiff {
  std::string file;  ///< relative to the case folder
  bool in_base = true, in_new = true;
  bool identical = false;         ///< byte-identical files
  bool size_differs = false;      ///< width or height differ (every pixel counts as beyond)
  int width = 0, height = 0;      ///< of the new frame
  std::size_t pixels_beyond = 0;  ///< pixels with a channel differing by more than the tolerance
  int max_channel_delta = 0;      ///< largest difference of one channel, 0-255
  bool beyond = false;            ///< more pixels beyond than the run allows
  std::string error;              ///< a frame that could not be read (named with its file)
  /// Copies in the diff folder (relative to it), for the page: base, new, difference image
  std::string base_copy, new_copy, diff_image;
};

/// One provenance item that differs (armstudy version, commit, MuJoCo, Mesa, renderer...).
struct ProvenanceDiff {
  std::string key;    ///< results.json provenance key, e.g. "gl_renderer"
  std::string label;  ///< for people, e.g. "GL renderer"
  std::string base, now;
};

/// An input of the case (results.json case.inputs) that differs between the runs.
struct InputDiff {
  std::string key;        ///< its dotted path, e.g. "placement.torque_limits_Nm"
  std::string base, now;  ///< as YAML text; "(none)" where that run's case file lacks it
};

struct CaseDiff {
  enum class Presence { kBoth, kAdded, kRemoved };
  std::string name;
  std::string study;
  Presence presence = Presence::kBoth;
  std::string base_status, new_status;         ///< "solved" / "unsolvable"
  bool base_passed = true, new_passed = true;  ///< ended as expected with every check passed
  std::string base_message, new_message;
  std::vector<FigureDiff> figures;  ///< every key figure of either side, in the study's order
  std::vector<CheckDiff> checks;    ///< only those whose verdict changed
  std::vector<FrameDiff> frames;    ///< every frame of either side
  std::vector<ProvenanceDiff> provenance;
  /// the inputs that differ; inputs_known: both runs' results.json echo their case's inputs
  std::vector<InputDiff> inputs;
  bool inputs_known = false;

  /// Something moved beyond its tolerance: added, removed, status or verdict changed, a
  /// key figure or a frame beyond tolerance.
  bool beyond() const;
  /// Anything differs at all (values within tolerance, provenance included).
  bool changed() const;
  bool status_changed() const { return base_status != new_status || base_passed != new_passed; }
};

/// A row of the sweep table (by case id) whose values changed.
struct SweepRowDiff {
  std::string case_name;
  std::string point;  ///< "arm.links[2].length = 0.12, placement.length_fraction = 0.5"
  std::string base_status, new_status;  ///< sweep table status: "ok" / "failed" / "" (absent)
  std::string figure;                   ///< the key figure with the largest relative change
  std::string unit;
  std::optional<double> base, now;
  double score = 0;         ///< |relative change| of that figure (inf: added, removed, status)
  int figures_changed = 0;  ///< how many key figures of the row changed at all
  bool beyond = false;
};

struct RunDiff {
  std::filesystem::path base_dir, new_dir;
  std::string tolerances_file;     ///< empty: built-in tolerances
  int pixel_tolerance = 0;         ///< per channel, 0-255
  std::size_t pixels_allowed = 0;  ///< pixels beyond it a frame may have and still match
  std::size_t base_cases = 0, new_cases = 0;
  std::vector<CaseDiff> cases;             ///< sorted by name
  std::vector<ProvenanceDiff> provenance;  ///< of the runs as a whole (values over all cases)
  std::string sweep_name;                  ///< empty: no sweep in either run
  std::size_t sweep_rows_base = 0, sweep_rows_new = 0;
  std::vector<SweepRowDiff> sweep;  ///< changed rows, largest change first

  /// How many cases moved beyond tolerance.
  std::size_t beyond_count() const;
};

/// GitHub-flavoured markdown: verdict, changes beyond tolerance first (with what moved),
/// the sweep's largest changes, changes within tolerance, provenance; at most max_bytes
/// (truncated with a note).
std::string diff_markdown(const RunDiff& diff, std::size_t max_bytes = 1 << 20);

/// Writes dir/diff.html (with report.css) through the case page template: the same
/// stylesheet and Content-Security-Policy as the reports; the frames it shows are copies
/// in `dir` (RunDiff's FrameDiff copies). @throws std::runtime_error when a file cannot be
/// written.
void write_diff_page(const std::filesystem::path& dir, const RunDiff& diff);

}  // namespace armstudy::report
