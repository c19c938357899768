// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// results.schema.json describes every study's section completely: its study sections are the
// JSON Schemas of the typed results (src/studies/<study>/study_results.hpp), so the file,
// the writer and the reader cannot drift apart.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/pipeline.hpp"
#include "report/results_fields.hpp"
#include "report/results_record.hpp"
#include "testing/files.hpp"

namespace armstudy::report {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kSchema = fs::path(ARMSTUDY_SOURCE_DIR) / "results.schema.json";

// the end of the JSON value that starts at text[at] ('{'), strings skipped
size_t value_end(const std::string& text, size_t at) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = at; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '{' || c == '[') {
      ++depth;
    } else if ((c == '}' || c == ']') && --depth == 0) {
      return i + 1;
    }
  }
  return std::string::npos;
}

// `text` with the value of properties/<name> (or, with `indent` "  ", the top-level <name>)
// replaced by `value`, the rest untouched
std::string with_section(std::string text, const std::string& name, const json& value,
                         const std::string& indent = "    ") {
  const std::string key = "\n" + indent + "\"" + name + "\": ";
  const size_t at = text.find(key);
  if (at == std::string::npos) throw std::runtime_error("results.schema.json has no " + name);
  const size_t start = at + key.size(), end = value_end(text, start);
  std::string dumped = value.dump(2), indented;
  for (char c : dumped) indented += c == '\n' ? "\n" + indent : std::string(1, c);
  return text.replace(start, end - start, indented);
}

// the shared record's schema (report/results_record.hpp) with the registry's studies: the
// "study" enum and one "required" line per study
json shared_schema() {
  json s = json_schema<ResultsRecord>();
  json names = json::array(), all_of = json::array();
  for (const app::StudyEntry& e : app::study_registry()) {
    const std::string study(e.study);
    names.push_back(study);
    all_of.push_back({{"if", {{"properties", {{"study", {{"const", study}}}}}}},
                      {"then", {{"required", json::array({study})}}}});
  }
  s["properties"]["study"]["enum"] = names;
  s["allOf"] = all_of;
  return s;
}

TEST(ResultsSchema, TheSharedRecordIsItsTypedSchema) {
  std::string text = armstudy::testing::slurp(kSchema);
  const json file = json::parse(text);
  const bool write = std::getenv("ARMSTUDY_WRITE_SCHEMA") != nullptr;
  const json want = shared_schema();
  if (write) {
    for (const auto& [key, value] : want["properties"].items())
      text = with_section(text, key, value);
    text = with_section(text, "required", want["required"], "  ");
    text = with_section(text, "allOf", want["allOf"], "  ");
    std::ofstream(kSchema) << text;
    return;
  }
  const char* regenerate =
      "results.schema.json does not describe the record the code writes; regenerate it with "
      "ARMSTUDY_WRITE_SCHEMA=1 build/tests/report_tests --gtest_filter=ResultsSchema.*";
  for (const auto& [key, value] : want["properties"].items())
    EXPECT_EQ(file["properties"][key], value) << key << ": " << regenerate;
  EXPECT_EQ(file["required"], want["required"]) << regenerate;
  EXPECT_EQ(file["allOf"], want["allOf"]) << regenerate;
  // nothing else at the top: the record's keys and one section per study
  EXPECT_EQ(file["additionalProperties"], json(false));
  for (const auto& [key, value] : file["properties"].items())
    EXPECT_TRUE(want["properties"].contains(key) || app::find_study(key)) << key;
  EXPECT_EQ(file["properties"]["schema_version"]["const"], kSchemaVersion);
}

// the reader takes exactly the version it writes, and says which it found
TEST(ResultsSchema, AnotherSchemaVersionIsAClearError) {
  ResultsRecord r;
  r.study = "pendulum";
  json j = write_record(r);
  EXPECT_EQ(j["schema_version"], kSchemaVersion);
  EXPECT_NO_THROW(read_record(j));
  for (const json& v :
       {json(kSchemaVersion - 1), json(kSchemaVersion + 1), json("2"), json(nullptr)}) {
    j["schema_version"] = v;
    try {
      read_record(j);
      FAIL() << v;
    } catch (const ResultsError& e) {
      EXPECT_EQ(e.path(), "/schema_version");
      EXPECT_NE(std::string(e.what()).find("schema_version " + v.dump() +
                                           " is not one this armstudy reads (" +
                                           std::to_string(kSchemaVersion) + ")"),
                std::string::npos)
          << e.what();
    }
  }
  j.erase("schema_version");
  EXPECT_THROW(read_record(j), ResultsError);
}

// the record round-trips, and a misspelt shared key is named (the study's key is the study's)
TEST(ResultsSchema, TheRecordRoundTripsAndAMisspeltKeyIsNamed) {
  ResultsRecord r;
  r.armstudy_version = "1.2.3";
  r.study = "throwing";
  r.case_info.name = "c";
  r.case_info.sweep = CaseRecord::Sweep{"s", {{"arm.links.0.mass_kg", "2"}}};
  r.checks = {{"a.b", "d", 1e-12, 1e-9, true}};
  r.key_figures = {{"e_J", 0.1, "J", "energy"}};
  r.animations.push_back({});
  r.animations[0].video.reset();
  r.exports = {{"m.csv", "motion_csv", "w", "idp", {}, 7, std::vector<std::string>{"t [s]"}}};
  json j = write_record(r);
  j["throwing"] = json::object({{"anything", 1}});
  EXPECT_EQ(write_record(read_record(j)), write_record(r));
  EXPECT_TRUE(j["animations"][0]["video"].is_null());
  j["key_figures"][0]["unti"] = "J";
  try {
    read_record(j);
    FAIL();
  } catch (const ResultsError& e) {
    EXPECT_EQ(e.path(), "/key_figures/0/unti");
    EXPECT_NE(std::string(e.what()).find("did you mean 'unit'?"), std::string::npos) << e.what();
  }
}

TEST(ResultsSchema, EveryStudySectionIsItsTypedResultsSchema) {
  std::string text = armstudy::testing::slurp(kSchema);
  const json file = json::parse(text);
  const bool write = std::getenv("ARMSTUDY_WRITE_SCHEMA") != nullptr;
  for (const app::StudyEntry& e : app::study_registry()) {
    const std::string study(e.study);
    const json want = e.results_schema();
    if (write) {
      text = with_section(text, study, want);
      continue;
    }
    ASSERT_TRUE(file["properties"].contains(study)) << study;
    EXPECT_EQ(file["properties"][study], want)
        << study << ": results.schema.json does not describe the section the code writes; "
        << "regenerate it with ARMSTUDY_WRITE_SCHEMA=1 build/tests/report_tests "
           "--gtest_filter=ResultsSchema.*";
  }
  if (write) std::ofstream(kSchema) << text;
}

// what the generated schema promises a reader of results.json
TEST(ResultsSchema, StudySectionsAdmitNoOtherKeyAndNameEveryUnit) {
  for (const app::StudyEntry& e : app::study_registry()) {
    int objects = 0, units = 0;
    std::function<void(const json&, const std::string&)> walk = [&](const json& s,
                                                                    const std::string& path) {
      if (!s.is_object()) return;
      if (s.value("type", json()) == "object") {
        ++objects;
        EXPECT_EQ(s.value("additionalProperties", json(true)), json(false)) << e.study << path;
        for (const auto& [k, v] : s["properties"].items()) {
          EXPECT_TRUE(v.contains("description")) << e.study << path << "/" << k;
          if (!unit_of_key(k).empty()) {
            ++units;
            EXPECT_NE(v.value("description", std::string()).find("unit: " + unit_of_key(k)),
                      std::string::npos)
                << e.study << path << "/" << k;
          }
          walk(v, path + "/" + k);
        }
      }
      if (s.contains("items")) walk(s["items"], path + "/items");
      if (s.contains("anyOf"))
        for (const auto& a : s["anyOf"]) walk(a, path);
    };
    walk(e.results_schema(), "");
    EXPECT_GT(objects, 3) << e.study;
    EXPECT_GT(units, 5) << e.study;
  }
}

TEST(ResultsSchema, UnitsComeFromTheKeySuffix) {
  EXPECT_EQ(unit_of_key("energy_J"), "J");
  EXPECT_EQ(unit_of_key("qd_rad_s"), "rad/s");
  EXPECT_EQ(unit_of_key("qdd1_rad_s2"), "rad/s^2");
  EXPECT_EQ(unit_of_key("inertia_kg_m2"), "kg m^2");
  EXPECT_EQ(unit_of_key("saving_percent"), "%");
  EXPECT_EQ(unit_of_key("samples"), "");
}

}  // namespace
}  // namespace armstudy::report
