// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The time-optimal study's verdicts on cases kept in tests/studies/cases: a correct plan
// fails none of its own checks (each check's tolerance is the error its own method
// allows), and an arm that cannot hold itself against gravity is told so, naming the joint,
// the point and the torque needed, before any other conflict; the speed the limits need at a
// rest point is given in the path's own unit.
#include <gtest/gtest.h>

#include <string>

#include "app/pipeline.hpp"
#include "app/run_case.hpp"

namespace armstudy::app {
namespace {

struct Solved {
  studies::Status status;
  std::string message;
  std::vector<studies::Check> checks;
};

Solved solve_case_file(const std::string& file) {
  LoadedCase c = load_case(std::string(ARMSTUDY_SOURCE_DIR) + "/tests/studies/cases/" + file);
  Solved out;
  out.status = c.run->solve({});
  out.message = c.run->message();
  out.checks = c.run->checks();
  return out;
}

void expect_every_check_passes(const Solved& s, const std::string& file) {
  ASSERT_EQ(s.status, studies::Status::kSolved) << file << ": " << s.message;
  ASSERT_FALSE(s.checks.empty());
  for (const studies::Check& c : s.checks)
    EXPECT_TRUE(c.passed) << file << ": " << c.name << " = " << c.value << " against "
                          << c.tolerance << ": " << c.description;
}

TEST(TimeOptimalVerdicts, ALinePassingTheInnerCircleByATenthOfAMillimetreFailsNoCheck) {
  // Complex's motion overshoots a limit between its check points by 2.3e-3 relative, within
  // its own discretisation error (8.8 % over the exact duration): no false failure
  const Solved s = solve_case_file("time-optimal-near-inner-circle.yaml");
  expect_every_check_passes(s, "time-optimal-near-inner-circle.yaml");
}

TEST(TimeOptimalVerdicts, ASixLinkArmOfPointMassesPassesItsMujocoReplay) {
  // a correct plan of a long chain passes every check, MuJoCo's replay included
  const Solved s = solve_case_file("time-optimal-6link-point-masses.yaml");
  expect_every_check_passes(s, "time-optimal-6link-point-masses.yaml");
  bool replayed = false;
  for (const studies::Check& c : s.checks) replayed |= c.name == "mujoco_dynamic_replay";
  EXPECT_TRUE(replayed);
}

TEST(TimeOptimalVerdicts, AnArmThatCannotHoldItselfIsToldSoFirst) {
  const Solved s = solve_case_file("time-optimal-cannot-hold.yaml");
  ASSERT_EQ(s.status, studies::Status::kUnsolvable);
  // the joint, the limit, the point and the torque needed, before the solver's conflict
  const std::string want =
      "the joint 1 torque limit 10 N m cannot hold the arm at rest against gravity";
  EXPECT_EQ(s.message.rfind(want, 0), 0u) << s.message;
  EXPECT_NE(s.message.find("at s = "), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("holding it needs 13."), std::string::npos) << s.message;
}

// the exact solver's words when the limits need speed at a rest point: s'^2 in the unit of
// the path, rad^2/s^2 on a joint-space path and m^2/s^2 on a tip path, never the other
void expect_rest_speed_in(const std::string& file, const std::string& unit,
                          const std::string& other) {
  const Solved s = solve_case_file(file);
  ASSERT_EQ(s.status, studies::Status::kUnsolvable) << file;
  const size_t at = s.message.find("the limits need s'^2 >= ");
  ASSERT_NE(at, std::string::npos) << file << ": " << s.message;
  const size_t close = s.message.find(')', at);
  ASSERT_NE(close, std::string::npos) << s.message;
  const std::string need = s.message.substr(at, close - at);
  EXPECT_TRUE(need.ends_with(" " + unit + "^2/s^2")) << file << ": " << need;
  EXPECT_EQ(s.message.find(other + "^2/s^2"), std::string::npos) << file << ": " << s.message;
}

TEST(TimeOptimalVerdicts, TheSpeedNeededAtARestPointIsInThePathsUnit) {
  expect_rest_speed_in("time-optimal-start-needs-speed-joint.yaml", "rad", " m");
  expect_rest_speed_in("time-optimal-start-needs-speed-tip.yaml", "m", "rad");
}

}  // namespace
}  // namespace armstudy::app
