// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// summary.md, junit.xml and sweep tables built from results.json data.
#include "cli/merge.hpp"

#include "report/text_escape.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace armstudy::cli {
namespace {
using nlohmann::json;

CaseOutput make_case(const std::string& name, const std::string& study, bool solved,
                     std::vector<std::pair<std::string, bool>> checks, double energy,
                     const std::string& ratio = "") {
  report::ResultsRecord r;
  r.study = study;
  r.case_info.name = name;
  r.case_info.path = name + ".yaml";
  r.case_info.sha256 = std::string(64, 'a');
  if (!ratio.empty())
    r.case_info.sweep = report::CaseRecord::Sweep{"s", {{"arm.links[2].length", ratio}}};
  r.status = solved ? "solved" : "unsolvable";
  r.message = solved ? "ok" : "target is 0.12 m outside the annulus";
  for (const auto& [n, p] : checks) r.checks.push_back({n, "d <x>", p ? 0.0 : 2.0, 1.0, p});
  r.key_figures = {{"min_energy_J", energy, "J", "least energy"}};
  return {name, report::write_record(r), r};
}

TEST(Merge, SummaryListsFailuresFirstWithReasons) {
  std::vector<CaseOutput> cases = {make_case("a", "placement", true, {{"work", true}}, 1.5),
                                   make_case("b", "placement", false, {}, 0),
                                   make_case("c", "time_optimal", true, {{"limits", false}}, 0.7)};
  const std::string md = summary_markdown(cases);
  EXPECT_EQ(md.rfind("# armstudy: 3 case(s), 2 failed", 0), 0u) << md;
  const size_t failures = md.find("## Failures"), placement = md.find("## placement");
  ASSERT_NE(failures, std::string::npos);
  ASSERT_NE(placement, std::string::npos);
  EXPECT_LT(failures, placement);
  EXPECT_NE(md.find("could not be solved: target is 0.12 m outside the annulus"),
            std::string::npos);
  EXPECT_NE(md.find("failed checks: limits (2 > 1)"), std::string::npos);
  EXPECT_NE(md.find("min_energy_J (J)"), std::string::npos);
}

TEST(Merge, SummaryIsTruncatedWithANoteUnderTheLimit) {
  std::vector<CaseOutput> cases;
  for (int i = 0; i < 3000; ++i)
    cases.push_back(make_case("case-" + std::to_string(i), "placement", i % 2, {}, i));
  const std::string md = summary_markdown(cases, 64 * 1024);
  EXPECT_LE(md.size(), 64u * 1024);
  EXPECT_NE(md.find("Truncated"), std::string::npos);
}

TEST(Merge, JunitCountsOneTestcasePerCaseAndCheck) {
  std::vector<CaseOutput> cases = {
      make_case("a", "placement", true, {{"w", true}, {"x", false}}, 1),
      make_case("b", "placement", false, {}, 0)};
  const std::string x = junit_xml(cases);
  EXPECT_NE(x.find("<testsuites name=\"armstudy\" tests=\"4\" failures=\"2\""), std::string::npos)
      << x;
  EXPECT_NE(x.find("d &lt;x&gt;"), std::string::npos) << "descriptions are escaped";
}

TEST(Merge, SweepTablesDoNotDependOnCaseOrder) {
  std::vector<CaseOutput> cases;
  for (int i = 0; i < 20; ++i)
    cases.push_back(make_case("p-" + std::to_string(100 + i), "placement", true, {}, 1.0 / (i + 1),
                              std::to_string(0.1 + 0.01 * i)));
  const std::string csv = sweep_csv(cases);
  const std::string js = sweep_json(cases).dump();
  std::mt19937 rng(3);
  std::shuffle(cases.begin(), cases.end(), rng);
  std::sort(cases.begin(), cases.end(),
            [](auto& a, auto& b) { return a.record.case_info.name < b.record.case_info.name; });
  EXPECT_EQ(sweep_csv(cases), csv);
  EXPECT_EQ(sweep_json(cases).dump(), js);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "case,status,arm.links[2].length,min_energy_J (J)");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 21);
}

// sweep.json is the typed sweep table's JSON (report/sweep_table.hpp): it reads back strictly
// into the table, which writes the same text; a case with no number for a figure, or without
// a parameter, has null there
TEST(Merge, SweepJsonReadsBackIntoTheTypedTable) {
  std::vector<CaseOutput> cases = {make_case("p-1", "placement", true, {}, 2.5, "0.2"),
                                   make_case("p-2", "placement", false, {}, NAN, "0.3"),
                                   make_case("q", "placement", true, {}, 1.0)};
  cases[1].record.case_info.sweep->point.clear();
  const json j = sweep_json(cases);
  const report::SweepTable t = report::from_json<report::SweepTable>(j);
  ASSERT_EQ(t.rows.size(), 2u) << "the case without a sweep point is no row";
  EXPECT_EQ(t.rows[0].case_name, "p-1");
  EXPECT_EQ(t.rows[0].parameters.at("arm.links[2].length"), "0.2");
  EXPECT_EQ(t.rows[0].key_figures.at("min_energy_J"), 2.5);
  EXPECT_EQ(t.rows[1].status, "failed");
  EXPECT_EQ(t.rows[1].parameters.at("arm.links[2].length"), std::nullopt);
  EXPECT_EQ(t.rows[1].key_figures.at("min_energy_J"), std::nullopt);
  EXPECT_EQ(j["rows"][1]["key_figures"]["min_energy_J"], nullptr);
  EXPECT_EQ(t.units.at("min_energy_J"), "J");
  EXPECT_EQ(report::to_json(t).dump(2), j.dump(2));
  EXPECT_TRUE(report::has_sweep_table_keys(j));
  json more = j;
  more["note"] = "x";
  EXPECT_FALSE(report::has_sweep_table_keys(more));
  EXPECT_FALSE(report::has_sweep_table_keys(json::array()));
}

}  // namespace
}  // namespace armstudy::cli

namespace armstudy::cli {
namespace {

// every character of s is one XML 1.0 allows (a newline, or printable and valid UTF-8)
bool xml_safe(const std::string& s) {
  bool ok = true;
  report::for_each_utf8(s, [&](long cp, const std::string&) {
    ok = ok && (cp == '\n' || (cp >= 0x20 && cp != 0x7f && !(cp >= 0x80 && cp <= 0x9f) &&
                               cp != 0xfffe && cp != 0xffff));
  });
  return ok;
}

TEST(Merge, JunitAndSummaryCarryNoRawControlOrForeignBytesFromNamesAndMessages) {
  const std::string hostile = std::string("a\x1b[31m\nb\r\x01\x7f\xc2\x9b", 13) +
                              std::string("\0", 1) + " <&>\"' \xff\xef\xbf\xbe|end";
  std::vector<CaseOutput> cases = {make_case("a", "placement", false, {{hostile, false}}, 1)};
  cases[0].record.message = hostile;
  cases[0].record.key_figures[0].unit = hostile;
  cases.push_back(failed_output("f", hostile, hostile, "error", hostile));
  const std::string x = junit_xml(cases);
  EXPECT_TRUE(xml_safe(x)) << x;
  EXPECT_NE(x.find("a\\x1B[31m&#10;b\\x0D\\x01\\x7F\\xC2\\x9B\\x00 "
                   "&lt;&amp;&gt;&quot;&apos; \\xFF\\xEF\\xBF\\xBE|end"),
            std::string::npos)
      << x;
  const std::string md = summary_markdown(cases);
  bool raw = false;  // a control character or a byte that is not UTF-8
  report::for_each_utf8(md, [&](long cp, const std::string&) {
    raw = raw || cp < 0 || (cp < 0x20 && cp != '\n') || (cp >= 0x7f && cp <= 0x9f);
  });
  EXPECT_FALSE(raw) << md;
  EXPECT_NE(md.find("a\\x1B[31m b \\x01\\x7F\\xC2\\x9B\\x00 &lt;&>\"' \\xFF"), std::string::npos)
      << md;
  EXPECT_NE(md.find("\\|end"), std::string::npos) << md;
}

}  // namespace
}  // namespace armstudy::cli
