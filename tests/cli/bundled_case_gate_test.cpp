// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The gate of the bundled cases (reports/cases/*.yaml): each one, run as `armstudy run
// --no-render --no-sensitivity` runs it (app::run_case), ends with the status it expects and
// passes every check, the study's and the source comparison's, each named with its value
// where it fails. One test per case.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/pipeline.hpp"
#include "app/run_case.hpp"
#include "testing/files.hpp"

namespace armstudy {
namespace {
namespace fs = std::filesystem;

// the bundled case files' stems, sorted, but the throws: their whole run (about a minute of
// CPU each) is BrowserReport's (the Release suite), and its
// BundledResultsValidateAndCiFilesCountEveryCheck holds them to the same gate (status as
// expected, every check passed)
std::vector<std::string> bundled_case_stems() {
  std::vector<std::string> stems;
  for (const auto& e : fs::directory_iterator(testing::kSource / "reports/cases"))
    if (e.path().extension() == ".yaml" && e.path().stem().string().rfind("throwing", 0) != 0)
      stems.push_back(e.path().stem().string());
  std::sort(stems.begin(), stems.end());
  return stems;
}

class BundledCaseGate : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledCaseGate, EndsAsItExpectsWithEveryCheckPassed) {
  const fs::path file = testing::kSource / "reports/cases" / (GetParam() + ".yaml");
  app::LoadedCase c = app::load_case(file.string());
  app::RunOptions options;
  options.out_dir = testing::fresh_dir("gate_" + GetParam());
  options.render = false;
  options.sensitivity = false;
  const app::CaseOutcome outcome = app::run_case(c, options, {});
  EXPECT_EQ(outcome.exit_code, 0) << outcome.message;
  const nlohmann::json j = nlohmann::json::parse(testing::slurp(outcome.folder / "results.json"));
  const std::string expect = c.info.expect_unsolvable ? "unsolvable" : "solved";
  EXPECT_EQ(j["status"], expect) << j.value("message", "");
  if (expect == "solved") {
    EXPECT_FALSE(j["checks"].empty());
  }
  for (const auto& check : j["checks"])
    EXPECT_TRUE(check["passed"].get<bool>())
        << check["name"] << ": value " << check["value"] << " against its tolerance "
        << check["tolerance"] << " (" << check["description"] << ")";
  fs::remove_all(options.out_dir);
}

INSTANTIATE_TEST_SUITE_P(Bundled, BundledCaseGate, ::testing::ValuesIn(bundled_case_stems()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           std::string name = param.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace armstudy
