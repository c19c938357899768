// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The case format made from the loaders (app/case_keys.hpp): every key a loader reads has a
// meaning (cases/key_docs.cpp) and no meaning names a key no loader reads; case.schema.json
// and docs/case-reference.md are what the loaders make of them today (regenerate with
// ARMSTUDY_WRITE_SCHEMA=1); every "expected one of" names every key of its mapping.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "app/case_keys.hpp"
#include "app/study_loaders.hpp"
#include "cases/key_docs.hpp"
#include "cases/placement_case.hpp"
#include "testing/case_keys.hpp"
#include "testing/files.hpp"

namespace {
namespace fs = std::filesystem;
using armstudy::app::case_keys;

const fs::path kSource = ARMSTUDY_SOURCE_DIR;
const char* kRegenerate =
    "regenerate it with ARMSTUDY_WRITE_SCHEMA=1 build/tests/cases_tests "
    "--gtest_filter=CaseSchema.*";

// a key a loader reads must say what it means: the entry to add is named
TEST(CaseSchema, EveryKeyALoaderReadsHasAMeaning) {
  std::set<std::pair<std::string, std::string>> read;  // (study, path)
  for (const auto& l : armstudy::app::study_loaders()) {
    const std::string study(l.study);
    const auto keys = case_keys(study);
    EXPECT_GT(keys.size(), 10u) << study;
    for (const auto& k : keys) {
      read.insert({study, k.info.path});
      EXPECT_TRUE(k.doc != nullptr)
          << "the " << study << " loader reads '" << k.info.path << "' (" << k.info.kind
          << "), which src/cases/key_docs.cpp does not explain; add to key_docs():\n"
          << "      {\"" << study << "\", \"" << k.info.path << "\", \"<what it means>\"},\n"
          << "(\"\" instead of \"" << study << "\" when every study reads it alike), then "
          << kRegenerate;
    }
  }
  // no meaning of a key no loader reads (a renamed or removed key)
  for (const auto& d : armstudy::cases::key_docs()) {
    bool found = false;
    for (const auto& [study, path] : read)
      found |= armstudy::cases::key_doc_matches(d, path) && (d.study.empty() || d.study == study);
    EXPECT_TRUE(found) << "src/cases/key_docs.cpp explains '" << d.path << "'"
                       << (d.study.empty() ? "" : " of " + std::string(d.study))
                       << ", which no loader reads";
  }
}

// every branch is walked: the keys only one alternative reads are there too
TEST(CaseSchema, TheCatalogWalksEveryAlternative) {
  auto paths = [](const std::string& study) {
    std::set<std::string> p;
    for (const auto& k : case_keys(study)) p.insert(k.info.path);
    return p;
  };
  const auto placement = paths("placement");
  for (const char* k :
       {"placement.length_m", "placement.length_fraction", "placement.evaluate[].root_xy_m",
        "placement.evaluate[].x_s_m", "placement.evaluate[].phi_deg", "arm.links[].length",
        "render.width", "sensitivity[].key"})
    EXPECT_TRUE(placement.count(k)) << k;
  const auto time_optimal = paths("time_optimal");
  for (const char* k : {"time_optimal.path.kind", "time_optimal.path.points_m",
                        "time_optimal.joint_path.points_rad", "time_optimal.joint_path.range_rad"})
    EXPECT_TRUE(time_optimal.count(k)) << k;
  // kinds, units, ranges and defaults are the loader's own
  for (const auto& k : case_keys("placement")) {
    if (k.info.path == "placement.duration_s") {
      EXPECT_EQ(k.info.kind, "number");
      EXPECT_EQ(k.info.rule.unit, "s");
      EXPECT_TRUE(k.info.default_text.has_value());
    }
    if (k.info.path == "placement.samples") {
      EXPECT_EQ(k.info.kind, "integer");
      EXPECT_EQ(k.info.rule.min, 21);
    }
  }
}

// the generated files in the repository are what the loaders make today
TEST(CaseSchema, TheSchemaAndTheReferenceAreTheLoaders) {
  const std::string schema = armstudy::app::case_schema().dump(2) + "\n";
  const std::string reference = armstudy::app::case_reference_markdown();
  if (std::getenv("ARMSTUDY_WRITE_SCHEMA")) {
    std::ofstream(kSource / "case.schema.json", std::ios::binary) << schema;
    std::ofstream(kSource / "docs/case-reference.md", std::ios::binary) << reference;
    return;
  }
  EXPECT_TRUE(armstudy::testing::slurp(kSource / "case.schema.json") == schema)
      << "case.schema.json does not describe the keys the loaders read; " << kRegenerate;
  EXPECT_TRUE(armstudy::testing::slurp(kSource / "docs/case-reference.md") == reference)
      << "docs/case-reference.md does not describe the keys the loaders read; " << kRegenerate;
}

// an unknown key's message lists every key of its mapping, those a loader only checks for
// (length_m and length_fraction, one of which placement needs) included
TEST(CaseSchema, ExpectedOneOfNamesEveryKeyOfTheMapping) {
  armstudy::cases::Diagnostics d("c.yaml");
  const YAML::Node n = YAML::Load("placement:\n  length_fraction: 0.5\n  qqqqqqqqqq: 1\n");
  armstudy::cases::Map root(n, d, "");
  armstudy::testing::mark_cli_keys(root);
  armstudy::cases::load_placement(root);
  root.finish();
  std::string message;
  for (const auto& e : d.errors())
    if (e.format().find("qqqqqqqqqq") != std::string::npos) message = e.format();
  ASSERT_FALSE(message.empty());
  for (const auto& k : case_keys("placement")) {
    const std::string& p = k.info.path;
    if (p.rfind("placement.", 0) != 0 || p.find('.', 10) != std::string::npos ||
        p.find('[') != std::string::npos)
      continue;
    EXPECT_NE(message.find(p.substr(10)), std::string::npos) << p << " missing in: " << message;
  }
}

}  // namespace
