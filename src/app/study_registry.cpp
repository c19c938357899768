// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The program's study registry: the one list of studies (app/study_loaders.cpp), each
// extended with its run and report parts from its pipeline file.
#include "app/pipeline.hpp"

namespace armstudy::app {

// each study's pipeline file (src/app/<study>_pipeline.cpp) defines its parts
StudyParts placement_parts();
StudyParts pendulum_parts();
StudyParts throwing_parts();
StudyParts time_optimal_parts();

const std::vector<StudyEntry>& study_registry() {
  static const std::vector<StudyEntry> registry =
      with_parts(study_loaders(),
                 {placement_parts(), pendulum_parts(), throwing_parts(), time_optimal_parts()});
  return registry;
}

std::vector<report::IndexStudy> index_studies() {
  std::vector<report::IndexStudy> out;
  for (const StudyEntry& e : study_registry()) out.push_back({e.study, e.answer, e.index_figure});
  return out;
}

}  // namespace armstudy::app
