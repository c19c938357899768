// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The answer box of page 1 and the CSS animations, from results.json written from the typed
// record and study sections: what the reviewer reads first must follow the checks and the
// study's own account of what binds.
#include "report/answer_box.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <utility>
#include <vector>

#include "app/pipeline.hpp"
#include "report/animation_view.hpp"
#include "report/page.hpp"
#include "report/results_record.hpp"
#include "report/study_sections.hpp"
#include "studies/placement/study_results.hpp"
#include "studies/time_optimal/study_results.hpp"

namespace armstudy::report {
namespace {
using nlohmann::json;

// a study's answer-box lines as its registry record holds them (the typed results read once)
StudyAnswer registered_answer(const std::string& study) { return app::find_study(study)->answer; }

// a results.json as run_case writes it: the shared record and the study's typed results
json results_of(const std::string& study, const json& section, std::vector<CheckRecord> checks,
                std::vector<std::string> frames, const std::string& message = "") {
  ResultsRecord r;
  r.armstudy_version = "0.1.0";
  r.study = study;
  r.case_info.name = "a-case";
  r.case_info.path = "a-case.yaml";
  r.case_info.sha256 = std::string(64, '0');
  r.provenance = {"0.1.0", {}, "2.2.2", "a compiler", "a CPU", {}, {}, {}};
  r.status = "solved";
  r.message = message;
  r.checks = std::move(checks);
  r.frames = std::move(frames);
  json j = write_record(r);
  j[study] = section;
  return j;
}

json placement_results(bool failed_check) {
  using PS = studies::placement::StudyResults;
  PS pl;
  pl.samples = 401;
  pl.singularity_margin_m = 0.01;
  PS::Optimum a, b;
  a.program = "cycloidal";
  a.energy_J = 4.0;
  a.decided_by.binding = "interior";
  a.decided_by.inner_slack_m = 0.1;
  a.decided_by.outer_slack_m = 0.2;
  b.program = "poly345";
  b.energy_J = 3.5;
  b.decided_by.binding = "inner_clearance";
  b.decided_by.margin_m = 0.01;
  pl.optima = {a, b};
  return results_of("placement", to_json(pl),
                    {{"energy_converged", "", 0, 0, true},
                     {"mujoco_dynamic_replay.poly345.1", "", 0, 0, !failed_check}},
                    {"placement_cycloidal_c1_locus.png", "placement_poly345_c1_strip.png",
                     "placement_poly345_c1_locus.png"},
                    "least energy 3.5 J (poly345, configuration 1)");
}

TEST(AnswerBox, VerdictCountsTheChecksAndNamesTheFailedOnesInWords) {
  const AnswerBox ok =
      answer_box(placement_results(false), CasePage{}, registered_answer("placement"));
  EXPECT_TRUE(ok.verdict_ok);
  EXPECT_EQ(ok.verdict, "All 2 checks passed.");
  const AnswerBox bad =
      answer_box(placement_results(true), CasePage{}, registered_answer("placement"));
  EXPECT_FALSE(bad.verdict_ok);
  EXPECT_EQ(bad.verdict, "1 of 2 checks FAILED: MuJoCo dynamic replay, poly345, 1.");
}

TEST(AnswerBox, KeyPictureIsTheLocusOfTheOptimumOfLeastEnergyAndBindingFollowsTheStudy) {
  const AnswerBox a =
      answer_box(placement_results(false), CasePage{}, registered_answer("placement"));
  EXPECT_EQ(a.picture, "placement_poly345_c1_locus.png");
  EXPECT_EQ(a.sentence, "least energy 3.5 J (poly345, configuration 1)");
  ASSERT_EQ(a.binding.size(), 2u);
  EXPECT_NE(a.binding[0].find("interior"), std::string::npos) << a.binding[0];
  EXPECT_NE(a.binding[1].find("clearance margin to the inner circle"), std::string::npos)
      << a.binding[1];
  EXPECT_FALSE(a.assumptions.empty());
  // without the study's lines: the first locus, and nothing said about what binds
  const AnswerBox plain = answer_box(placement_results(false), CasePage{}, nullptr);
  EXPECT_EQ(plain.picture, "placement_cycloidal_c1_locus.png");
  EXPECT_TRUE(plain.binding.empty());
}

TEST(AnswerBox, WithoutFramesThePageFirstFigureIsThePicture) {
  json r = placement_results(false);
  r["frames"] = json::array();
  CasePage page;
  Section s;
  s.figure({"fig01_map.svg", "the energy map"});
  page.sections.push_back(s);
  const AnswerBox a = answer_box(r, page, registered_answer("placement"));
  EXPECT_EQ(a.picture, "fig01_map.svg");
  EXPECT_EQ(a.picture_caption, page.sections[0].blocks[0].figure.caption);
}

TEST(AnswerBox, AMisspeltKeyIsAnErrorNamingItNotAnEmptyBox) {
  json r = placement_results(false);
  r["checks"][0]["pased"] = r["checks"][0]["passed"];
  r["checks"][0].erase("passed");
  try {
    answer_box(r, CasePage{}, registered_answer("placement"));
    FAIL() << "expected a ResultsError";
  } catch (const ResultsError& e) {
    EXPECT_EQ(e.path(), "/checks/0/pased");
    EXPECT_NE(std::string(e.what()).find("did you mean 'passed'?"), std::string::npos) << e.what();
  }
  json s = placement_results(false);
  s["placement"]["optima"][0]["decided_by"]["bindng"] = "interior";
  EXPECT_THROW(answer_box(s, CasePage{}, registered_answer("placement")), ResultsError);
}

// the answer box of a time-optimal result of two joints (configuration 1) whose exact solver
// has the samples given: times, and per joint (one row each) the rates and torques
AnswerBox exact_answer(std::vector<double> velocity_limits, std::vector<double> t,
                       std::vector<std::vector<double>> qd, std::vector<std::vector<double>> tau) {
  using TO = studies::time_optimal::StudyResults;
  TO to;
  to.limits.velocity_rad_s = std::move(velocity_limits);
  to.limits.torque_Nm = {10.0, 10.0};
  to.configuration = 1;
  TO::Solver exact;
  exact.samples = TO::Samples{};
  exact.samples->t_s = std::move(t);
  exact.samples->qd_rad_s = std::move(qd);
  exact.samples->tau_Nm = std::move(tau);
  to.solvers = {exact};
  return answer_box(results_of("time_optimal", to_json(to), {}, {}), CasePage{},
                    registered_answer("time_optimal"));
}

TEST(AnswerBox, TimeOptimalNamesTheLimitsAtTheirBoundByShareOfSamples) {
  const AnswerBox a = exact_answer({1.0, 2.0}, {0, 1, 2, 3}, {{0.5, 1.0, 1.0, 0.2}, {0, 0, 0, 2.0}},
                                   {{10, 1, 1, 1}, {0, 0, 0, 0}});
  ASSERT_EQ(a.binding.size(), 3u);
  EXPECT_NE(a.binding[0].find("velocity of joint 1 limit binds at 50 %"), std::string::npos)
      << a.binding[0];
  EXPECT_NE(a.binding[1].find("binds at 25 %"), std::string::npos) << a.binding[1];
  EXPECT_EQ(a.verdict, "The study ran no checks on this case.");
  EXPECT_NE(a.assumptions.back().find("no joint acceleration limit"), std::string::npos)
      << a.assumptions.back();
}

// the binding lines of a two-joint time-optimal result whose joint 1 torque is at its limit
// at `at` of `n` samples of the exact solver
std::vector<std::string> torque_binding(int at, int n) {
  std::vector<double> t;
  for (int i = 0; i < n; ++i) t.push_back(0.01 * i);
  std::vector<double> tau1(n, 2.0);
  for (int i = 0; i < at; ++i) tau1[i] = i % 2 ? -10.0 : 10.0;
  return exact_answer({5.0, 5.0}, std::move(t),
                      {std::vector<double>(n, 1.0), std::vector<double>(n, 1.0)},
                      {tau1, std::vector<double>(n, 1.0)})
      .binding;
}

TEST(AnswerBox, AFullyTorqueBoundTimeOptimalCaseSaysOneHundredPerCentNeverInExponentForm) {
  // every sample at the torque limit: "100 %", never format_sig's "1e+02 %"
  const std::vector<std::string> all = torque_binding(400, 400);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0], "the torque of joint 1 limit binds at 100 % of the samples (within 1 %)");
  // all but one of 1000 (99.9 %): whole per cents, and not rounded up to all of them
  const std::vector<std::string> most = torque_binding(999, 1000);
  ASSERT_EQ(most.size(), 1u);
  EXPECT_EQ(most[0], "the torque of joint 1 limit binds at 99 % of the samples (within 1 %)");
  // a few: two digits
  const std::vector<std::string> few = torque_binding(3, 1000);
  ASSERT_EQ(few.size(), 1u);
  EXPECT_EQ(few[0], "the torque of joint 1 limit binds at 0.3 % of the samples (within 1 %)");
  for (const auto& lines : {all, most, few})
    for (const std::string& line : lines) EXPECT_EQ(line.find("e+"), std::string::npos) << line;
}

AnimationRecord arm_animation() {
  AnimationRecord a;
  a.name = "arm";
  a.title = "the arm";
  a.sprite = "arm_anim.png";
  a.still = "arm_still.png";
  a.video = "arm.mp4";
  a.frames = 10;
  a.columns = 4;
  a.frame_width_px = 480;
  a.frame_height_px = 360;
  a.fps = 9.0;
  a.duration_s = 1.0;
  a.video_duration_s = 10 / 9.0;
  return a;
}

TEST(AnimationView, KeyframesStepThroughEveryFrameOfTheGridAndHoldTheLast) {
  const std::vector<AnimationRecord> r = {arm_animation()};
  const std::string css = animation_css(r);
  EXPECT_NE(
      css.find(".anim.a-arm { aspect-ratio: 480 / 360; background-image: url(\"arm_anim.png\"); "
               "background-size: 400% 300%; animation: a-arm 2.5s step-end infinite; }"),
      std::string::npos)
      << css;
  // 10 frames and the held end: 11 stops; frame 9 is column 1 of row 2 (of 0..2)
  const std::regex stop(R"(\d+(\.\d+)?% \{ background-position)");
  EXPECT_EQ(
      std::distance(std::sregex_iterator(css.begin(), css.end(), stop), std::sregex_iterator()),
      11);
  EXPECT_NE(css.find("90% { background-position: 33.33% 100%; }"), std::string::npos) << css;
  EXPECT_NE(css.find("100% { background-position: 33.33% 100%; }"), std::string::npos) << css;
  const Section s = animation_section(r);
  ASSERT_EQ(s.blocks.size(), 2u);
  ASSERT_EQ(s.blocks[1].movies.size(), 1u);
  EXPECT_EQ(s.blocks[1].movies[0].video, "arm.mp4");
  EXPECT_NE(s.blocks[1].movies[0].caption.find("2.2× slower than real time"), std::string::npos)
      << s.blocks[1].movies[0].caption;
}

TEST(AnimationView, AnUnsafeSpriteNameWritesNoRule) {
  AnimationRecord a = arm_animation();
  a.sprite = "a\");}body{x:url(\"y.png";
  EXPECT_EQ(animation_css({a}), "");
}

}  // namespace
}  // namespace armstudy::report
