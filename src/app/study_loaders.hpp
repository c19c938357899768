// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The loading half of a study's registry record: its name, its case loader (src/cases) and
/// its results.json part's schema and strict reader, with nothing of its solver, scenes
/// or report. study_loaders() (app/study_loaders.cpp) is the one list of armstudy's
/// studies: the program's registry (app/study_registry.cpp) extends each of its records
/// with the study's run and report parts (StudyParts, app/pipeline.hpp), and the fuzz build
/// (tests/fuzz) links this list alone, so that a study added here is loaded and read there
/// too.

#include <any>
#include <string>
#include <string_view>
#include <typeindex>
#include <vector>

#include <nlohmann/json.hpp>

#include "cases/yaml_reader.hpp"
#include "report/results_fields.hpp"

namespace armstudy::app {

/// A study's case loader and results.json reader. Build one with study_loader<>() below.
struct StudyLoader {
  /// Reads the study's keys from the root mapping (every error into root.diag()): the
  /// study's spec, or nothing when root.diag() holds an error.
  using Load = std::any (*)(cases::Map& root);
  using StudyResultsSchema = nlohmann::json (*)();
  using StudyResultsCheck = void (*)(const nlohmann::json& results);

  std::string_view study;     ///< "placement", "pendulum", "throwing", "time_optimal"
  std::type_index spec_type;  ///< the type of the spec `load` returns
  Load load = nullptr;
  /// The JSON Schema of results[study] (results.schema.json holds it).
  StudyResultsSchema results_schema = nullptr;
  /// Reads results[study] of a whole results.json strictly into the typed results.
  /// @throws report::ResultsError naming the JSON pointer of the first problem.
  StudyResultsCheck check_results = nullptr;
};

/// The loader record of `study`: its cases are read by `Load` (cases::Map& -> the study's
/// spec, e.g. cases::load_placement), its results.json part is `Results`
/// (studies/<study>/study_results.hpp).
template <class Results, auto Load>
StudyLoader study_loader(std::string_view study) {
  using Spec = decltype(Load(std::declval<cases::Map&>()));
  static const std::string name(study);
  return StudyLoader{study, typeid(Spec),
                     [](cases::Map& root) -> std::any {
                       Spec spec = Load(root);
                       if (!root.diag().empty()) return {};
                       return spec;
                     },
                     [] { return report::json_schema<Results>(); },
                     [](const nlohmann::json& results) {
                       (void)report::read_study_results<Results>(results, name);
                     }};
}

/// Every study armstudy knows, its loading half, in the order of --help (app/study_loaders.cpp).
const std::vector<StudyLoader>& study_loaders();

}  // namespace armstudy::app
