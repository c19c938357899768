// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The source beside armstudy (report/source_comparison.hpp): value paths into results.json,
// the precision a printed number carries, and the verdicts.
#include "report/source_comparison.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace armstudy::report::source_comparison_test {

using nlohmann::json;

const json kResults = json::parse(R"({
  "key_figures": [{"name": "energy_J[cycloidal,1]", "value": 4.0}, {"name": "bad", "value": null}],
  "placement": {"evaluations": [
    {"label": "a", "program": "cycloidal", "configuration": 1, "energy_J": 5.25, "xy": [0.1, -0.2]},
    {"label": "a", "program": "cycloidal", "configuration": 2, "energy_J": 5.15, "xy": [0.3, 0.4]},
    {"label": "b", "program": "poly345", "configuration": 1, "energy_J": null}]}
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

}  // namespace armstudy::report::source_comparison_test
