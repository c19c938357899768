// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The sweep page: one plot per key figure over the first numeric parameter, curves per
// combination of the others, failed cases left out of the plots and counted.
#include "report/sweep_report.hpp"

#include <gtest/gtest.h>

#include "testing/files.hpp"

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace armstudy::report {
namespace {
namespace fs = std::filesystem;

using armstudy::testing::slurp;

fs::path sweep_dir(const std::string& name) {
  return armstudy::testing::fresh_dir("sweep_report_test_" + name);
}

// ratio in {0.2, 0.4, 0.6} x fraction in {0.5, 0.8}; one case failed
SweepTable table() {
  SweepTable t;
  t.parameters = {"arm.ratio", "task.fraction"};
  t.figures = {"root_x_m", "energy_J"};
  t.units = {{"energy_J", "J"}, {"root_x_m", "m"}};
  int k = 0;
  for (const char* ratio : {"0.2", "0.4", "0.6"})
    for (const char* fraction : {"0.5", "0.8"}) {
      const double r = std::stod(ratio), f = std::stod(fraction);
      SweepRow row;
      row.case_name = "c";
      row.case_name += std::to_string(k);
      row.status = k == 3 ? "failed" : "ok";
      row.parameters = {{"arm.ratio", ratio}, {"task.fraction", fraction}};
      row.key_figures = {{"energy_J", r * f}, {"root_x_m", r - f}};
      t.rows.push_back(row);
      ++k;
    }
  return t;
}

TEST(SweepReport, DrawsEveryKeyFigureOverTheNumericAxisInTheStudysOrder) {
  const fs::path dir = sweep_dir("plots");
  EXPECT_EQ(write_sweep_report(dir, table(), "demo-sweep"), 2);
  const std::string html = slurp(dir / "index.html");
  EXPECT_NE(html.find("demo-sweep"), std::string::npos);
  EXPECT_NE(html.find("Key figures over arm.ratio"), std::string::npos);
  EXPECT_NE(html.find("1 case(s) did not pass"), std::string::npos) << "failed cases are counted";
  // the study's order: root_x_m first, then energy_J; every linked image exists
  const size_t root = html.find("The key figure root_x_m");
  const size_t energy = html.find("The key figure energy_J");
  ASSERT_NE(root, std::string::npos);
  ASSERT_NE(energy, std::string::npos);
  EXPECT_LT(root, energy);
  const std::regex img("<img src=\"([^\"]+)\"");
  int images = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), img); it != std::sregex_iterator();
       ++it) {
    EXPECT_TRUE(fs::exists(dir / (*it)[1].str())) << (*it)[1].str();
    ++images;
  }
  EXPECT_EQ(images, 2);
  // one curve per fraction: both appear in the legend of the SVG
  const std::string svg = slurp(dir / "fig02_sweep_2.svg");
  EXPECT_GT(svg.size(), 1000u);
  fs::remove_all(dir);
}

TEST(SweepReport, WithoutANumericParameterSaysSoAndDrawsNothing) {
  SweepTable t = table();
  for (auto& r : t.rows) r.parameters["arm.ratio"] = "a" + *r.parameters["arm.ratio"];
  for (auto& r : t.rows) r.parameters["task.fraction"] = "[1, 2]";
  const fs::path dir = sweep_dir("none");
  EXPECT_EQ(write_sweep_report(dir, t, "no-axis"), 0);
  EXPECT_NE(slurp(dir / "index.html").find("no axis to plot over"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace armstudy::report
