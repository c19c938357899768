// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// A case's sensitivity part has a work budget (docs/budgets.md): each key re-solves the case
// twice, each re-solve about kSensitivityResolveFraction of the solve, and the re-solves
// together may ask for at most the study's budget, besides the solve's. A case within its
// study's budget alone was accepted with any number of keys and then re-solved them all.
#include <gtest/gtest.h>

#include <string>

#include "app/pipeline.hpp"
#include "app/run_order.hpp"
#include "cases/budget.hpp"
#include "cases/case_error.hpp"

namespace armstudy::app {
namespace {

// a placement case at about 0.89 of its work budget (8.9e9 of 1e10 trajectory samples)
const char* kNearBudget =
    "study: placement\nname: b\n"
    "placement: {length_fraction: 0.5, nx_s: 2000, phi_step_deg: 0.065, duration_s: 1.0}\n";

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

// the part has a budget of its own, the study's: 2 keys (x 0.6 of the solve) fit beside
// the solve, 4 (x 1.2) do not
TEST(SensitivityBudget, TheReSolvesOfEachKeyCountInABudgetOfTheirOwn) {
  EXPECT_EQ(budget_errors(kNearBudget), "") << "within the budget alone";
  const std::string two_keys = std::string(kNearBudget) +
                               "sensitivity:\n  - placement.length_fraction\n"
                               "  - placement.duration_s\n";
  EXPECT_EQ(budget_errors(two_keys), "");
  const std::string four_keys = two_keys + "  - placement.nx_s\n  - placement.phi_step_deg\n";
  const std::string e = budget_errors(four_keys);
  EXPECT_NE(e.find("c.yaml:3:12: the sensitivity part of the placement sweep asks for about "
                   "1.1e+10 trajectory samples (the 2 x 4 re-solves of its 4 sensitivity keys, "
                   "each about 0.15 of the solve's 8.9e+09: x 1.2), more than the budget of "
                   "1e+10 trajectory samples it has besides the solve's, set by the length of "
                   "'sensitivity' and placement.nx_s"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("; list fewer keys, reduce them, or pass --allow-large"), std::string::npos)
      << e;
  EXPECT_EQ(budget_errors(four_keys, true), "") << "--allow-large accepts it";
}

TEST(SensitivityBudget, TheShareIsTwoResolvesAKeyAtTheMeasuredFraction) {
  cases::Demand d;
  d.what = "the study";
  d.unit = "steps";
  d.keys = "study.steps";
  d.detail = "100 steps";
  d.work = 4e8;
  d.work_budget = 1e9;
  EXPECT_TRUE(cases::over_budget(d, 1, 64, 64).empty());
  const cases::Resolves nine{9, kSensitivityResolveFraction};
  EXPECT_DOUBLE_EQ(nine.share(), 2 * 9 * 0.15);
  EXPECT_TRUE(cases::over_budget(d, 1, 64, 64, {8, kSensitivityResolveFraction}).empty())
      << "4e8 x 2.4 is within 1e9";
  ASSERT_EQ(cases::over_budget(d, 1, 64, 64, nine).size(), 1u) << "4e8 x 2.7 is not";
  d.work = 2e9;
  const auto both = cases::over_budget(d, 1, 64, 64, nine);
  ASSERT_EQ(both.size(), 1u) << "a solve beyond the budget is said once, as before";
  EXPECT_EQ(both[0].message.find("sensitivity"), std::string::npos) << both[0].message;
}

}  // namespace
}  // namespace armstudy::app
