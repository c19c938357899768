// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The source beside armstudy (report/source_comparison.hpp): value paths into results.json,
// the precision a printed number carries, and the verdicts.
#include "report/source_comparison.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

namespace armstudy::report::source_comparison_test {

using nlohmann::json;

const json kResults = json::parse(R"({
  "key_figures": [{"name": "energy_J[cycloidal,1]", "value": 4.0}, {"name": "bad", "value": null}],
  "placement": {"evaluations": [
    {"label": "a", "program": "cycloidal", "configuration": 1, "energy_J": 5.25, "xy": [0.1, -0.2]},
    {"label": "a", "program": "cycloidal", "configuration": 2, "energy_J": 5.15, "xy": [0.3, 0.4]},
    {"label": "b", "program": "poly345", "configuration": 1, "energy_J": null}],
   "optima": [
    {"program": "cycloidal", "energy_J": 16.27, "root_xy_m": [0.45201, 0.37620],
     "refinement": {"root_error_m": 1e-9, "energy_error_J": 5e-9}},
    {"program": "poly345", "energy_J": 14.45, "root_xy_m": [0.45168, 0.37360],
     "refinement": {"root_error_m": 2e-9, "energy_error_J": 4.2e-9}},
    {"program": "grid", "energy_J": 16.269, "root_xy_m": [0.45201, 0.37620],
     "refinement": {"root_error_m": null, "energy_error_J": 0.01}}]}
})");

TEST(SourceComparison, ValuePathsSelectOneElementOrNothing) {
  EXPECT_EQ(value_at(kResults, "key:energy_J[cycloidal,1]"), 4.0);
  EXPECT_EQ(value_at(kResults, "placement.evaluations[label=a,configuration=2].energy_J"), 5.15);
  EXPECT_EQ(value_at(kResults, "placement.evaluations[label=a,configuration=1].xy[1]"), -0.2);
  EXPECT_EQ(value_at(kResults, "placement.evaluations[2].configuration"), 1.0);
  // two elements match: the path names no one value
  EXPECT_FALSE(value_at(kResults, "placement.evaluations[label=a].energy_J"));
  // none matches, out of range, a null, a missing key, a key figure that is not finite
  EXPECT_FALSE(value_at(kResults, "placement.evaluations[label=c].energy_J"));
  EXPECT_FALSE(value_at(kResults, "placement.evaluations[7].energy_J"));
  EXPECT_FALSE(value_at(kResults, "placement.evaluations[label=b].energy_J"));
  EXPECT_FALSE(value_at(kResults, "placement.nothing"));
  EXPECT_FALSE(value_at(kResults, "key:bad"));
  EXPECT_FALSE(value_at(kResults, "key:missing"));
}

TEST(SourceComparison, APrintedNumberCarriesHalfAUnitOfItsLastDigit) {
  EXPECT_DOUBLE_EQ(cases::printed_precision("9.58"), 0.005);
  EXPECT_DOUBLE_EQ(cases::printed_precision("0.2000"), 0.00005);
  EXPECT_DOUBLE_EQ(cases::printed_precision("17"), 0.5);
  EXPECT_DOUBLE_EQ(cases::printed_precision("-0.4324"), 0.00005);
  EXPECT_DOUBLE_EQ(cases::printed_precision("1.2e-3"), 0.00005);
}

TEST(SourceComparison, VerdictsFollowThePrintedDigitsAndTheClaimedRelation) {
  cases::SourceSpec spec;
  spec.document = "A (2000)";
  cases::PrintedItem agrees;
  agrees.value = 5.2;
  agrees.tolerance = 0.05;
  agrees.at_source_setting = "placement.evaluations[label=a,configuration=1].energy_J";
  cases::PrintedItem differs = agrees;
  differs.value = 5.3;  // 5.25 is 0.05 below: at the edge of 5.3's digit, still agrees
  cases::PrintedItem far = agrees;
  far.value = 9.58;
  far.tolerance = 0.005;
  cases::PrintedItem tie;
  tie.claim = cases::SourceClaim{"key:energy_J[cycloidal,1]", "less", "4", 1e-6, ""};
  cases::PrintedItem holds;
  holds.claim = cases::SourceClaim{"key:energy_J[cycloidal,1]", "less", "4.5", 1e-6, ""};
  cases::PrintedItem missing = agrees;
  missing.at_source_setting = "placement.evaluations[label=b].energy_J";
  // a value the study constrains to within the tolerance is met by it, not an agreement
  cases::PrintedItem constrained = agrees;
  constrained.by_constraint = true;
  cases::PrintedItem constrained_far = far;
  constrained_far.by_constraint = true;
  spec.printed = {agrees, differs, far, tie, holds, missing, constrained, constrained_far};
  const SourceRecord r = compare_with_source(spec, kResults);
  ASSERT_EQ(r.rows.size(), 8u);
  EXPECT_EQ(r.rows[6].verdict, "met_by_constraint");
  EXPECT_EQ(r.rows[7].verdict, "differs");
  EXPECT_NE(source_summary(r).find("1 met by a constraint, 3 differ"), std::string::npos)
      << source_summary(r);
  EXPECT_EQ(r.rows[0].verdict, "agrees");
  EXPECT_EQ(r.rows[1].verdict, "agrees");
  EXPECT_EQ(r.rows[2].verdict, "differs");
  EXPECT_NEAR(*r.rows[2].difference, 5.25 - 9.58, 1e-12);
  EXPECT_EQ(r.rows[3].verdict, "contradicted");  // a tie is no relation
  EXPECT_EQ(r.rows[4].verdict, "confirmed");
  EXPECT_EQ(r.rows[5].verdict, "no_value");
  // a difference, a contradiction and a missing value without their reason fail the check
  const CheckRecord c = source_explained_check(r);
  EXPECT_FALSE(c.passed);
  EXPECT_EQ(c.value, 4);
}

// a claim between two optima of kResults: `a_at` and `b_at` are their programs
cases::PrintedItem claim_between(const std::string& a_at, const std::string& relation,
                                 const std::string& b_at, const std::string& key,
                                 const std::string& error_key) {
  cases::PrintedItem it;
  cases::SourceClaim c;
  c.a = "placement.optima[program=" + a_at + "]." + key;
  c.relation = relation;
  c.b = "placement.optima[program=" + b_at + "]." + key;
  if (!error_key.empty()) {
    c.a_error = "placement.optima[program=" + a_at + "].refinement." + error_key;
    c.b_error = "placement.optima[program=" + b_at + "].refinement." + error_key;
  }
  it.claim = c;
  it.unit = key == "energy_J" ? "J" : "m";
  return it;
}

TEST(SourceComparison, ClaimsAreJudgedAgainstTheErrorsOfTheirValuesAndPointsByDistance) {
  cases::SourceSpec spec;
  spec.document = "A (2000)";
  spec.printed = {
      // two roots 2.6 mm apart against errors of 3e-9 m: not the same point
      claim_between("poly345", "same", "cycloidal", "root_xy_m", "root_error_m"),
      // the same point (distance 0): the same, with or without errors
      claim_between("grid", "same", "cycloidal", "root_xy_m", ""),
      // 14.45 J against 16.27 J, errors of 9e-9 J: less
      claim_between("poly345", "less", "cycloidal", "energy_J", "energy_error_J"),
      // 16.269 J against 16.27 J with 0.01 J of error: within it, a tie
      claim_between("grid", "less", "cycloidal", "energy_J", "energy_error_J"),
      // without the errors the same gap decides
      claim_between("grid", "less", "cycloidal", "energy_J", ""),
      // greater, beyond the errors: contradicted
      claim_between("poly345", "greater", "cycloidal", "energy_J", "energy_error_J"),
      // an error that is null: no value
      claim_between("grid", "same", "cycloidal", "root_xy_m", "root_error_m"),
      // points have no order
      claim_between("poly345", "less", "cycloidal", "root_xy_m", ""),
  };
  const SourceRecord r = compare_with_source(spec, kResults);
  ASSERT_EQ(r.rows.size(), 8u);
  EXPECT_EQ(r.rows[0].verdict, "contradicted");
  ASSERT_TRUE(r.rows[0].distance);
  EXPECT_NEAR(*r.rows[0].distance, std::hypot(0.00033, 0.0026), 1e-12);
  EXPECT_DOUBLE_EQ(*r.rows[0].a_error + *r.rows[0].b_error, 3e-9);
  ASSERT_TRUE(r.rows[0].a_point);
  EXPECT_EQ(*r.rows[0].a_point, (std::vector<double>{0.45168, 0.37360}));
  EXPECT_FALSE(r.rows[0].a);
  EXPECT_EQ(r.rows[1].verdict, "confirmed");
  EXPECT_EQ(*r.rows[1].distance, 0.0);
  EXPECT_EQ(r.rows[2].verdict, "confirmed");
  EXPECT_EQ(r.rows[3].verdict, "tie");
  EXPECT_EQ(r.rows[4].verdict, "confirmed");
  EXPECT_EQ(r.rows[5].verdict, "contradicted");
  EXPECT_EQ(r.rows[6].verdict, "no_value");
  EXPECT_EQ(r.rows[7].verdict, "no_value");
  // the table shows the points, the distance and the errors beside each other
  std::string page;
  for (const Block& b : source_section(r).blocks)
    for (const auto& row : b.table.rows)
      for (const std::string& cell : row) page += cell + " | ";
  EXPECT_NE(page.find("a = (0.45168, 0.3736) m ± 2e-09, b = (0.45201, 0.3762) m ± 1e-09"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("distance 0.00262086 m; their errors together 3e-09 m"), std::string::npos)
      << page;
  EXPECT_NE(page.find("a - b = -1.82 (-11.2 %); their errors together 9.2e-09 J"),
            std::string::npos)
      << page;
}

}  // namespace armstudy::report::source_comparison_test
