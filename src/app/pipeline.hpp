#pragma once
/// The pipeline of one case: case -> study -> result -> scene/report. Each study plugs in
/// one StudyRun implementation and one registry entry (study_registry.cpp); the CLI knows
/// nothing else about studies.

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "cases/case_info.hpp"
#include "cases/yaml_reader.hpp"
#include "studies/common.hpp"

namespace armstudy::app {

/// A number a reader compares across cases.
struct KeyFigure {
  std::string name;  ///< stable identifier, e.g. "min_energy_J"
  double value = 0;
  std::string unit;  ///< e.g. "J", "s", "%", "" for none
  std::string label;  ///< what a reader sees, in words, e.g. "lowest energy"; empty: the name
};

/// One loaded case of some study, ready to solve. Stages are called in this order:
/// solve, checks/results, render (unless --no-render), report.
class StudyRun {
 public:
  virtual ~StudyRun() = default;
  /// Solves the study (pure computation).
  virtual studies::Status solve(const studies::ProgressFn& progress) = 0;
  /// Why the study could not be solved (or a one-line summary when it was).
  virtual std::string message() const = 0;
  /// The checks the study ran on its own answer.
  virtual std::vector<studies::Check> checks() const { return {}; }
  /// The study's own section of results.json (SI; keys ending in _deg are degrees).
  virtual nlohmann::json results() const = 0;
  /// The few numbers a reader compares across cases (summary tables, sweep tables),
  /// e.g. {"energy_J[cycloidal,1]", 12.3, "J"}. Written to results.json "key_figures".
  virtual std::vector<KeyFigure> key_figures() const { return {}; }
  /// Renders frames into `dir`; returns the file names written (relative to dir).
  /// @throws scene::SceneError when MuJoCo or OSMesa fails.
  virtual std::vector<std::string> render(const std::filesystem::path& dir,
                                          const cases::CaseInfo& info) {
    return {};
  }
  /// Writes the study's report page and plots into `dir` (frames already there).
  virtual void report(const std::filesystem::path& dir, const cases::CaseInfo& info,
                      const nlohmann::json& results_json) {}
};

/// One study kind: its name and how to load its part of a case file.
struct StudyEntry {
  std::string_view study;    ///< "placement", "pendulum", "throwing", "time_optimal"
  std::string_view summary;  ///< one line for --help
  /// Reads the study's keys from the root mapping (every error into root.diag()).
  std::unique_ptr<StudyRun> (*load)(cases::Map& root, const cases::CaseInfo& info);
};

/// Every study armstudy knows.
const std::vector<StudyEntry>& study_registry();

/// A case file loaded and validated.
struct LoadedCase {
  cases::CaseInfo info;
  std::unique_ptr<StudyRun> run;
};

/// How a case is judged when it is loaded.
struct LoadOptions {
  /// Accept work and memory beyond the documented budget (cases/budget.hpp).
  bool allow_large = false;
};

/// Loads and validates a case file, its estimated work and memory included.
/// @throws cases::CaseErrors with every problem found.
LoadedCase load_case(const std::string& path, const LoadOptions& options = {});

/// Loads and validates case text; `path` names it in messages and results.
/// @throws cases::CaseErrors with every problem found.
LoadedCase load_case_text(const std::string& text, const std::string& path,
                          const LoadOptions& options = {});

}  // namespace armstudy::app
