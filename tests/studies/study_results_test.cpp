// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Each study's typed result and its JSON mapping agree with what a real run writes: a small
// case of every study is run into results.json; the study's section read back into its typed
// result (studies/<study>/study_results.hpp) and written again gives the same text, and
// the whole file validates against results.schema.json.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "app/json_numbers.hpp"
#include "app/pipeline.hpp"
#include "app/run_case.hpp"
#include "report/results_fields.hpp"
#include "studies/pendulum/study_results.hpp"
#include "studies/placement/study_results.hpp"
#include "studies/throwing/study_results.hpp"
#include "studies/time_optimal/study_results.hpp"
#include "testing/files.hpp"

namespace armstudy::app {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

// small cases of every study, seconds each (as tests/e2e/results_numbers_test.cpp)
const char* kPendulum = "study: pendulum\nname: rt-pendulum\npendulum: {duration_s: 0.4}\n";
const char* kPlacement =
    "study: placement\nname: rt-placement\nplacement:\n  length_fraction: 0.4\n"
    "  nx_s: 6\n  phi_step_deg: 6\n  samples: 51\n  map: {nx: 12, ny: 6}\n"
    "  evaluate:\n    - {label: a-placement, x_s_m: 0.52, phi_deg: 130.89}\n";
const char* kThrowing =
    "study: throwing\nname: rt-throwing\nthrowing:\n"
    "  idp: {stages: 4, steps_per_stage: 5, iterations: 2, max_passes: 1, candidates: 3, seeds: "
    "1}\n"
    "  nlopt: {max_evaluations: 3}\n  checks: {allow_not_converged: true}\n";
const char* kTimeOptimal =
    "study: time_optimal\nname: rt-time-optimal\ntime_optimal:\n"
    "  path: {kind: line, points_m: [[0.3, 0.1], [-0.1, 0.8]]}\n"
    "  dp: {segments: 10, levels: 40, states: [path_speed, joint1_velocity], convergence_segments: "
    "[]}\n"
    "  complex: {max_iterations: 400}\n  exact: {grid_points: 200}\n";

// runs `yaml` into a fresh folder; returns its results.json
json run(const std::string& yaml, const fs::path& out) {
  LoadedCase c = load_case_text(yaml, "case.yaml");
  RunOptions options;
  options.out_dir = out;
  options.render = false;
  run_case(c, options, {});
  return json::parse(armstudy::testing::slurp(out / c.info.name / "results.json"));
}

template <class Section>
void expect_round_trip(const std::string& yaml, const std::string& study) {
  const fs::path out = armstudy::testing::fresh_dir("results_sections_" + study);
  const json results = run(yaml, out);
  ASSERT_TRUE(results.contains(study));
  const Section typed = report::read_study_results<Section>(results, study);
  // to_json(from_json(section)) is the section, number for number and type for type
  EXPECT_EQ(results_text(report::to_json(typed)), results_text(results[study])) << study;
  // and the whole file is what results.schema.json describes
  const fs::path src(ARMSTUDY_SOURCE_DIR);
  const std::string cmd = "/usr/bin/python3 " + (src / "scripts/validate_results.py").string() +
                          " " + (src / "results.schema.json").string() + " " + out.string() +
                          " > " + (out / "validate.txt").string() + " 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << armstudy::testing::slurp(out / "validate.txt");
  fs::remove_all(out);
}

TEST(StudyResults, PendulumRoundTripsAndValidates) {
  expect_round_trip<studies::PendulumStudyResults>(kPendulum, "pendulum");
}
TEST(StudyResults, PlacementRoundTripsAndValidates) {
  expect_round_trip<studies::placement::StudyResults>(kPlacement, "placement");
}
TEST(StudyResults, ThrowingRoundTripsAndValidates) {
  expect_round_trip<studies::ThrowingStudyResults>(kThrowing, "throwing");
}
TEST(StudyResults, TimeOptimalRoundTripsAndValidates) {
  expect_round_trip<studies::time_optimal::StudyResults>(kTimeOptimal, "time_optimal");
}

// the strict reader: every problem names its JSON pointer
TEST(StudyResults, AMisspeltOrMistypedKeyIsAnErrorNamingIt) {
  const json good = report::to_json(studies::PendulumStudyResults{});
  const json whole = {{"pendulum", good}};
  EXPECT_NO_THROW(report::read_study_results<studies::PendulumStudyResults>(whole, "pendulum"));
  auto message = [&](const std::function<void(json&)>& edit) {
    json j = whole;
    edit(j);
    try {
      report::read_study_results<studies::PendulumStudyResults>(j, "pendulum");
    } catch (const report::ResultsError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message([](json& j) {
              j["pendulum"]["energy"]["drift_j"] = j["pendulum"]["energy"]["drift_J"];
              j["pendulum"]["energy"].erase("drift_J");
            }),
            "/pendulum/energy/drift_j: unknown key 'drift_j'; did you mean 'drift_J'?");
  EXPECT_EQ(message([](json& j) { j["pendulum"]["energy"].erase("drift_J"); }),
            "/pendulum/energy/drift_J: missing");
  EXPECT_EQ(message([](json& j) { j["pendulum"]["integrator"]["steps_accepted"] = 1.5; }),
            "/pendulum/integrator/steps_accepted: expected an integer, found a number");
  EXPECT_EQ(message([](json& j) { j["pendulum"]["energy"]["drift_J"] = "small"; }),
            "/pendulum/energy/drift_J: expected a number or null, found a string");
  EXPECT_EQ(message([](json& j) { j.erase("pendulum"); }), "/pendulum: missing");
  // null is how a number that is not finite is written: it reads back as NaN
  json j = whole;
  j["pendulum"]["energy"]["drift_J"] = nullptr;
  EXPECT_TRUE(std::isnan(
      report::read_study_results<studies::PendulumStudyResults>(j, "pendulum").energy.drift_J));
}

}  // namespace
}  // namespace armstudy::app
