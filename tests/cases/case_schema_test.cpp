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
#include "studies/placement/spec.hpp"
#include "studies/time_optimal/spec.hpp"
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

// the schema of `name` in `s`: the first "properties" entry of that name, depth first
const nlohmann::json* property(const nlohmann::json& s, const std::string& name) {
  if (!s.is_object() && !s.is_array()) return nullptr;
  if (s.is_object() && s.contains("properties") && s["properties"].contains(name))
    return &s["properties"][name];
  for (const auto& v : s)
    if (const auto* found = property(v, name)) return found;
  return nullptr;
}

// a list's default is the loader's own, in the key reference and the schema; the lists with
// none are those whose absence means none (no limit, no extra item) or that a case must give
TEST(CaseSchema, ListsHaveTheLoadersDefaults) {
  // (arm.links: without `arm:` the study's own arm; with arm.model, the model's links)
  const std::set<std::string> no_default = {"source.printed",
                                            "sensitivity",
                                            "arm.links",
                                            "arm.point_masses",
                                            "placement.torque_limits_Nm",
                                            "placement.power_limits_W",
                                            "placement.evaluate",
                                            "placement.evaluate[].root_xy_m",
                                            "placement.cycle_time.velocity_limit_rad_s",
                                            "placement.cycle_time.torque_limit_Nm",
                                            "placement.cycle_time.acceleration_limit_rad_s2",
                                            "time_optimal.acceleration_limit_rad_s2",
                                            "time_optimal.path.points_m",
                                            "time_optimal.joint_path.points_rad",
                                            "time_optimal.joint_path.range_rad"};
  for (const auto& l : armstudy::app::study_loaders())
    for (const auto& k : case_keys(std::string(l.study))) {
      if (k.info.kind != "numbers" && k.info.kind != "list") continue;
      const bool has =
          k.info.default_text || k.info.required || (k.doc && !k.doc->default_words.empty());
      EXPECT_TRUE(has || no_default.count(k.info.path))
          << l.study << ": '" << k.info.path << "' is a list without a default; pass the "
          << "loader's default to Map::numbers() or Map::seq()";
    }
  // placement.configurations and time_optimal.dp.convergence_segments: what the specs keep
  const nlohmann::json schema = armstudy::app::case_schema();
  const auto* configurations = property(schema, "configurations");
  ASSERT_NE(configurations, nullptr);
  ASSERT_TRUE(configurations->contains("default")) << configurations->dump();
  EXPECT_EQ((*configurations)["default"],
            nlohmann::json(armstudy::studies::placement::Spec{}.configurations));
  const auto* segments = property(schema, "convergence_segments");
  ASSERT_NE(segments, nullptr);
  ASSERT_TRUE(segments->contains("default")) << segments->dump();
  EXPECT_EQ((*segments)["default"],
            nlohmann::json(armstudy::studies::time_optimal::DpSettings{}.convergence_segments));
  const auto* states = property(schema, "states");
  ASSERT_NE(states, nullptr);
  ASSERT_TRUE(states->contains("default")) << states->dump();
  EXPECT_EQ((*states)["default"], nlohmann::json::array({"path_speed"}));
  std::string expected_row = "| `placement.configurations` | list of numbers |  | [";
  for (const int c : armstudy::studies::placement::Spec{}.configurations)
    expected_row += (expected_row.back() == '[' ? "" : ", ") + std::to_string(c);
  EXPECT_NE(armstudy::app::case_reference_markdown().find(expected_row + "] |"), std::string::npos)
      << expected_row;
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
