// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// A case's sensitivity part is in its work budget (docs/budgets.md): each key re-solves the
// case twice, each re-solve about kSensitivityResolveFraction of the solve. A case within
// its study's budget alone was accepted with any number of keys and then re-solved them all.
#include <gtest/gtest.h>

#include <string>

#include "app/pipeline.hpp"
#include "app/run_order.hpp"
#include "cases/budget.hpp"
#include "cases/case_error.hpp"

namespace armstudy::app {
namespace {

// a placement case at about 0.73 of its work budget (7.3e9 of 1e10 trajectory samples)
const char* kNearBudget =
    "study: placement\nname: b\n"
    "placement: {length_fraction: 0.5, nx_s: 2000, phi_step_deg: 0.08, duration_s: 1.0}\n";

std::string budget_errors(const std::string& yaml, bool allow_large = false) {
  try {
    load_case_text(yaml, "c.yaml", LoadOptions{allow_large});
  } catch (const cases::CaseErrors& e) {
    std::string out;
    for (const auto& err : e.errors()) out += err.format() + "\n";
    return out;
  }
  return "";
}

TEST(SensitivityBudget, EachKeysReSolvesCountInTheCasesWorkBudget) {
  EXPECT_EQ(budget_errors(kNearBudget), "") << "within the budget alone";
  const std::string two_keys = std::string(kNearBudget) +
                               "sensitivity:\n  - placement.length_fraction\n"
                               "  - placement.duration_s\n";
  const std::string e = budget_errors(two_keys);
  EXPECT_NE(e.find("c.yaml:3:12: the placement sweep with its sensitivity part asks for about "),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("; x 1.6 for the 2 x 2 re-solves of its 2 sensitivity keys, each about 0.15 "
                   "of the solve), more than the budget of 1e+10 trajectory samples"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("and the length of 'sensitivity'; reduce them, list fewer keys, or pass "
                   "--allow-large"),
            std::string::npos)
      << e;
  EXPECT_EQ(budget_errors(two_keys, true), "") << "--allow-large accepts it";
}

TEST(SensitivityBudget, TheFactorIsOnePlusTwoResolvesAKeyAtTheMeasuredShare) {
  cases::Demand d;
  d.what = "the study";
  d.unit = "steps";
  d.keys = "study.steps";
  d.detail = "100 steps";
  d.work = 4e8;
  d.work_budget = 1e9;
  EXPECT_TRUE(cases::over_budget(d, 1, 64, 64).empty());
  const cases::Resolves nine{9, kSensitivityResolveFraction};
  EXPECT_DOUBLE_EQ(nine.factor(), 1 + 2 * 9 * 0.15);
  EXPECT_TRUE(cases::over_budget(d, 1, 64, 64, {4, kSensitivityResolveFraction}).empty())
      << "4e8 x 2.2 is within 1e9";
  ASSERT_EQ(cases::over_budget(d, 1, 64, 64, nine).size(), 1u) << "4e8 x 3.7 is not";
}

}  // namespace
}  // namespace armstudy::app
