// The fuzz build's study registry: each study's loader from src/cases, as the pipelines
// (src/app/<study>_pipeline.cpp) call it, without their solvers, scenes and reports, so
// that the fuzz target links only the loading code (cases, core, studies) and builds in a
// minute with the sanitizers. The pipelines' load() functions are these calls and a
// check of the diagnostics; keep them in step.
#include <stdexcept>

#include "app/pipeline.hpp"
#include "app/run_case.hpp"
#include "cases/pendulum_case.hpp"
#include "cases/placement_case.hpp"
#include "cases/throwing_case.hpp"
#include "cases/time_optimal_case.hpp"

namespace armstudy::app {
namespace {
template <typename Spec>
class Loaded : public StudyRun {
 public:
  explicit Loaded(Spec spec) : spec_(std::move(spec)) {}
  studies::Status solve(const studies::ProgressFn&) override {
    throw std::logic_error("the fuzz build loads cases; it does not solve them");
  }
  std::string message() const override { return ""; }
  nlohmann::json results() const override { return {}; }

 private:
  Spec spec_;
};

template <typename Spec>
std::unique_ptr<StudyRun> loaded(Spec spec) {
  return std::make_unique<Loaded<Spec>>(std::move(spec));
}
}  // namespace

// the fuzz build has no results.json and no report: these parts are never called
nlohmann::json no_schema() { return {}; }
void no_check(const nlohmann::json&) {}
void no_report(const nlohmann::json&, report::FigureWriter&, report::CasePage&) {
  throw std::logic_error("the fuzz build loads cases; it does not report them");
}

const std::vector<StudyEntry>& study_registry() {
  static const std::vector<StudyEntry> registry = {
      {"placement", "",
       [](cases::Map& root, const cases::CaseInfo&) { return loaded(cases::load_placement(root)); },
       &no_schema, &no_check, &no_report},
      {"pendulum", "",
       [](cases::Map& root, const cases::CaseInfo&) {
         return loaded(cases::load_pendulum_spec(root));
       },
       &no_schema, &no_check, &no_report},
      {"throwing", "",
       [](cases::Map& root, const cases::CaseInfo&) {
         return loaded(cases::load_throwing_spec(root));
       },
       &no_schema, &no_check, &no_report},
      {"time_optimal", "",
       [](cases::Map& root, const cases::CaseInfo&) {
         return loaded(cases::load_time_optimal(root));
       },
       &no_schema, &no_check, &no_report},
  };
  return registry;
}

// sweep.cpp's expand_sweep writes with it; the fuzz target never expands
void write_file_atomic(const std::filesystem::path&, const std::string&) {
  throw std::logic_error("the fuzz build writes no files");
}

}  // namespace armstudy::app
