// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Adding a study is its folder, one line in the list of studies and its parts in the registry
// (docs/development.md, "Adding a study"): a trivial study defined here, with its typed
// results.json part, loader, solver, checks, key figures and report sections, runs through
// run_case like the bundled studies and gets its results.json (written from and read back into
// its typed results) and its index.html. The last test checks that every registered study has
// each step's place, and that the steps name them.
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
#include "cli/merge.hpp"
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

// src/studies/<study>/: the spec, the answer and the typed results (here: sums of 1..n)
struct TallySpec {
  int n = 3;
};
struct TallyResults {
  int n = 0;
  long long sum = 0;
  std::vector<double> squares_m2;
};
template <class V>
void fields(V& v, TallyResults& x) {
  v("n", x.n, "how far to count");
  v("sum", x.sum, "1 + 2 + ... + n");
  v("squares_m2", x.squares_m2, "k^2 for k = 1..n");
}

// src/cases/<study>_case.cpp: the case file's `tally:` keys -> the spec
TallySpec load_tally_spec(cases::Map& root) {
  TallySpec spec;
  if (auto m = root.map("tally")) {
    spec.n = m->integer_or("n", 3, 1, 1000);
    m->finish();
  }
  return spec;
}

// src/app/<study>_pipeline.cpp: the study in the pipeline
class TallyRun final : public StudyRun {
 public:
  using SpecType = TallySpec;        // the spec it is made from (TypedStudyRun names both)
  using ResultsType = TallyResults;  // its results.json part
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
  TallyResults section_;
};

// src/report/<study>_section.cpp: the study's sections, from its typed results
void tally_sections(const TallyResults& s, const report::ResultsRecord&, report::FigureWriter&,
                    report::CasePage& page) {
  report::Section sec;
  sec.id = "tally";
  sec.heading = "The tally";
  sec.paragraph("1 + ... + " + std::to_string(s.n) + " = " + std::to_string(s.sum));
  page.sections.push_back(std::move(sec));
}

// src/report/<study>_answer.cpp (optional): its lines of the answer box on page 1
void tally_answer(const TallyResults& s, const report::ResultsRecord&, report::AnswerBox& a) {
  a.binding.push_back("nothing binds a count to " + std::to_string(s.n));
}

// src/app/study_loaders.cpp: its line in the one list of studies (the fuzz build's too)
const StudyLoader kTallyLoader = study_loader<TallyResults, &load_tally_spec>("tally");
// src/app/<study>_pipeline.cpp: its parts (the answer lines and the index figure optional),
// joined to its loader in src/app/study_registry.cpp by the spec its run takes
const StudyEntry kTally(kTallyLoader, study_parts<TallyRun>("counts", &tally_sections));
const StudyEntry kTallyAnswered(kTallyLoader,
                                study_parts<TallyRun>("counts", &tally_sections, &tally_answer));

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
  c.run = entry.load(root);
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
  EXPECT_NO_THROW(kTally.check_results(r));
  EXPECT_EQ(kTally.results_schema()["properties"]["sum"]["type"], "integer");
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

// a study cannot be registered without its report (or any other part), nor without the parts
// of its spec
TEST(AddedStudy, ARecordWithoutAPartIsRefused) {
  EXPECT_THROW(StudyEntry(kTallyLoader, study_parts<TallyRun>("counts", nullptr)),
               std::invalid_argument);
  StudyLoader no_reader = kTallyLoader;
  no_reader.check_results = nullptr;
  EXPECT_THROW(StudyEntry(no_reader, study_parts<TallyRun>("counts", &tally_sections)),
               std::invalid_argument);
  StudyParts other_spec = study_parts<TallyRun>("counts", &tally_sections);
  other_spec.spec_type = typeid(int);
  EXPECT_THROW(StudyEntry(kTallyLoader, other_spec), std::invalid_argument);
  // a study in the list without its parts in the registry, and parts without a study
  EXPECT_THROW(with_parts({kTallyLoader}, {}), std::logic_error);
  EXPECT_THROW(with_parts({}, {study_parts<TallyRun>("counts", &tally_sections)}),
               std::logic_error);
  EXPECT_EQ(
      with_parts({kTallyLoader}, {study_parts<TallyRun>("counts", &tally_sections)}).at(0).study,
      "tally");
}

// a case with an error in its study's keys loads no run (load_case then reports the error)
TEST(AddedStudy, ACaseWithAnErrorLoadsNoRun) {
  cases::Diagnostics diag("tally.yaml");
  cases::Map root(YAML::Load("study: tally\nname: t\ntally: {n: 0}\n"), diag, "");
  EXPECT_EQ(kTally.load(root), nullptr);
  EXPECT_FALSE(diag.empty());
}

bool has_file(const std::string& path) { return fs::exists(armstudy::testing::kSource / path); }
bool file_has(const std::string& path, const std::string& text) {
  return armstudy::testing::slurp(armstudy::testing::kSource / path).find(text) !=
         std::string::npos;
}

// every registered study has the place of each step of "Adding a study" (docs/development.md)
// that a test can see, and the steps name every place a study needs
TEST(AddedStudy, EveryStudyHasEachStepsPlace) {
  for (const StudyEntry& e : study_registry()) {
    const std::string s(e.study);
    EXPECT_TRUE(has_file("src/studies/" + s + "/study_results.hpp")) << s << ": step 1";
    EXPECT_TRUE(has_file("src/cases/" + s + "_case.cpp")) << s << ": step 2";
    EXPECT_TRUE(file_has("src/app/study_loaders.cpp", '"' + s + '"')) << s << ": step 3";
    EXPECT_TRUE(file_has("src/app/" + s + "_pipeline.cpp", s + "_parts()")) << s << ": step 4";
    EXPECT_TRUE(file_has("src/app/study_registry.cpp", s + "_parts()")) << s << ": step 4";
    EXPECT_TRUE(has_file("src/report/" + s + "_section.cpp")) << s << ": step 5";
    EXPECT_TRUE(file_has("src/report/study_sections.hpp", s + "_sections(")) << s << ": step 5";
    // step 7: its index figure's file is a reserved run-level name (cli::run_level_file)
    if (!e.index_figure.file.empty()) {
      EXPECT_NE(cli::run_level_file(std::string(e.index_figure.file)), nullptr) << s;
    }
    EXPECT_TRUE(file_has("results.schema.json", '"' + s + "\": {")) << s << ": step 8";
    bool bundled = false;
    for (const auto& f : fs::directory_iterator(armstudy::testing::kSource / "reports/cases"))
      bundled = bundled ||
                armstudy::testing::slurp(f.path()).find("study: " + s + "\n") != std::string::npos;
    EXPECT_TRUE(bundled) << s << ": step 9 (a bundled case in reports/cases/)";
  }
  // the fuzz build compiles the one list and builds its registry from it, naming no study
  EXPECT_TRUE(file_has("tests/fuzz/CMakeLists.txt", "${ROOT}/src/app/study_loaders.cpp"));
  EXPECT_TRUE(file_has("tests/fuzz/fuzz_registry.cpp", "with_parts(study_loaders()"));
  for (const StudyEntry& e : study_registry())
    EXPECT_FALSE(file_has("tests/fuzz/fuzz_registry.cpp", '"' + std::string(e.study) + '"'))
        << "tests/fuzz/fuzz_registry.cpp names study '" << e.study << "': it takes them all from "
        << "src/app/study_loaders.cpp";
  for (const char* place : {"src/studies/foo/", "src/cases/foo_case.", "src/app/study_loaders.cpp",
                            "src/app/foo_pipeline.cpp", "src/app/study_registry.cpp",
                            "src/report/foo_section.cpp", "report/study_sections.hpp",
                            "src/scene/foo_frames.", "run_level_file", "report::run_level_outputs",
                            "tests/fuzz/CMakeLists.txt", "results.schema.json", "reports/cases/"})
    EXPECT_TRUE(file_has("docs/development.md", place))
        << "docs/development.md, \"Adding a study\", does not name " << place;
}

}  // namespace
}  // namespace armstudy::app
