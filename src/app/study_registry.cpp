#include "app/pipeline.hpp"

namespace armstudy::app {

// each study's pipeline file (src/app/<study>_pipeline.cpp) defines its entry
StudyEntry placement_entry();
StudyEntry pendulum_entry();
StudyEntry throwing_entry();
StudyEntry time_optimal_entry();

const std::vector<StudyEntry>& study_registry() {
  static const std::vector<StudyEntry> registry = {
      placement_entry(),
      pendulum_entry(),
      throwing_entry(),
      time_optimal_entry(),
  };
  return registry;
}

const StudyEntry* find_study(std::string_view study) {
  for (const StudyEntry& e : study_registry())
    if (e.study == study) return &e;
  return nullptr;
}

std::vector<report::IndexStudy> index_studies() {
  std::vector<report::IndexStudy> out;
  for (const StudyEntry& e : study_registry()) out.push_back({e.study, e.answer, e.index_figure});
  return out;
}

}  // namespace armstudy::app
