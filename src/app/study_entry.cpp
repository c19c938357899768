// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "app/study_entry.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace armstudy::app {

StudyEntry::StudyEntry(const StudyLoader& loader, const StudyParts& parts)
    : study(loader.study),
      summary(parts.summary),
      results_schema(loader.results_schema),
      check_results(loader.check_results),
      index_figure(parts.index_figure),
      load_spec_(loader.load),
      make_run_(parts.make_run) {
  // the report parts read the study's section from results[study]: its name, from the list
  const std::string name(study);
  if (parts.report)
    report = [name, f = parts.report](const nlohmann::json& results,
                                      const report::ResultsRecord& record,
                                      report::FigureWriter& figures, report::CasePage& page) {
      f(name, results, record, figures, page);
    };
  if (parts.answer)
    answer = [name, f = parts.answer](const nlohmann::json& results,
                                      const report::ResultsRecord& record,
                                      report::AnswerBox& box) { f(name, results, record, box); };
  const char* missing = !load_spec_       ? "a loader"
                        : !results_schema ? "a results.json schema"
                        : !check_results  ? "a results.json reader"
                        : !make_run_      ? "a run"
                        : !report         ? "report sections"
                                          : nullptr;
  if (study.empty() || missing)
    throw std::invalid_argument("study '" + std::string(study) + "' registered without " +
                                (missing ? missing : "a name"));
  if (loader.spec_type != parts.spec_type)
    throw std::invalid_argument("study '" + std::string(study) +
                                "' registered with a run of another spec than its loader reads");
}

std::unique_ptr<StudyRun> StudyEntry::load(cases::Map& root) const {
  std::any spec = load_spec_(root);
  if (!spec.has_value()) return nullptr;
  return make_run_(std::move(spec));
}

std::vector<StudyEntry> with_parts(const std::vector<StudyLoader>& loaders,
                                   const std::vector<StudyParts>& parts) {
  std::vector<StudyEntry> out;
  std::vector<bool> used(parts.size(), false);
  for (const StudyLoader& l : loaders) {
    size_t k = 0;
    while (k < parts.size() && parts[k].spec_type != l.spec_type) ++k;
    if (k == parts.size())
      throw std::logic_error("study '" + std::string(l.study) +
                             "' (app/study_loaders.cpp) has no run and report parts (its "
                             "<study>_parts() in app/study_registry.cpp)");
    used[k] = true;
    out.emplace_back(l, parts[k]);
  }
  for (size_t k = 0; k < parts.size(); ++k)
    if (!used[k])
      throw std::logic_error("the parts '" + std::string(parts[k].summary) +
                             "' take a spec no study of app/study_loaders.cpp loads");
  return out;
}

const StudyEntry* find_study(std::string_view study) {
  for (const StudyEntry& e : study_registry())
    if (e.study == study) return &e;
  return nullptr;
}

}  // namespace armstudy::app
