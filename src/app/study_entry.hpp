// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// What a study's pipeline (app/<study>_pipeline.cpp) builds its StudyRun and its registry
/// parts with.

#include "app/pipeline.hpp"
#include "report/results_fields.hpp"
#include "report/results_record.hpp"

namespace armstudy::app {

/// What every study's StudyRun has the same way: its spec, its result (with the message) and
/// results() written from its typed results.json part. A study derives from it and
/// writes solve(), study_results() and what it adds (checks, key figures, frames).
template <class Spec, class Result, class Results>
class TypedStudyRun : public StudyRun {
 public:
  using SpecType = Spec;
  using ResultsType = Results;
  explicit TypedStudyRun(Spec spec) : spec_(std::move(spec)) {}
  std::string message() const override { return result_.message; }
  nlohmann::json results() const final { return report::to_json(study_results()); }
  /// The study's part of results.json, typed (studies/<study>/study_results.hpp).
  virtual Results study_results() const = 0;

 protected:
  Spec spec_;
  Result result_;
};

/// A study's own sections of its case page, from its typed results.json part (read once
/// from results[study] by the registry) and the shared record (frames, checks).
template <class Results>
using TypedSections = void (*)(const Results& section, const report::ResultsRecord& record,
                               report::FigureWriter& figures, report::CasePage& page);
/// A study's lines of its answer box, from its typed results and the shared record.
template <class Results>
using TypedAnswer = void (*)(const Results& section, const report::ResultsRecord& record,
                             report::AnswerBox& box);

/// A study's parts (app/pipeline.hpp): its cases are solved by `Run` (a StudyRun made from
/// the study's spec, e.g. a TypedStudyRun, whose results.json part is Run::ResultsType);
/// its report parts receive that section, read once from results[study]; its answer-box
/// lines and index figure optional.
template <class Run>
StudyParts study_parts(std::string_view summary, TypedSections<typename Run::ResultsType> sections,
                       TypedAnswer<typename Run::ResultsType> answer = nullptr,
                       report::IndexFigure index_figure = {}) {
  using Spec = typename Run::SpecType;
  using Results = typename Run::ResultsType;
  StudyParts parts{typeid(Spec),
                   summary,
                   [](std::any spec) -> std::unique_ptr<StudyRun> {
                     return std::make_unique<Run>(std::any_cast<Spec>(std::move(spec)));
                   },
                   {},
                   {},
                   index_figure};
  if (sections)
    parts.report = [sections](const std::string& study, const nlohmann::json& results,
                              const report::ResultsRecord& record, report::FigureWriter& figures,
                              report::CasePage& page) {
      sections(report::read_study_results<Results>(results, study), record, figures, page);
    };
  if (answer)
    parts.answer = [answer](const std::string& study, const nlohmann::json& results,
                            const report::ResultsRecord& record, report::AnswerBox& box) {
      answer(report::read_study_results<Results>(results, study), record, box);
    };
  return parts;
}

}  // namespace armstudy::app
