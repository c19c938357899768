// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The bad-input corpus: every file in tests/cases/bad/ states in its header the exit code,
// the key words its message must contain and the position of the first error
// (`# expect-position: LINE:COL`, or `none`); `armstudy validate` and `armstudy run` must
// both fail with that code, print `file:line:col:` at that position, say it briefly (a
// hostile file is never quoted whole) and write nothing.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "testing/cli.hpp"

namespace {
namespace fs = std::filesystem;

struct Expectation {
  int exit_code = -1;
  std::vector<std::string> keywords;
  bool position = true;
  std::string line_col;  // "9:15" when the header gives it
};

Expectation read_expectation(const fs::path& file) {
  std::ifstream in(file);
  Expectation e;
  std::string line;
  while (std::getline(in, line) && line.rfind("#", 0) == 0) {
    if (line.rfind("# expect-exit:", 0) == 0) e.exit_code = std::stoi(line.substr(14));
    if (line.rfind("# expect-position: none", 0) == 0)
      e.position = false;
    else if (line.rfind("# expect-position: ", 0) == 0)
      e.line_col = line.substr(19);
    if (line.rfind("# expect:", 0) == 0) {
      std::stringstream ss(line.substr(9));
      std::string k;
      while (std::getline(ss, k, '|')) {
        k.erase(0, k.find_first_not_of(' '));
        k.erase(k.find_last_not_of(' ') + 1);
        if (!k.empty()) e.keywords.push_back(k);
      }
    }
  }
  return e;
}

using armstudy::testing::CliRun;
using armstudy::testing::run_cli;

std::vector<fs::path> corpus() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(fs::path(ARMSTUDY_SOURCE_DIR) / "tests/cases/bad"))
    if (e.path().extension() == ".yaml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(BadCaseCorpus, HasAtLeastThirtyFilesEachWithExpectations) {
  const auto files = corpus();
  EXPECT_GE(files.size(), 30u);
  for (const auto& f : files) {
    const Expectation e = read_expectation(f);
    EXPECT_EQ(e.exit_code, 2) << f;
    EXPECT_FALSE(e.keywords.empty()) << f;
    EXPECT_TRUE(!e.position || !e.line_col.empty()) << f << ": no '# expect-position: LINE:COL'";
  }
}

TEST(BadCaseCorpus, EveryFileFailsWithItsCodeMessageAndPositionAndWritesNothing) {
  const fs::path out =
      fs::temp_directory_path() / ("armstudy_bad_corpus_" + std::to_string(getpid()));
  for (const auto& f : corpus()) {
    SCOPED_TRACE(f.filename().string());
    const Expectation e = read_expectation(f);
    for (const std::string& cmd :
         {"validate " + f.string(), "run --no-render --out " + out.string() + " " + f.string()}) {
      const CliRun r = run_cli(cmd);
      EXPECT_EQ(r.exit_code, e.exit_code) << cmd << "\n" << r.output;
      for (const auto& k : e.keywords)
        EXPECT_NE(r.output.find(k), std::string::npos) << "missing '" << k << "' in:\n" << r.output;
      if (e.position) {
        const std::regex pos(
            std::regex_replace(f.string(), std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") +
            ":[0-9]+:[0-9]+: ");
        EXPECT_TRUE(std::regex_search(r.output, pos)) << "no file:line:col in:\n" << r.output;
        if (!e.line_col.empty()) {
          EXPECT_NE(r.output.find(f.string() + ":" + e.line_col + ": "), std::string::npos)
              << "no error at " << e.line_col << " in:\n"
              << r.output;
        }
      }
      // errors are capped and quoted briefly: never a whole hostile file
      EXPECT_LT(r.output.size(), 12000u) << r.output.substr(0, 2000);
    }
    EXPECT_FALSE(fs::exists(out)) << "output written for a bad case";
  }
  fs::remove_all(out);
}

}  // namespace
