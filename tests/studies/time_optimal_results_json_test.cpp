// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The time-optimal pipeline records its grid-convergence check and MuJoCo's dynamic replay
// in results.json and its checks: a near-singular line is solved on a graded grid and says
// so (on its uniform grid it fails exact_grid_converged and says so in its message); a
// regular one passes; both replay within their tolerance.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "app/pipeline.hpp"

namespace armstudy::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct CaseRun {
  studies::Status status;
  std::string message;
  json results;
  std::vector<studies::Check> checks;
};

CaseRun run_case_text(const std::string& end_point, const std::string& exact_more = "") {
  const fs::path dir =
      fs::temp_directory_path() / ("armstudy_to_json_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "case.yaml";
  std::ofstream(file) << "study: time_optimal\nname: json-test\ntime_optimal:\n"
                         "  path: {kind: line, points_m: [[0.3, 0.1], " +
                             end_point +
                             "]}\n"
                             "  dp: {states: [path_speed], convergence_segments: []}\n"
                             "  complex: {enabled: false}\n"
                             "  exact: {grid_points: 600" +
                             exact_more + "}\n";
  LoadedCase c = load_case(file.string());
  CaseRun r;
  r.status = c.run->solve({});
  r.message = c.run->message();
  r.results = c.run->results();
  r.checks = c.run->checks();
  fs::remove_all(dir);
  return r;
}

const studies::Check& check(const CaseRun& r, const std::string& name) {
  for (const auto& c : r.checks)
    if (c.name == name) return c;
  throw std::runtime_error("no check " + name);
}

void expect_replay_recorded(const json& rep) {
  for (const char* k :
       {"integrator", "timestep_s", "steps", "max_deviation_rad", "tolerance_rad", "tolerance_rule",
        "coarse_max_deviation_rad", "simulates", "does_not_simulate"})
    EXPECT_TRUE(rep.contains(k)) << k;
  EXPECT_EQ(rep["integrator"], "RK4");
  EXPECT_TRUE(rep["passed"].get<bool>());
  EXPECT_LE(rep["max_deviation_rad"].get<double>(), rep["tolerance_rad"].get<double>());
  const json& s = rep["series"];
  ASSERT_EQ(s["deviation_rad"].size(), 2u);
  EXPECT_EQ(s["deviation_rad"][0].size(), s["t_s"].size());
  EXPECT_EQ(s["q_sim_rad"][1].size(), s["t_s"].size());
}

TEST(TimeOptimalResultsJson, RegularLineRecordsAConvergedGridAndAFaithfulReplay) {
  const CaseRun r = run_case_text("[-0.1, 0.8]");
  ASSERT_EQ(r.status, studies::Status::kSolved) << r.message;
  const json& g = r.results["grid_convergence"];
  EXPECT_TRUE(g["passed"].get<bool>()) << g["text"];
  EXPECT_EQ(g["refined_points"].get<int>(), 2 * g["grid_points"].get<int>() - 1);
  EXPECT_TRUE(check(r, "exact_grid_converged").passed);
  expect_replay_recorded(r.results["mujoco_replay"]);
  EXPECT_TRUE(check(r, "mujoco_dynamic_replay").passed);
}

std::string near_singular_end() {
  // ends 1e-8 m inside the outer boundary, at (0.9 - 1e-8) m from the base
  const double r0 = 0.9 - 1e-8, a = 1.0;
  char end[80];
  std::snprintf(end, sizeof end, "[%.17g, %.17g]", r0 * std::cos(a), r0 * std::sin(a));
  return end;
}

TEST(TimeOptimalResultsJson, NearSingularLineRecordsItsGradedGrid) {
  const CaseRun r = run_case_text(near_singular_end());
  ASSERT_EQ(r.status, studies::Status::kSolved) << r.message;
  const json& g = r.results["grid_convergence"];
  EXPECT_TRUE(g["passed"].get<bool>()) << g["text"];
  ASSERT_TRUE(g.contains("graded") && g["graded"].is_object()) << g;
  const json& gr = g["graded"];
  EXPECT_EQ(gr["uniform_points"].get<int>(), 600);
  EXPECT_GT(gr["uniform_change"].get<double>(), 0.01);
  EXPECT_GT(gr["rounds"].get<int>(), 0);
  EXPECT_EQ(gr["tolerance_rel"].get<double>(), 1e-4);
  EXPECT_FALSE(gr["capped"].get<bool>());
  EXPECT_GT(g["grid_points"].get<int>(), 600);
  EXPECT_LE(g["change"].get<double>(), 1e-4);
  EXPECT_LT(g["path_min_abs_sin_q2"].get<double>(), 0.01);
  EXPECT_TRUE(check(r, "exact_grid_converged").passed);
  EXPECT_EQ(r.message.find("NOT converged"), std::string::npos) << r.message;
  expect_replay_recorded(r.results["mujoco_replay"]);
}

TEST(TimeOptimalResultsJson, NearSingularLineOnItsUniformGridFailsItsGridCheckAndSaysSo) {
  const CaseRun r = run_case_text(near_singular_end(), ", tolerance_rel: 0");
  ASSERT_EQ(r.status, studies::Status::kSolved) << r.message;
  const json& g = r.results["grid_convergence"];
  EXPECT_FALSE(g["passed"].get<bool>());
  EXPECT_GT(g["change"].get<double>(), 0.01);
  EXPECT_LT(g["min_abs_sin_q2"].get<double>(), 0.01);
  EXPECT_FALSE(check(r, "exact_grid_converged").passed);
  EXPECT_NE(r.message.find("NOT converged"), std::string::npos) << r.message;
  expect_replay_recorded(r.results["mujoco_replay"]);
}

}  // namespace
}  // namespace armstudy::app
