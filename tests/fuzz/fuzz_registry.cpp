// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The fuzz build's study registry: the one list of studies (src/app/study_loaders.cpp: each
// study's case loader and results.json part's strict reader, compiled here as in the
// program), each extended with stand-ins for the parts the fuzz targets never call (the run
// and the report), so that the fuzz targets link only the loading and reading code and build
// in a minute with the sanitizers. Nothing here names a study: a study added to that list is
// loaded and read here too.
#include <stdexcept>

#include "app/pipeline.hpp"
#include "app/run_case.hpp"

namespace armstudy::app {
namespace {

// a loaded case: the spec the loader read, never solved
class Loaded : public StudyRun {
 public:
  explicit Loaded(std::any spec) : spec_(std::move(spec)) {}
  studies::Status solve(const studies::ProgressFn&) override {
    throw std::logic_error("the fuzz build loads cases; it does not solve them");
  }
  std::string message() const override { return ""; }
  nlohmann::json results() const override { return {}; }

 private:
  std::any spec_;
};

std::unique_ptr<StudyRun> loaded(std::any spec) {
  return std::make_unique<Loaded>(std::move(spec));
}

// the fuzz build writes no report: this part is never called
void no_report(const std::string&, const nlohmann::json&, const report::ResultsRecord&,
               report::FigureWriter&, report::CasePage&) {
  throw std::logic_error("the fuzz build loads cases; it does not report them");
}

}  // namespace

const std::vector<StudyEntry>& study_registry() {
  static const std::vector<StudyEntry> registry = [] {
    std::vector<StudyParts> parts;
    for (const StudyLoader& l : study_loaders())
      parts.push_back(StudyParts{l.spec_type, "", &loaded, &no_report, {}, {}});
    return with_parts(study_loaders(), parts);
  }();
  return registry;
}

// sweep.cpp's expand_sweep and merge.cpp's write_merged write with it; the fuzz targets
// never expand nor write
void write_file_atomic(const std::filesystem::path&, const std::string&) {
  throw std::logic_error("the fuzz build writes no files");
}

}  // namespace armstudy::app
