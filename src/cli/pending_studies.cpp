// Studies whose pipeline has not landed yet: loading such a case is a clear error
// (exit 2), never a fake result. Each study's own <study>_pipeline.cpp replaces its entry.
#include "cli/pipeline.hpp"

namespace armstudy::app {
namespace {
template <const char* kName>
std::unique_ptr<StudyRun> not_available(cases::Map& root, const cases::CaseInfo&) {
  root.error("study", std::string("study '") + kName +
                          "' is not available in this version of armstudy; expected another study");
  for (const auto& kv : root.node()) root.get(kv.first.Scalar());
  return nullptr;
}
constexpr char kTimeOptimal[] = "time_optimal";
}  // namespace

StudyEntry time_optimal_entry() {
  return {"time_optimal", "(not available yet)", &not_available<kTimeOptimal>};
}

}  // namespace armstudy::app
