// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The pipeline of one case: case -> study -> result -> scene/report. Each study plugs in
/// one loader record (StudyLoader, app/study_loaders.cpp), one StudyRun implementation and
/// its parts (StudyParts, app/study_registry.cpp); the CLI, the report and merge know
/// nothing else about studies.

#include <any>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <typeindex>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/study_loaders.hpp"
#include "cases/case_info.hpp"
#include "cases/yaml_reader.hpp"
#include "report/case_report.hpp"
#include "report/results_record.hpp"
#include "scene/rendered.hpp"
#include "studies/common.hpp"

namespace armstudy::report {
struct CasePage;
class FigureWriter;
}  // namespace armstudy::report

namespace armstudy::app {

/// A number a reader compares across cases.
struct KeyFigure {
  std::string name;  ///< stable identifier, e.g. "min_energy_J"
  double value = 0;
  std::string unit;   ///< e.g. "J", "s", "%", "" for none
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
  /// The study's own part of results.json (SI; keys ending in _deg are degrees).
  virtual nlohmann::json results() const = 0;
  /// The few numbers a reader compares across cases (summary tables, sweep tables),
  /// e.g. {"energy_J[cycloidal,1]", 12.3, "J"}. Written to results.json "key_figures".
  virtual std::vector<KeyFigure> key_figures() const { return {}; }
  /// Renders frames and animations into `dir`; returns the frames' file names (relative to
  /// dir) and the animations, whose videos may still be encoding (scene/animation.hpp).
  /// @throws scene::SceneError when MuJoCo or OSMesa fails.
  virtual scene::Rendered render(const std::filesystem::path& dir, const cases::CaseInfo& info) {
    return {};
  }
  /// Writes the files other tools open into `dir` (model.xml, one motion CSV per solver or
  /// optimiser) and returns their records, results.json's "exports": one per file naming
  /// what it holds. Called when the study is solved, with or without rendering, before the
  /// report.
  virtual std::vector<report::ExportRecord> write_exports(const std::filesystem::path& dir,
                                                          const cases::CaseInfo& info) {
    return {};
  }

  // what a sensitivity part (app/sensitivity.hpp) asks of a solved study
  /// The name of the key figure that answers the case (one of key_figures()); the
  /// sensitivity part varies it. Default: the first key figure.
  virtual std::string headline() const {
    const auto k = key_figures();
    return k.empty() ? std::string() : k.front().name;
  }
  /// The constraints that bind the answer, in words, in a fixed order (empty: none binds
  /// or the study has no constraints).
  virtual std::vector<std::string> binding() const { return {}; }
  /// Prepares this run (the same case with one key changed) to solve from `nominal`'s
  /// answer, and only for the headline figure (no report extras). Returns true when
  /// solve() will then be warm-started; false: solve() solves from scratch (or only without
  /// the extras). Called before solve().
  virtual bool warm_start(const StudyRun& nominal) { return false; }
  /// After solve(): whether the answer came from the nominal one (a warm start that could not
  /// be used, e.g. a start outside a tightened constraint, solves from scratch).
  virtual bool warm_started() const { return false; }
  /// After a sensitivity step solved `step` (this case with one key changed, `from` names the
  /// step): when the step's answer also meets this case's limits and costs less than this
  /// answer (by more than kOfferMargin of it), keeps it as a start of the next solve() and
  /// returns true. A problem that is tighter, or that moves a key that does not bind, must
  /// never answer below the case itself: the program then solves the case again with it
  /// (app/run_case.cpp). Default: nothing is kept.
  virtual bool offer_start(const StudyRun& step, const std::string& from) { return false; }
  /// The starts kept by offer_start() since the last solve(), in words ("" none).
  virtual std::string offered() const { return {}; }
};

/// A step's throw is kept as a start when it costs less than the answer by more than this share
/// of it: above the optimisers' own spread between restarts (about 2e-5 on the bundled throw)
inline constexpr double kOfferMargin = 1e-4;

/// A study's sections of its case page, built from the whole results.json (the study's
/// typed results read back from results[study]; report/study_sections.hpp).
using ReportSections = report::StudySections;

/// What the program adds to a study's StudyLoader (app/study_loaders.hpp): the StudyRun it
/// solves a loaded spec with (solver, checks, key figures, frames, results()), its line of
/// --help, its report sections, its lines of the answer box and its figure over all its
/// cases on the index page (the last two optional). Build one with study_parts<Run>()
/// (app/study_entry.hpp); it is paired with the loader whose spec its run takes.
struct StudyParts {
  /// The run of a loaded spec (the std::any holds a spec of `spec_type`).
  using MakeRun = std::unique_ptr<StudyRun> (*)(std::any spec);
  /// The report parts, given the study's name (its typed results is results[study]): the
  /// registry passes it when it joins the parts to their loader.
  using NamedSections = std::function<void(const std::string& study, const nlohmann::json& results,
                                           const report::ResultsRecord& record,
                                           report::FigureWriter& figures, report::CasePage& page)>;
  using NamedAnswer =
      std::function<void(const std::string& study, const nlohmann::json& results,
                         const report::ResultsRecord& record, report::AnswerBox& box)>;

  std::type_index spec_type;  ///< the spec its run takes
  std::string_view summary;   ///< one line for --help
  MakeRun make_run = nullptr;
  /// The study's sections of its case page.
  NamedSections report;
  /// What binds its answer and what the case assumes, on page 1 (and its key picture);
  /// empty: none.
  NamedAnswer answer;
  /// Its figure over all its cases on the index page (none when `draw` is null).
  report::IndexFigure index_figure;
};

/// One study kind, the one record of it the registry holds (nothing else dispatches on the
/// study name): its loader record (name, case loader, results.json part's schema and
/// strict reader: app/study_loaders.cpp, the one list of studies) and its parts (the
/// StudyRun a loaded case is solved by, the report sections, the answer lines and the index
/// figure: app/<study>_pipeline.cpp). Every part but the answer lines and the index figure
/// is required (a null one is an error at registration).
struct StudyEntry {
  /// @throws std::invalid_argument when a required part is missing or the parts' run takes
  /// another spec than the loader reads.
  StudyEntry(const StudyLoader& loader, const StudyParts& parts);

  /// Reads the study's keys from the root mapping (every error into root.diag()) and
  /// returns the run of the case; nullptr when root.diag() holds an error.
  std::unique_ptr<StudyRun> load(cases::Map& root) const;

  std::string_view study;    ///< "placement", "pendulum", "throwing", "time_optimal"
  std::string_view summary;  ///< one line for --help
  /// The JSON Schema of results[study] (results.schema.json holds it).
  StudyLoader::StudyResultsSchema results_schema;
  /// Reads results[study] of a whole results.json strictly into the typed results.
  /// @throws report::ResultsError naming the JSON pointer of the first problem.
  StudyLoader::StudyResultsCheck check_results;
  /// The study's sections of its case page.
  ReportSections report;
  /// What binds its answer and what the case assumes, on page 1 (and its key picture).
  report::StudyAnswer answer = nullptr;
  /// Its figure over all its cases on the index page (none when `draw` is null).
  report::IndexFigure index_figure;

 private:
  StudyLoader::Load load_spec_;
  StudyParts::MakeRun make_run_;
};

/// The registry's records: each loader of `loaders` with the one of `parts` whose run takes
/// its spec, in the order of `loaders`.
/// @throws std::logic_error naming the study when a loader has no parts or parts have no
/// loader.
std::vector<StudyEntry> with_parts(const std::vector<StudyLoader>& loaders,
                                   const std::vector<StudyParts>& parts);

/// Every study armstudy knows.
const std::vector<StudyEntry>& study_registry();

/// The registry's record of `study`; nullptr when there is none.
const StudyEntry* find_study(std::string_view study);

/// What the index page needs of every study in the registry (report::write_index).
std::vector<report::IndexStudy> index_studies();

/// A case file loaded and validated.
struct LoadedCase {
  cases::CaseInfo info;
  std::unique_ptr<StudyRun> run;
  const StudyEntry* entry = nullptr;  ///< the study's registry record
  /// The work and memory the study's loader estimated from its keys (cases/budget.hpp).
  std::vector<cases::Demand> demands;
  /// Loaded with LoadOptions::allow_large: its sensitivity part's re-solves are too.
  bool allow_large = false;
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

/// Reads the keys every case has besides `study` (name, description, expect, render, sweep,
/// source, sensitivity) from the root mapping into out.info; errors into root.diag().
void read_case_parts(cases::Map& root, LoadedCase& out);

}  // namespace armstudy::app
