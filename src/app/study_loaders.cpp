// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The one list of armstudy's studies (app/study_loaders.hpp): a study is added here, by its
// name, its case loader and its results.json part, and then gets its run and report
// parts in app/study_registry.cpp (the program refuses to start while one is missing). The
// fuzz build compiles this file as it is: it may name loaders and sections only, never a
// solver, a scene or a report.
#include "app/study_loaders.hpp"

#include "cases/pendulum_case.hpp"
#include "cases/placement_case.hpp"
#include "cases/throwing_case.hpp"
#include "cases/time_optimal_case.hpp"
#include "studies/pendulum/study_results.hpp"
#include "studies/placement/study_results.hpp"
#include "studies/throwing/study_results.hpp"
#include "studies/time_optimal/study_results.hpp"

namespace armstudy::app {

const std::vector<StudyLoader>& study_loaders() {
  static const std::vector<StudyLoader> loaders = {
      study_loader<studies::placement::StudyResults, &cases::load_placement>("placement"),
      study_loader<studies::PendulumStudyResults, &cases::load_pendulum_spec>("pendulum"),
      study_loader<studies::ThrowingStudyResults, &cases::load_throwing_spec>("throwing"),
      study_loader<studies::time_optimal::StudyResults, &cases::load_time_optimal>("time_optimal"),
  };
  return loaders;
}

}  // namespace armstudy::app
