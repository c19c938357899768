// Adding a study is its folder and one registry record (docs/development.md, "Adding a study"): a
// trivial study defined here, with its typed results.json section, loader, solver, checks, key
// figures and report sections, runs through run_case like the bundled studies and gets its
// results.json (written from and read back into its typed section) and its index.html.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>
#include <nlohmann/json.hpp>

#include "app/pipeline.hpp"
#include "app/run_case.hpp"
#include "app/study_entry.hpp"
#include "cases/yaml_reader.hpp"
#include "report/answer_box.hpp"
#include "report/case_report.hpp"
#include "report/page.hpp"
#include "report/results_fields.hpp"
#include "report/results_record.hpp"
#include "testing/files.hpp"

namespace armstudy::app {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

// src/studies/<study>/: the spec, the answer and the typed section (here: sums of 1..n)
struct TallySpec {
  int n = 3;
};
struct TallySection {
  int n = 0;
  long long sum = 0;
  std::vector<double> squares_m2;
};
template <class V>
void fields(V& v, TallySection& x) {
  v("n", x.n, "how far to count");
  v("sum", x.sum, "1 + 2 + ... + n");
  v("squares_m2", x.squares_m2, "k^2 for k = 1..n");
}

// src/app/<study>_pipeline.cpp: the study in the pipeline
class TallyRun final : public StudyRun {
 public:
  explicit TallyRun(TallySpec spec) : spec_(spec) {}
  studies::Status solve(const studies::ProgressFn&) override {
    section_.n = spec_.n;
    for (int k = 1; k <= spec_.n; ++k) {
      section_.sum += k;
      section_.squares_m2.push_back(double(k) * k);
    }
    return studies::Status::kSolved;
  }
  std::string message() const override { return "counted to " + std::to_string(spec_.n); }
  std::vector<studies::Check> checks() const override {
    return {studies::make_check("tally_gauss", "sum equals n (n + 1) / 2: the difference",
                                std::abs(double(section_.sum) - spec_.n * (spec_.n + 1) / 2.0),
                                0.0)};
  }
  json results() const override { return report::to_json(section_); }
  std::vector<KeyFigure> key_figures() const override {
    return {{"sum", double(section_.sum), "", "the sum"}};
  }

 private:
  TallySpec spec_;
  TallySection section_;
};

std::unique_ptr<StudyRun> load_tally(cases::Map& root, const cases::CaseInfo&) {
  TallySpec spec;
  if (auto m = root.map("tally")) {
    spec.n = m->integer_or("n", 3, 1, 1000);
    m->finish();
  }
  return std::make_unique<TallyRun>(spec);
}

// src/report/<study>_section.cpp: the study's sections, from its typed section
void tally_sections(const TallySection& s, const report::ResultsRecord&, report::FigureWriter&,
                    report::CasePage& page) {
  report::Section sec;
  sec.id = "tally";
  sec.heading = "The tally";
  sec.paragraph("1 + ... + " + std::to_string(s.n) + " = " + std::to_string(s.sum));
  page.sections.push_back(std::move(sec));
}

// src/report/<study>_answer.cpp (optional): its lines of the answer box on page 1
void tally_answer(const TallySection& s, const report::ResultsRecord&, report::AnswerBox& a) {
  a.binding.push_back("nothing binds a count to " + std::to_string(s.n));
}

// src/app/study_registry.cpp: its one line (the answer lines and the index figure optional)
const StudyEntry kTally =
    study_entry<TallySection>("tally", "counts", &load_tally, &tally_sections);
const StudyEntry kTallyAnswered =
    study_entry<TallySection>("tally", "counts", &load_tally, &tally_sections, &tally_answer);

CaseOutcome run_tally(const StudyEntry& entry, const fs::path& out) {
  const std::string yaml = "study: tally\nname: tally-case\ntally: {n: 4}\n";
  LoadedCase c;
  c.info.name = "tally-case";
  c.info.study = "tally";
  c.info.path = "tally.yaml";
  c.info.yaml = yaml;
  c.info.sha256 = std::string(64, '0');
  cases::Diagnostics diag("tally.yaml");
  cases::Map root(YAML::Load(yaml), diag, "");
  root.get("study");
  root.get("name");
  c.run = entry.load(root, c.info);
  root.finish();
  EXPECT_TRUE(diag.empty());
  c.entry = &entry;
  RunOptions options;
  options.out_dir = out;
  options.render = false;
  return run_case(c, options, {});
}

TEST(AddedStudy, RunsThroughRunCaseIntoResultsJsonAndIndexHtml) {
  const fs::path out = armstudy::testing::fresh_dir("added_study");
  const CaseOutcome o = run_tally(kTally, out);
  EXPECT_EQ(o.exit_code, 0) << o.message;
  const json r = json::parse(armstudy::testing::slurp(out / "tally-case" / "results.json"));
  EXPECT_EQ(r["study"], "tally");
  EXPECT_EQ(r["status"], "solved");
  EXPECT_EQ(r["tally"]["sum"], 10);
  EXPECT_EQ(r["key_figures"][0]["name"], "sum");
  EXPECT_TRUE(r["checks"][0]["passed"].get<bool>());
  EXPECT_NO_THROW(kTally.check_section(r));
  EXPECT_EQ(kTally.section_schema()["properties"]["sum"]["type"], "integer");
  const std::string html = armstudy::testing::slurp(out / "tally-case" / "index.html");
  EXPECT_NE(html.find("1 + ... + 4 = 10"), std::string::npos);
  // the shared record reads back typed; the parts a study may leave out default to none
  EXPECT_EQ(report::read_record(r).key_figures.at(0).value, 10);
  EXPECT_EQ(kTally.answer, nullptr);
  EXPECT_EQ(kTally.index_figure.draw, nullptr);
  EXPECT_EQ(report::write_index(out, {{kTally.study, kTally.answer, kTally.index_figure}}), 1);
  EXPECT_NE(armstudy::testing::slurp(out / "index.html").find("tally-case/index.html"),
            std::string::npos);
  fs::remove_all(out);
}

// a study's own lines of the answer box come from its record, not from its name
TEST(AddedStudy, ItsAnswerLinesComeFromItsRecord) {
  const fs::path out = armstudy::testing::fresh_dir("added_study_answer");
  EXPECT_EQ(run_tally(kTallyAnswered, out).exit_code, 0);
  const std::string html = armstudy::testing::slurp(out / "tally-case" / "index.html");
  EXPECT_NE(html.find("nothing binds a count to 4"), std::string::npos);
  fs::remove_all(out);
}

// a study cannot be registered without its report (or any other part)
TEST(AddedStudy, ARecordWithoutReportSectionsIsRefused) {
  EXPECT_THROW(StudyEntry("tally", "counts", &load_tally, kTally.section_schema,
                          kTally.check_section, nullptr),
               std::invalid_argument);
  EXPECT_THROW(study_entry<TallySection>("tally", "counts", &load_tally, nullptr),
               std::invalid_argument);
}

// the fuzz build links the loaders without the solvers through a registry of its own
// (tests/fuzz/fuzz_registry.cpp, step 6 of "Adding a study"): every study of this registry
// has its record there too
TEST(AddedStudy, EveryRegisteredStudyIsInTheFuzzRegistry) {
  const std::string fuzz =
      armstudy::testing::slurp(armstudy::testing::kSource / "tests/fuzz/fuzz_registry.cpp");
  for (const StudyEntry& e : study_registry()) {
    std::string quoted = "\"";
    quoted += e.study;
    quoted += '"';
    EXPECT_NE(fuzz.find(quoted), std::string::npos)
        << "study '" << e.study << "' has no record in tests/fuzz/fuzz_registry.cpp";
  }
}

}  // namespace
}  // namespace armstudy::app
