// The answer box of page 1 and the CSS animations, from hand-made results.json: what the
// reviewer reads first must follow the checks and the study's own account of what binds.
#include "report/answer_box.hpp"

#include <gtest/gtest.h>

#include <regex>

#include "report/animation_view.hpp"
#include "report/page.hpp"

namespace armstudy::report {
namespace {
using nlohmann::json;

json placement_results(bool failed_check) {
  return json{{"study", "placement"},
              {"status", "solved"},
              {"message", "least energy 3.5 J (poly345, configuration 1)"},
              {"checks", json::array({{{"name", "energy_converged"}, {"passed", true}},
                                      {{"name", "mujoco_dynamic_replay.poly345.1"}, {"passed", !failed_check}}})},
              {"frames", json::array({"placement_cycloidal_c1_locus.png", "placement_poly345_c1_strip.png",
                                      "placement_poly345_c1_locus.png"})},
              {"placement",
               {{"samples", 401},
                {"singularity_margin_m", 0.01},
                {"torque_limits_Nm", nullptr},
                {"power_limits_W", nullptr},
                {"optima", json::array({{{"program", "cycloidal"}, {"configuration", 1}, {"energy_J", 4.0},
                                         {"decided_by", {{"binding", "interior"}, {"inner_slack_m", 0.1}, {"outer_slack_m", 0.2}}}},
                                        {{"program", "poly345"}, {"configuration", 1}, {"energy_J", 3.5},
                                         {"decided_by", {{"binding", "inner_clearance"}, {"margin_m", 0.01}}}}})}}}};
}

TEST(AnswerBox, VerdictCountsTheChecksAndNamesTheFailedOnesInWords) {
  const AnswerBox ok = answer_box(placement_results(false), CasePage{});
  EXPECT_TRUE(ok.verdict_ok);
  EXPECT_EQ(ok.verdict, "All 2 checks passed.");
  const AnswerBox bad = answer_box(placement_results(true), CasePage{});
  EXPECT_FALSE(bad.verdict_ok);
  EXPECT_EQ(bad.verdict, "1 of 2 checks FAILED: MuJoCo dynamic replay, poly345, 1.");
}

TEST(AnswerBox, KeyPictureIsTheLocusOfTheOptimumOfLeastEnergyAndBindingFollowsTheStudy) {
  const AnswerBox a = answer_box(placement_results(false), CasePage{});
  EXPECT_EQ(a.picture, "placement_poly345_c1_locus.png");
  EXPECT_EQ(a.sentence, "least energy 3.5 J (poly345, configuration 1)");
  ASSERT_EQ(a.binding.size(), 2u);
  EXPECT_NE(a.binding[0].find("interior"), std::string::npos) << a.binding[0];
  EXPECT_NE(a.binding[1].find("clearance margin to the inner circle"), std::string::npos) << a.binding[1];
  EXPECT_FALSE(a.assumptions.empty());
}

TEST(AnswerBox, WithoutFramesThePageFirstFigureIsThePicture) {
  json r = placement_results(false);
  r["frames"] = json::array();
  CasePage page;
  Section s;
  s.figure({"fig01_map.svg", "the energy map"});
  page.sections.push_back(s);
  const AnswerBox a = answer_box(r, page);
  EXPECT_EQ(a.picture, "fig01_map.svg");
  EXPECT_EQ(a.picture_caption, page.sections[0].blocks[0].figure.caption);
}

TEST(AnswerBox, TimeOptimalNamesTheLimitsAtTheirBoundByShareOfSamples) {
  json r = {{"study", "time_optimal"},
            {"checks", json::array()},
            {"time_optimal",
             {{"limits", {{"velocity_rad_s", {1.0, 2.0}}, {"torque_Nm", {10.0, 10.0}}, {"acceleration_rad_s2", nullptr}}},
              {"configuration", 1},
              {"solvers", json::array({{{"samples",
                                         {{"t_s", {0, 1, 2, 3}},
                                          {"qd_rad_s", {{0.5, 0}, {1.0, 0}, {1.0, 0}, {0.2, 2.0}}},
                                          {"tau_Nm", {{10, 0}, {1, 0}, {1, 0}, {1, 0}}}}}}})}}}};
  const AnswerBox a = answer_box(r, CasePage{});
  ASSERT_EQ(a.binding.size(), 3u);
  EXPECT_NE(a.binding[0].find("velocity of joint 1 limit binds at 50 %"), std::string::npos) << a.binding[0];
  EXPECT_EQ(a.verdict, "The study ran no checks on this case.");
}

TEST(AnimationView, KeyframesStepThroughEveryFrameOfTheGridAndHoldTheLast) {
  const json r = {{"animations", json::array({{{"name", "arm"}, {"title", "the arm"}, {"sprite", "arm_anim.png"},
                                               {"still", "arm_still.png"}, {"video", "arm.mp4"},
                                               {"frames", 10}, {"columns", 4}, {"frame_width_px", 480},
                                               {"frame_height_px", 360}, {"fps", 9.0}, {"duration_s", 1.0},
                                               {"video_duration_s", 10 / 9.0}}})}};
  const std::string css = animation_css(r);
  EXPECT_NE(css.find(".anim.a-arm { aspect-ratio: 480 / 360; background-image: url(\"arm_anim.png\"); "
                     "background-size: 400% 300%; animation: a-arm 2.5s step-end infinite; }"),
            std::string::npos)
      << css;
  // 10 frames and the held end: 11 stops; frame 9 is column 1 of row 2 (of 0..2)
  const std::regex stop(R"(\d+(\.\d+)?% \{ background-position)");
  EXPECT_EQ(std::distance(std::sregex_iterator(css.begin(), css.end(), stop), std::sregex_iterator()), 11);
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
  const json r = {{"animations", json::array({{{"name", "x"}, {"sprite", "a\");}body{x:url(\"y.png"},
                                               {"frames", 4}, {"columns", 2}, {"frame_width_px", 10},
                                               {"frame_height_px", 10}, {"fps", 3.0}, {"duration_s", 1.0}}})}};
  EXPECT_EQ(animation_css(r), "");
}

}  // namespace
}  // namespace armstudy::report
