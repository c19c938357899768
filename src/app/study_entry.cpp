#include "app/study_entry.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace armstudy::app {

StudyEntry::StudyEntry(std::string_view study_, std::string_view summary_, Loader load_,
                       SectionSchema schema_, SectionCheck check_, ReportSections report_,
                       report::StudyAnswer answer_, report::IndexFigure index_figure_)
    : study(study_),
      summary(summary_),
      load(load_),
      section_schema(schema_),
      check_section(std::move(check_)),
      report(std::move(report_)),
      answer(std::move(answer_)),
      index_figure(index_figure_) {
  const char* missing = !load             ? "a loader"
                        : !section_schema ? "a results.json schema"
                        : !check_section  ? "a results.json reader"
                        : !report         ? "report sections"
                                          : nullptr;
  if (study.empty() || missing)
    throw std::invalid_argument("study '" + std::string(study) + "' registered without " +
                                (missing ? missing : "a name"));
}

}  // namespace armstudy::app
