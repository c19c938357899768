// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The throwing study's checks in the pipeline (cli/throwing_pipeline.cpp): a run cut short by
// its budget is flagged "not converged" and fails the case unless the case allows it; the
// results carry the seed spread, the comparison table and the contact forces over time.
#include <gtest/gtest.h>

#include <string>

#include "app/pipeline.hpp"

namespace armstudy::app {
namespace {

// a small throw (8 stages) whose IDP is cut after one pass with a tolerance it cannot meet
std::string small_case(bool allow) {
  return std::string(
             "study: throwing\n"
             "name: t\n"
             "throwing:\n"
             "  motors: {power_max_W: 200, current_max_A: 10}\n"
             "  idp: {stages: 8, steps_per_stage: 8, iterations: 2, max_passes: 1, candidates: 3,\n"
             "        tolerance: 1.0e-9, seeds: 2}\n"
             "  nlopt: {enabled: false}\n"
             "  checks: {allow_not_converged: ") +
         (allow ? "true" : "false") + "}\n";
}

const studies::Check* find(const std::vector<studies::Check>& cs, const std::string& name) {
  for (const auto& c : cs)
    if (c.name == name) return &c;
  return nullptr;
}

TEST(ThrowingPipeline, BudgetCutIdpFailsTheCaseUnlessTheCaseAllowsIt) {
  for (bool allow : {false, true}) {
    LoadedCase lc = load_case_text(small_case(allow), "t.yaml");
    ASSERT_EQ(lc.run->solve({}), studies::Status::kSolved) << lc.run->message();
    EXPECT_NE(lc.run->message().find("NOT converged"), std::string::npos) << lc.run->message();
    const auto checks = lc.run->checks();
    const studies::Check* c = find(checks, "idp_converged");
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->value, 1.0);
    EXPECT_EQ(c->passed, allow) << "allow_not_converged: " << allow;
    EXPECT_EQ(find(checks, "slsqp_converged"), nullptr);  // SLSQP is off in this case
    // every constraint of the reported optimum is checked at 4x the steps
    for (const char* n : {"idp_contact", "idp_friction", "idp_ball_in_tray", "idp_voltage",
                          "idp_current", "idp_power", "idp_release_theta3"})
      EXPECT_NE(find(checks, n), nullptr) << n;
    const nlohmann::json j = lc.run->results();
    EXPECT_EQ(j["idp"]["converged"], false);
    EXPECT_EQ(j["idp"]["seed_runs"].size(), 2u);
    EXPECT_TRUE(j["idp"]["spread"]["best_J"].is_number());
    EXPECT_LE(j["idp"]["spread"]["best_J"].get<double>(),
              j["idp"]["spread"]["worst_J"].get<double>());
    EXPECT_EQ(j["comparison"].size(), 1u);
    EXPECT_TRUE(j["comparison"][0]["margins"].contains("contact_N"));
    const auto& series = j["optimum"]["series"];
    EXPECT_EQ(series["normal_force_N"].size(), series["t_s"].size());
    EXPECT_EQ(series["friction_needed"].size(), series["t_s"].size());
    EXPECT_GE(j["assumptions"].size(), 5u);
  }
}

}  // namespace
}  // namespace armstudy::app
