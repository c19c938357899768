// The fuzz build's study registry: each study's loader from src/cases, as the pipelines
// (src/app/<study>_pipeline.cpp) call it, and where clang can build it its results.json
// section's strict reader (the same study_entry<Section> record), without their solvers, scenes and
// reports, so that the fuzz targets link only the loading and reading code and build in a minute
// with the sanitizers. The pipelines' load() functions are these calls and a check of the
// diagnostics; keep them in step.
#include <stdexcept>

#include "app/pipeline.hpp"
#include "app/run_case.hpp"
#include "app/study_entry.hpp"
#include "cases/pendulum_case.hpp"
#include "cases/placement_case.hpp"
#include "cases/throwing_case.hpp"
#include "cases/time_optimal_case.hpp"
#include "studies/pendulum/results_section.hpp"

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

// the fuzz build writes no report: this part is never called
void no_report(const nlohmann::json&, report::FigureWriter&, report::CasePage&) {
  throw std::logic_error("the fuzz build loads cases; it does not report them");
}

// A study whose results.json section clang 14 cannot instantiate the reader of (its
// std::optional members of nested structs with default member initializers are not
// constructible inside the enclosing class there; gcc reads them): the shared record is
// fuzzed, its section is not (the normal build's corpus replay reads the seeds' sections).
nlohmann::json no_schema() { return {}; }
void no_section_check(const nlohmann::json&) {}
StudyEntry without_section(std::string_view study, StudyEntry::Loader load) {
  return StudyEntry(study, "", load, &no_schema, &no_section_check, &no_report);
}

const std::vector<StudyEntry>& study_registry() {
  static const std::vector<StudyEntry> registry = {
      without_section("placement",
                      [](cases::Map& root, const cases::CaseInfo&) {
                        return loaded(cases::load_placement(root));
                      }),
      study_entry<studies::PendulumResultsSection>(
          "pendulum", "",
          [](cases::Map& root, const cases::CaseInfo&) {
            return loaded(cases::load_pendulum_spec(root));
          },
          &no_report),
      without_section("throwing",
                      [](cases::Map& root, const cases::CaseInfo&) {
                        return loaded(cases::load_throwing_spec(root));
                      }),
      without_section("time_optimal",
                      [](cases::Map& root, const cases::CaseInfo&) {
                        return loaded(cases::load_time_optimal(root));
                      }),
  };
  return registry;
}

const StudyEntry* find_study(std::string_view study) {
  for (const StudyEntry& e : study_registry())
    if (e.study == study) return &e;
  return nullptr;
}

// sweep.cpp's expand_sweep and merge.cpp's write_merged write with it; the fuzz targets
// never expand nor write
void write_file_atomic(const std::filesystem::path&, const std::string&) {
  throw std::logic_error("the fuzz build writes no files");
}

}  // namespace armstudy::app
