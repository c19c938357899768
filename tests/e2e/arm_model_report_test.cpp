// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// An arm read from a robot description (`arm: {model: FILE}`): every study that takes one
// says where its arm and its limits came from, in results.json (`<study>.arm_model`) and on
// its page, in the same words (report/arm_model_paragraphs.hpp). The placement study said
// it only in model.xml's comment.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "testing/cli.hpp"
#include "testing/files.hpp"

namespace {
namespace fs = std::filesystem;
using armstudy::testing::fresh_dir;
using armstudy::testing::kSource;
using armstudy::testing::run_cli;
using armstudy::testing::slurp;

TEST(ArmModelReport, ThePlacementStudySaysWhereItsArmAndLimitsCameFromAsTheTimeOptimalDoes) {
  const fs::path d = fresh_dir("arm_model_report");
  const fs::path c = d / "placement-urdf.yaml";
  // the placement study's default arm as a URDF with effort limits, on a small search
  std::ofstream(c) << "study: placement\nname: placement-urdf\narm: {model: "
                   << (kSource / "tests/cases/models/thesis_arm.urdf").string() << "}\n"
                   << "placement:\n  length_fraction: 0.5\n  nx_s: 6\n  phi_step_deg: 30\n"
                      "  thesis_divisions: 2\n  map: {nx: 4, ny: 3}\n"
                      "  programs: [cycloidal]\n  configurations: [1]\n";
  const fs::path out = d / "out";
  const auto r =
      run_cli("run --no-render --no-sensitivity --out " + out.string() + " " + c.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(slurp(out / "placement-urdf/results.json"));
  ASSERT_TRUE(j["placement"].contains("arm_model")) << "placement.arm_model";
  const auto lines = j["placement"]["arm_model"].get<std::vector<std::string>>();
  ASSERT_GE(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("arm read from ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find("thesis_arm.urdf (URDF"), std::string::npos) << lines[0];
  EXPECT_EQ(lines[1].rfind("placement.torque_limits_Nm", 0), 0u) << lines[1];
  const std::string page = slurp(out / "placement-urdf/index.html");
  EXPECT_NE(page.find("The arm read from "), std::string::npos);
  EXPECT_NE(page.find("Where each limit came from: placement.torque_limits_Nm"), std::string::npos);
  // an arm written in the case has no such entry
  std::ofstream(c) << "study: placement\nname: placement-urdf\n"
                   << "placement:\n  length_fraction: 0.5\n  nx_s: 6\n  phi_step_deg: 30\n"
                      "  thesis_divisions: 2\n  map: {nx: 4, ny: 3}\n"
                      "  programs: [cycloidal]\n  configurations: [1]\n";
  const auto again =
      run_cli("run --no-render --no-sensitivity --force --out " + out.string() + " " + c.string());
  ASSERT_EQ(again.exit_code, 0) << again.output;
  const auto k = nlohmann::json::parse(slurp(out / "placement-urdf/results.json"));
  EXPECT_FALSE(k["placement"].contains("arm_model"));
  EXPECT_EQ(slurp(out / "placement-urdf/index.html").find("Where each limit came from"),
            std::string::npos);
  fs::remove_all(d);
}

}  // namespace
