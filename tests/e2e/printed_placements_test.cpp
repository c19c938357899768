// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The thesis's printed placements in the placement report (Kopmaz 2016, Ch. 9): their roots
// marked on the maps and on the Fig. 9.30 analogue, their motion over time drawn beside the
// optima's (example 1's Figs. 9.1-9.5), from the bundled examples 1 and 2.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "report/placement_page.hpp"
#include "report/results_fields.hpp"
#include "testing/cli.hpp"
#include "testing/files.hpp"

namespace armstudy::printed_placements_e2e {
namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kRepo = ARMSTUDY_SOURCE_DIR;
const char* const kQuantities[] = {"joint_angles", "joint_velocities", "joint_accelerations",
                                   "joint_torques", "joint_powers"};

// the evaluation of `label` for the cycloidal program at `configuration`
const json& evaluation(const json& results, const std::string& label, int configuration) {
  for (const json& e : results["placement"]["evaluations"])
    if (e["label"] == label && e["program"] == "cycloidal" && e["configuration"] == configuration)
      return e;
  static const json none;
  ADD_FAILURE() << "no evaluation " << label << " of configuration " << configuration;
  return none;
}

bool has(const std::string& text, const std::string& what) {
  return text.find(what) != std::string::npos;
}

// the case folder's figure NAME.svg (written as figNN_NAME.svg); empty when there is none
fs::path figure(const fs::path& dir, const std::string& name) {
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string f = e.path().filename().string();
    if (f.starts_with("fig") && f.find('_') == 5 && f.substr(6) == name + ".svg") return e.path();
  }
  return {};
}

using PS = studies::placement::StudyResults;

// examples 1 and 2 run once per process into a folder of the process's own (ctest runs each
// test in a process of its own, several at once); each test first asks that the run worked
class PrintedPlacements : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    out_ = new fs::path(testing::fresh_dir("printed_placements_" + std::to_string(::getpid())));
    run_ = new testing::CliRun(
        testing::run_cli("run --no-render --no-sensitivity --out " + out_->string() + " " +
                         (kRepo / "reports/cases/placement-example-1.yaml").string() + " " +
                         (kRepo / "reports/cases/placement-example-2.yaml").string()));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*out_);
    delete out_;
    delete run_;
  }
  void SetUp() override { ASSERT_EQ(run_->exit_code, 0) << run_->output; }
  static fs::path dir(int example) {
    return *out_ / ("placement-example-" + std::to_string(example));
  }
  static fs::path* out_;
  static testing::CliRun* run_;
};
testing::CliRun* PrintedPlacements::run_ = nullptr;
fs::path* PrintedPlacements::out_ = nullptr;

// example 2: the printed roots (from the printed x_S and phi by (4.14)) are marked on armstudy's
// root-location figure and on the map of their configuration, with their legend
TEST_F(PrintedPlacements, TheThesisRootsAreMarkedOnTheMapsWithTheirLegend) {
  const json results = json::parse(testing::slurp(dir(2) / "results.json"));
  const json& c1 = evaluation(results, "thesis-config-1", 1);
  const double phi = 138.96 * M_PI / 180;
  EXPECT_NEAR(c1["root_xy_m"][0].get<double>(), -0.6 * std::cos(phi), 1e-12);
  EXPECT_NEAR(c1["root_xy_m"][1].get<double>(), 0.6 * std::sin(phi), 1e-12);
  EXPECT_NEAR(c1["root_xy_m"][0].get<double>(), 0.4526, 5e-5);  // the printed 2X1

  // the marks the maps draw, from the case's results.json as the report reads it
  const PS pl = report::read_study_results<PS>(results, "placement");
  const auto printed = report::placement_page::printed_placements(pl, "cycloidal");
  ASSERT_EQ(printed.size(), 2u);
  EXPECT_EQ(printed[0]->label, "thesis-config-1");
  EXPECT_EQ(printed[0]->configuration, 1);
  EXPECT_EQ(printed[1]->label, "thesis-config-2");  // not the tangent line it means
  EXPECT_EQ(printed[1]->configuration, 2);
  const auto conf2 = report::placement_page::printed_root_markers(pl, 2);
  ASSERT_EQ(conf2.size(), 1u);
  EXPECT_TRUE(conf2[0].printed);
  EXPECT_EQ(conf2[0].label, "thesis's printed root, conf. 2");
  const double phi2 = 155.18 * M_PI / 180;
  EXPECT_NEAR(conf2[0].x, -0.4764 * std::cos(phi2), 1e-12);
  EXPECT_NEAR(conf2[0].y, 0.4764 * std::sin(phi2), 1e-12);
  EXPECT_EQ(report::placement_page::printed_root_markers(pl, 0).size(), 2u);

  EXPECT_FALSE(figure(dir(2), "root_loci").empty());
  EXPECT_FALSE(figure(dir(2), "map_cycloidal_2").empty());
  const std::string html = testing::slurp(dir(2) / "index.html");
  EXPECT_TRUE(has(html, "Triangles: the roots the thesis prints")) << "the caption names them";
  EXPECT_TRUE(has(html, "conf. 1 (0.4526, 0.394) m from x_S = 0.6 m, φ = 138.96°"));
  EXPECT_TRUE(has(html, "the triangle the root the thesis prints for the configuration"));
}

// example 2: the motion at the printed placements beside the optima's; the printed
// configuration-2 line dips into the inner circle, so the tangent line it means is drawn, and
// its running energy is not (the folded elbow's jump term is not in the samples)
TEST_F(PrintedPlacements, TheirMotionIsDrawnBesideTheOptimas) {
  for (const char* q : kQuantities) {
    EXPECT_FALSE(figure(dir(2), std::string("printed_") + q).empty()) << q;
    EXPECT_FALSE(figure(dir(2), q).empty()) << q << " of the optima";
  }
  EXPECT_FALSE(figure(dir(2), "printed_energy").empty());
  const std::string html = testing::slurp(dir(2) / "index.html");
  EXPECT_TRUE(has(html, "The motion at the thesis&apos;s printed placements"));
  EXPECT_TRUE(has(html, "No motion at conf. 2 (thesis-config-2: x_S = 0.4764 m, φ = 155.18°)"));
  EXPECT_TRUE(has(html,
                  "drawn instead: the line the printed digits mean, conf. 2 "
                  "(thesis-config-2-tangent"));
  EXPECT_TRUE(has(html, "The running energy is not drawn for conf. 2 (thesis-config-2-tangent"));

  // the drawn energy ends on the placement's printed (quadrature) energy, 17.1067 J
  const json results = json::parse(testing::slurp(dir(2) / "results.json"));
  const json& c1 = evaluation(results, "thesis-config-1", 1);
  const double end = c1["series"]["energy_J"].back().get<double>();
  EXPECT_NEAR(end, c1["energy_J"].get<double>(), 1e-3 * c1["energy_J"].get<double>());
  EXPECT_NEAR(c1["energy_J"].get<double>(), 17.10669985, 1e-6);
  // the tangent line's sampled energy misses the fold's jump: far below its 92.14 J
  const json& t2 = evaluation(results, "thesis-config-2-tangent", 2);
  EXPECT_LT(t2["series"]["energy_J"].back().get<double>(), 0.6 * t2["energy_J"].get<double>());
}

// example 1 (no admissible optimum): the thesis's Figs. 9.1-9.5, the cycloidal program's
// motion in both configurations on the one line of length Lmax, and its root on the Fig. 9.30
// analogue; the elbow folds at t = T/2, so the rates there are a gap, not a number
TEST_F(PrintedPlacements, ExampleOnesTimeHistoriesAreDrawnAsTheThesisDrawsThem) {
  for (const char* q : kQuantities)
    EXPECT_FALSE(figure(dir(1), std::string("printed_") + q).empty()) << q;
  EXPECT_TRUE(figure(dir(1), "printed_energy").empty()) << "the fold's jump is not sampled";
  EXPECT_FALSE(figure(dir(1), "root_loci").empty()) << "the printed root, without an optimum";
  const std::string html = testing::slurp(dir(1) / "index.html");
  EXPECT_TRUE(has(html, "Joint angles over time (the thesis&apos;s Figure 9.1)"));
  EXPECT_TRUE(has(html, "Powers over time (the thesis&apos;s Figure 9.5)"));
  EXPECT_TRUE(has(html, "The running energy is not drawn for conf. 1 (thesis-only-line"));
  const json results = json::parse(testing::slurp(dir(1) / "results.json"));
  const PS pl = report::read_study_results<PS>(results, "placement");
  const auto marks = report::placement_page::printed_root_markers(pl, 0);
  ASSERT_EQ(marks.size(), 1u);  // one line, printed for both configurations
  EXPECT_EQ(marks[0].label, "thesis's printed root, conf. 1 and 2");
  for (int conf = 1; conf <= 2; ++conf) {
    const json& e = evaluation(results, "thesis-only-line", conf);
    EXPECT_NEAR(e["root_xy_m"][0].get<double>(), std::sqrt(0.32), 1e-12);  // the printed 0.56
    EXPECT_NEAR(e["root_xy_m"][1].get<double>(), 0.2, 1e-12);              // the printed 0.1999
    EXPECT_NEAR(e["energy_J"].get<double>(), 146.5337909, 1e-6);
    const json& q1 = e["series"]["q1_rad"];
    ASSERT_EQ(q1.size(), 101u);
    for (const json& v : q1) EXPECT_TRUE(v.is_number());  // the angles are defined throughout
    EXPECT_TRUE(e["series"]["qd1_rad_s"][50].is_null());  // 0/0 at the fold, t = T/2
  }
}

}  // namespace armstudy::printed_placements_e2e
