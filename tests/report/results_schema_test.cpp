// results.schema.json describes every study's section completely: its study sections are the
// JSON Schemas of the typed results (src/studies/<study>/results_section.hpp), so the file,
// the writer and the reader cannot drift apart.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/pipeline.hpp"
#include "report/results_fields.hpp"
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
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
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

// `text` with the value of properties/<study> replaced by `value`, the rest untouched
std::string with_section(std::string text, const std::string& study, const json& value) {
  const std::string key = "\n    \"" + study + "\": ";
  const size_t at = text.find(key);
  if (at == std::string::npos) throw std::runtime_error("results.schema.json has no properties/" + study);
  const size_t start = at + key.size(), end = value_end(text, start);
  std::string dumped = value.dump(2), indented;
  for (char c : dumped) indented += c == '\n' ? std::string("\n    ") : std::string(1, c);
  return text.replace(start, end - start, indented);
}

TEST(ResultsSchema, EveryStudySectionIsItsTypedResultsSchema) {
  std::string text = armstudy::testing::slurp(kSchema);
  const json file = json::parse(text);
  const bool write = std::getenv("ARMSTUDY_WRITE_SCHEMA") != nullptr;
  for (const app::StudyEntry& e : app::study_registry()) {
    const std::string study(e.study);
    const json want = e.section_schema();
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
    std::function<void(const json&, const std::string&)> walk = [&](const json& s, const std::string& path) {
      if (!s.is_object()) return;
      if (s.value("type", json()) == "object") {
        ++objects;
        EXPECT_EQ(s.value("additionalProperties", json(true)), json(false)) << e.study << path;
        for (const auto& [k, v] : s["properties"].items()) {
          EXPECT_TRUE(v.contains("description")) << e.study << path << "/" << k;
          if (!unit_of_key(k).empty()) {
            ++units;
            EXPECT_NE(v.value("description", std::string()).find("unit: " + unit_of_key(k)), std::string::npos)
                << e.study << path << "/" << k;
          }
          walk(v, path + "/" + k);
        }
      }
      if (s.contains("items")) walk(s["items"], path + "/items");
      if (s.contains("anyOf"))
        for (const auto& a : s["anyOf"]) walk(a, path);
    };
    walk(e.section_schema(), "");
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
