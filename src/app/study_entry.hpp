#pragma once
/// Builds a study's registry record from its typed results.json section: the section's
/// schema and strict reader come from the Section's `fields` (report/results_fields.hpp).

#include "app/pipeline.hpp"
#include "report/results_fields.hpp"

namespace armstudy::app {

/// The record of `study`, whose results.json section is `Section`.
template <class Section>
StudyEntry study_entry(std::string_view study, std::string_view summary, StudyEntry::Loader load,
                       ReportSections report) {
  static const std::string name(study);
  return StudyEntry(
      study, summary, load, [] { return report::json_schema<Section>(); },
      [](const nlohmann::json& results) { (void)report::read_section<Section>(results, name); }, report);
}

}  // namespace armstudy::app
