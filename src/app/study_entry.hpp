#pragma once
/// Builds a study's registry record from its typed results.json section: the section's
/// schema and strict reader come from the Section's `fields` (report/results_fields.hpp).

#include "app/pipeline.hpp"
#include "report/results_fields.hpp"
#include "report/results_record.hpp"

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

/// A study's own sections of its case page, from its typed results.json section (read once
/// from results[study] by study_entry) and the shared record (frames, checks).
template <class Section>
using TypedSections = void (*)(const Section& section, const report::ResultsRecord& record,
                               report::FigureWriter& figures, report::CasePage& page);
/// A study's lines of its answer box, from its typed section and the shared record.
template <class Section>
using TypedAnswer = void (*)(const Section& section, const report::ResultsRecord& record,
                             report::AnswerBox& box);

/// The record of `study`, whose results.json section is `Section` (its answer-box lines and
/// index figure optional). The study name is spelled here once: the section's schema, its
/// strict reader and the report parts' typed section all read results[study].
template <class Section>
StudyEntry study_entry(std::string_view study, std::string_view summary, StudyEntry::Loader load,
                       TypedSections<Section> sections, TypedAnswer<Section> answer = nullptr,
                       report::IndexFigure index_figure = {}) {
  const std::string name(study);
  ReportSections report;
  if (sections)
    report = [name, sections](const nlohmann::json& results, report::FigureWriter& figures,
                              report::CasePage& page) {
      sections(report::read_section<Section>(results, name), report::read_record(results), figures,
               page);
    };
  report::StudyAnswer lines;
  if (answer)
    lines = [name, answer](const nlohmann::json& results, const report::ResultsRecord& record,
                           report::AnswerBox& box) {
      answer(report::read_section<Section>(results, name), record, box);
    };
  return StudyEntry(
      study, summary, load, [] { return report::json_schema<Section>(); },
      [name](const nlohmann::json& results) { (void)report::read_section<Section>(results, name); },
      std::move(report), std::move(lines), index_figure);
}

}  // namespace armstudy::app
