// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The fuzz corpus replayed in the normal build: every bad case file (tests/cases/bad),
// every input that ever crashed a reader (tests/fuzz/corpus), the fuzzers' seeds
// (tests/fuzz/seeds: small results.json and tolerances files) and the bundled cases and
// sweeps go through both fuzz entries (tests/fuzz/fuzz_entries.hpp), exactly as the
// libFuzzer targets run them: each reader loads the file or refuses it cleanly.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz/fuzz_entries.hpp"

namespace {
namespace fs = std::filesystem;

std::vector<fs::path> files_in(const std::string& folder) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(fs::path(ARMSTUDY_SOURCE_DIR) / folder))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void replay(const std::string& folder, size_t at_least) {
  const std::vector<fs::path> files = files_in(folder);
  EXPECT_GE(files.size(), at_least) << folder;
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    const std::string input = read(f);
    EXPECT_EQ(armstudy::fuzz::case_and_sweep_loaders(input), "");
    EXPECT_EQ(armstudy::fuzz::results_and_tolerances_readers(input), "");
    EXPECT_EQ(armstudy::fuzz::template_folder_reader(input), "");
  }
}

TEST(FuzzCorpus, EveryInputThatEverCrashedAReaderIsLoadedOrRefusedCleanly) {
  replay("tests/fuzz/corpus", 2);
}
TEST(FuzzCorpus, EveryBadCaseFileIsRefusedCleanlyByEveryReader) { replay("tests/cases/bad", 30); }
TEST(FuzzCorpus, EverySeedResultsAndTolerancesFileIsReadOrRefusedCleanly) {
  replay("tests/fuzz/seeds", 4);
}
// the report templates (ARMSTUDY_TEMPLATE_DIR), bundled and broken: each is read or refused
// with a message, and one read renders
TEST(FuzzCorpus, EveryTemplateBundledOrBrokenIsReadOrRefusedCleanly) {
  replay("templates", 3);
  replay("tests/fuzz/templates", 3);
}
TEST(FuzzCorpus, EveryBundledCaseAndSweepIsReadOrRefusedCleanly) {
  replay("reports/cases", 10);
  replay("reports/sweeps", 2);
}

}  // namespace
