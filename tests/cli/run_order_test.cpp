// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The order a run works through its cases: the longest estimated solve first, each case
// exactly once, equal estimates in the order given.

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "app/run_order.hpp"

namespace {

using armstudy::app::LoadedCase;

std::vector<LoadedCase> bundled_cases() {
  std::vector<std::string> paths;
  for (const auto& e :
       std::filesystem::directory_iterator(std::string(ARMSTUDY_SOURCE_DIR) + "/reports/cases"))
    if (e.path().extension() == ".yaml") paths.push_back(e.path().string());
  std::sort(paths.begin(), paths.end());
  std::vector<LoadedCase> cases;
  for (const auto& p : paths) cases.push_back(armstudy::app::load_case(p));
  return cases;
}

std::vector<std::string> names_in_order(const std::vector<LoadedCase>& cases, bool render) {
  std::vector<std::string> names;
  for (const size_t i : armstudy::app::longest_first(cases, render))
    names.push_back(cases[i].info.name);
  return names;
}

TEST(RunOrder, EveryCaseRunsOnceLongestEstimateFirst) {
  const auto cases = bundled_cases();
  ASSERT_GE(cases.size(), 10u);
  const auto order = armstudy::app::longest_first(cases, true);
  std::vector<size_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (size_t i = 0; i < sorted.size(); ++i) EXPECT_EQ(sorted[i], i);
  for (size_t k = 1; k < order.size(); ++k)
    EXPECT_GE(armstudy::app::estimated_seconds(cases[order[k - 1]], true),
              armstudy::app::estimated_seconds(cases[order[k]], true))
        << cases[order[k - 1]].info.name << " before " << cases[order[k]].info.name;
  for (const auto& c : cases)
    EXPECT_GT(armstudy::app::estimated_seconds(c, true), 0) << c.info.name;
}

TEST(RunOrder, TheThrowingOptimisationStartsFirstAndEqualCasesKeepTheirOrder) {
  const auto cases = bundled_cases();
  for (const bool render : {false, true}) {
    const auto names = names_in_order(cases, render);
    const auto at = [&](const std::string& n) {
      return std::find(names.begin(), names.end(), n) - names.begin();
    };
    // the IDP and multi-start SLSQP throws on their control grids are the longest cases of
    // the bundled set (the bundled throw first: its sensitivity list is the longer)
    EXPECT_EQ(names[0], "throwing");
    EXPECT_EQ(names[1], "throwing-motor-on-base");
    // the placement examples ask for the same sweep and frames: they keep their name order
    EXPECT_LT(at("placement-example-2"), at("placement-example-3"));
    EXPECT_LT(at("placement-example-3"), at("placement-example-4"));
    EXPECT_LT(at("placement-example-4"), at("placement-example-5"));
    if (render) {
      // four optima's animations and strips: before the one-motion time-optimal cases
      EXPECT_LT(at("placement-example-5"), at("time-optimal-source"));
    } else {
      // the pendulum's solve is the shortest
      EXPECT_EQ(names.back(), "pendulum");
    }
  }
}

// IDP's iterations and SLSQP's budget both count (SLSQP's budget of every start dominates)
TEST(RunOrder, MoreIdpIterationsOrSlsqpEvaluationsEstimateALongerSolve) {
  const std::string path = std::string(ARMSTUDY_SOURCE_DIR) + "/reports/cases/throwing.yaml";
  const LoadedCase base = armstudy::app::load_case(path);
  std::string text = base.info.yaml;
  const std::string key = "iterations:";
  const auto p = text.find(key);
  ASSERT_NE(p, std::string::npos);
  const auto end = text.find('\n', p);
  const int iterations = std::stoi(text.substr(p + key.size(), end - p - key.size()));
  text.replace(p, end - p, key + " " + std::to_string(2 * iterations));
  const LoadedCase more = armstudy::app::load_case_text(text, path);
  // (IDP is a small part of the bundled throw's work since SLSQP refines on 32 and 64
  // stages: doubling its iterations adds about 4 %)
  EXPECT_GT(armstudy::app::estimated_seconds(more, false),
            1.02 * armstudy::app::estimated_seconds(base, false));
  const std::string budget = "max_evaluations: 1500";
  const auto b = text.find(budget);
  ASSERT_NE(b, std::string::npos);
  text.replace(b, budget.size(), "max_evaluations: 3000");
  // (twice SLSQP's budget on every grid is beyond the default work budget)
  armstudy::app::LoadOptions large;
  large.allow_large = true;
  const LoadedCase more_slsqp = armstudy::app::load_case_text(text, path, large);
  EXPECT_GT(armstudy::app::estimated_seconds(more_slsqp, false),
            1.5 * armstudy::app::estimated_seconds(more, false));
}

}  // namespace

namespace {

// two cases of 3 GiB each never run at once under a 4 GiB budget; small ones do
TEST(RunOrder, TheMemoryBudgetCoversAllJobs) {
  armstudy::app::MemoryGate gate(4.0 * (1ull << 30));
  const double big = 3.0 * (1ull << 30), small = 0.5 * (1ull << 30);
  std::atomic<int> running{0}, most{0};
  auto job = [&](double bytes) {
    gate.acquire(bytes);
    const int now = ++running;
    int m = most.load();
    while (now > m && !most.compare_exchange_weak(m, now)) {
    }
    EXPECT_LE(gate.in_use(), 4.0 * (1ull << 30));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    --running;
    gate.release(bytes);
  };
  std::vector<std::thread> pool;
  for (int k = 0; k < 4; ++k) pool.emplace_back(job, big);
  for (auto& t : pool) t.join();
  EXPECT_EQ(most.load(), 1) << "3 GiB cases ran side by side";
  pool.clear();
  most = 0;
  for (int k = 0; k < 4; ++k) pool.emplace_back(job, small);
  for (auto& t : pool) t.join();
  EXPECT_GE(most.load(), 1);
  EXPECT_EQ(gate.in_use(), 0.0);
  // a case beyond the budget alone (--allow-large) still runs, alone
  gate.acquire(8.0 * (1ull << 30));
  gate.release(8.0 * (1ull << 30));
}

// the sensitivity part's re-solves are in the estimate: the bundled throwing case lists its keys,
// 2 re-solves each at kSensitivityResolveFraction of the work they repeat (the run's
// --no-sensitivity leaves them out). A re-solve starts from the nominal answer, so it repeats
// the local work only: the global phase (the smooth starts) is not counted in it
TEST(RunOrder, TheEstimateCoversTheSensitivityResolves) {
  const std::string path = std::string(ARMSTUDY_SOURCE_DIR) + "/reports/cases/throwing.yaml";
  const LoadedCase c = armstudy::app::load_case(path);
  const size_t keys = c.info.sensitivity.items.size();
  ASSERT_GT(keys, 0u);
  const double without = armstudy::app::estimated_seconds(c, false, false);
  const double with = armstudy::app::estimated_seconds(c, false, true);
  ASSERT_GT(without, 0);
  double solve = 0, repeated = 0;
  for (const armstudy::cases::Demand& d : c.demands) {
    if (d.work_per_second <= 0) continue;
    solve += d.work / d.work_per_second;
    repeated += (d.resolve_base > 0 ? d.resolve_base : d.work) / d.work_per_second;
  }
  EXPECT_DOUBLE_EQ(without, solve);
  EXPECT_GT(repeated, 0);
  EXPECT_LT(repeated, solve) << "the re-solves repeat the global phase";
  EXPECT_NEAR(with - without,
              2.0 * double(keys) * armstudy::app::kSensitivityResolveFraction * repeated,
              1e-12 * with);
}

}  // namespace
