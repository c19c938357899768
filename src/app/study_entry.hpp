#pragma once
/// Builds a study's registry record from its typed results.json section: the section's
/// schema and strict reader come from the Section's `fields` (report/results_fields.hpp).

#include "app/pipeline.hpp"
#include "report/results_fields.hpp"

namespace armstudy::app {

/// What every study's StudyRun has the same way: its spec, its result (with the message) and
/// results() written from its typed results.json section. A study derives from it and
/// writes solve(), section() and what it adds (checks, key figures, frames).
template <class Spec, class Result, class Section>
class TypedStudyRun : public StudyRun {
 public:
  explicit TypedStudyRun(Spec spec) : spec_(std::move(spec)) {}
  std::string message() const override { return result_.message; }
  nlohmann::json results() const final { return report::to_json(section()); }
  /// The study's section of results.json, typed (studies/<study>/results_section.hpp).
  virtual Section section() const = 0;

 protected:
  Spec spec_;
  Result result_;
};

/// The record of `study`, whose results.json section is `Section` (its answer-box lines and
/// index figure optional).
template <class Section>
StudyEntry study_entry(std::string_view study, std::string_view summary, StudyEntry::Loader load,
                       ReportSections report, report::StudyAnswer answer = nullptr,
                       report::IndexFigure index_figure = {}) {
  static const std::string name(study);
  return StudyEntry(
      study, summary, load, [] { return report::json_schema<Section>(); },
      [](const nlohmann::json& results) { (void)report::read_section<Section>(results, name); },
      report, answer, index_figure);
}

}  // namespace armstudy::app
