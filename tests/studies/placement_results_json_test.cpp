// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The "placement" part of results.json as placement_pipeline.cpp documents it, produced by the
// pipeline from a case file (what the report and CI read).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/pipeline.hpp"
#include "app/run_case.hpp"
#include "report/case_report.hpp"
#include "studies/placement/converge.hpp"

namespace armstudy::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json run_case_file(const std::string& yaml, studies::Status* status) {
  const fs::path dir =
      fs::temp_directory_path() / ("armstudy_placement_json_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "case.yaml";
  std::ofstream(file) << yaml;
  LoadedCase c = load_case(file.string());
  *status = c.run->solve({});
  json j = c.run->results();
  fs::remove_all(dir);
  return j;
}

const char* kCase =
    "study: placement\nname: json-test\nplacement:\n  length_fraction: 0.4\n  nx_s: 20\n"
    "  phi_step_deg: 2\n  samples: 201\n  map: {nx: 40, ny: 25}\n"
    "  evaluate:\n    - {label: thesis-config-1, x_s_m: 0.52, phi_deg: 130.89}\n";

TEST(PlacementResultsJson, HoldsOptimaEvaluationsCountsAndLmaxAsSpecified) {
  studies::Status status;
  const json j = run_case_file(kCase, &status);
  ASSERT_EQ(status, studies::Status::kSolved);
  EXPECT_NEAR(j["lmax_m"].get<double>(), 4 * std::sqrt(0.08), 1e-6);
  for (const char* k : {"total", "singular", "clear", "unreachable", "thesis_admitted",
                        "thesis_rejected_by_exact_check", "exact_accepted_outside_thesis"})
    EXPECT_TRUE(j["geometry_counts"].contains(k)) << k;
  EXPECT_EQ(j["geometry_counts"]["total"].get<int>(),
            j["geometry_counts"]["unreachable"].get<int>() +
                j["geometry_counts"]["singular"].get<int>() +
                j["geometry_counts"]["clear"].get<int>());
  ASSERT_EQ(j["optima"].size(), 4u);
  for (const json& o : j["optima"]) {
    for (const char* k : {"program", "configuration", "energy_J", "x_s_m", "phi_deg", "root_xy_m",
                          "grid_energy_J", "min_abs_sin_elbow", "peak_torque_Nm", "singular"})
      ASSERT_TRUE(o.contains(k)) << k;
    EXPECT_FALSE(o["singular"].get<bool>());
    EXPECT_LE(o["energy_J"].get<double>(), o["grid_energy_J"].get<double>());
    // (4.14): the root in the line's frame from the start abscissa and direction angle
    const double xs = o["x_s_m"], phi = o["phi_deg"].get<double>() * M_PI / 180;
    EXPECT_NEAR(o["root_xy_m"][0].get<double>(), -xs * std::cos(phi), 1e-6);
    EXPECT_NEAR(o["root_xy_m"][1].get<double>(), xs * std::sin(phi), 1e-6);
    EXPECT_EQ(o["peak_torque_Nm"].size(), 2u);
    EXPECT_EQ(o["series"]["t_s"].size(), o["series"]["tau2_Nm"].size());
    // the series is sampled (the spec's samples) and ends on the sampled energy there; the
    // printed energy is the quadrature's, within the doubling's 1e-4 of the sampled one
    const json& rows = o["energy_convergence"]["rows"];
    ASSERT_EQ(rows[0]["samples"].get<int>(), j["samples"].get<int>());
    EXPECT_NEAR(o["series"]["energy_J"].back().get<double>(), rows[0]["energy_J"].get<double>(),
                1e-9);
    EXPECT_NEAR(o["series"]["energy_J"].back().get<double>(), o["energy_J"].get<double>(),
                1e-4 * o["energy_J"].get<double>());
    EXPECT_DOUBLE_EQ(o["energy_J"].get<double>(),
                     o["energy_convergence"]["quadrature"]["energy_J"].get<double>());
    EXPECT_LT(o["energy_error_J"].get<double>(), 1e-9 * o["energy_J"].get<double>());
  }
  ASSERT_EQ(j["evaluations"].size(), 4u);
  for (const json& e : j["evaluations"]) {
    for (const char* k : {"program", "configuration", "x_s_m", "phi_deg", "energy_J", "singular",
                          "saving_J", "saving_percent"})
      ASSERT_TRUE(e.contains(k)) << k;
    EXPECT_NEAR(e["phi_deg"].get<double>(), 130.89, 1e-9);
    EXPECT_GE(e["saving_J"].get<double>(), 0.0);
  }
}

TEST(PlacementResultsJson, MapsAreRowsOfEnergiesAndStatusesOnTheNodeGrid) {
  studies::Status status;
  const json j = run_case_file(kCase, &status);
  ASSERT_EQ(j["maps"].size(), 4u);
  for (const json& m : j["maps"]) {
    const size_t nx = m["x_m"].size(), ny = m["y_m"].size();
    EXPECT_EQ(nx, 40u);
    EXPECT_EQ(ny, 25u);
    ASSERT_EQ(m["energy_J_rows"].size(), ny);
    ASSERT_EQ(m["status_rows"].size(), ny);
    size_t feasible = 0;
    for (size_t r = 0; r < ny; ++r) {
      const std::string st = m["status_rows"][r];
      ASSERT_EQ(st.size(), nx);
      std::istringstream in(m["energy_J_rows"][r].get<std::string>());
      std::string tok;
      size_t i = 0;
      while (in >> tok) {
        ASSERT_LT(i, nx);
        // '-' where the line leaves the annulus, and inside the margin where the sampled
        // energy has not converged; an energy at every admissible node
        if (st[i] == '.') {
          EXPECT_EQ(tok, "-") << "row " << r << " col " << i;
        }
        if (st[i] == 'o' || st[i] == 'x') {
          EXPECT_NE(tok, "-") << "row " << r << " col " << i;
        }
        if (st[i] == 'o') {
          ++feasible;
          EXPECT_GE(std::stod(tok), 0.0);
        }
        ++i;
      }
      EXPECT_EQ(i, nx);
    }
    EXPECT_GT(feasible, 0u);
    ASSERT_TRUE(m["optimum_xy_m"].is_array());
  }
  ASSERT_EQ(j["pareto"].size(), 8u);  // two joints per program and configuration
  ASSERT_EQ(j["curves"].size(), 4u);
  EXPECT_EQ(j["curves"][0]["phi_deg"].size(), j["curves"][0]["status"].get<std::string>().size());
}

// results.json and the page of a small case: the optimum's decision, the margin sensitivity,
// a singular evaluation that prints no energy, peak or saving
struct Page {
  json results;
  std::string html;
};

Page run_and_render(const std::string& yaml, const std::string& name) {
  const fs::path dir = fs::temp_directory_path() /
                       ("armstudy_placement_page_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "case.yaml";
  std::ofstream(file) << yaml;
  LoadedCase c = load_case(file.string());
  const studies::Status st = c.run->solve({});
  json j = report::write_record(results_header(c.info, st, c.run->message(), {}));
  j["placement"] = c.run->results();
  fs::create_directories(dir / "out");
  report::write_case_report(dir / "out", c.info, j, c.entry->report, c.entry->answer);
  std::ifstream in(dir / "out" / "index.html");
  std::stringstream html;
  html << in.rdbuf();
  fs::remove_all(dir);
  return {j, html.str()};
}

TEST(PlacementResultsJson, AMarginBoundOptimumSaysSoInResultsAndOnThePage) {
  // 0.5 Lmax: the optimum lies on the inner circle's clearance margin; plus the line tangent
  // to the inner circle (the thesis's printed optimum at Y = 0.2000 m, exactly: to the last
  // digit of a double)
  char tangent[64];
  std::snprintf(tangent, sizeof tangent, "%.17g", 180.0 - std::asin(0.2 / 0.36) * 180 / M_PI);
  const Page p = run_and_render(
      std::string(
          "study: placement\nname: margin-page\nplacement:\n  length_fraction: 0.5\n"
          "  programs: [cycloidal]\n  configurations: [1]\n  nx_s: 16\n  phi_step_deg: 3\n"
          "  map: {nx: 8, ny: 4}\n  evaluate:\n    - {label: tangent, x_s_m: 0.36, phi_deg: ") +
          tangent + "}\n    - {label: outer-start, x_s_m: 0.6, phi_deg: 150}\n",
      "margin");
  const json& pl = p.results["placement"];
  ASSERT_EQ(pl["optima"].size(), 1u);
  const json& o = pl["optima"][0];
  EXPECT_EQ(o["decided_by"]["binding"], "inner_clearance");
  EXPECT_TRUE(o["decided_by"]["set_by_margin"].get<bool>());
  EXPECT_NEAR(o["decided_by"]["inner_slack_m"].get<double>(), 0.0, 1e-9);
  EXPECT_TRUE(o["refinement"]["converged"].get<bool>());
  EXPECT_LE(o["refinement"]["final_tolerance_rel"].get<double>(), 1e-7);
  EXPECT_FALSE(o["refinement"]["method"].get<std::string>().empty());
  EXPECT_TRUE(o["energy_convergence"]["converged"].get<bool>());
  ASSERT_GE(o["margin_sensitivity"].size(), 5u);
  double last = 0;
  for (const json& m : o["margin_sensitivity"]) {
    ASSERT_TRUE(m["found"].get<bool>());
    EXPECT_GT(m["energy_J"].get<double>(), last) << m["margin_m"];  // falls as the margin shrinks
    last = m["energy_J"].get<double>();
  }
  EXPECT_NE(p.results["message"].get<std::string>().find("set by the 0.0100 m clearance margin"),
            std::string::npos);
  EXPECT_NE(p.html.find("is set by the 0.01 m clearance margin to the inner circle"),
            std::string::npos);
  EXPECT_NE(p.html.find("Margin sensitivity"), std::string::npos);
  // the tangent line: the elbow folds at its middle; its energy (the limit of the lines just
  // outside, with the reversal's jump term) is printed with its error, its peak torque is an
  // impulse and withheld, and the note says why
  ASSERT_EQ(pl["evaluations"].size(), 2u);
  const json& e = pl["evaluations"][0];
  EXPECT_TRUE(e["singular_trajectory"].get<bool>());
  ASSERT_TRUE(e["energy_J"].is_number());
  EXPECT_NEAR(e["energy_J"].get<double>(), 36.0426863, 1e-6);  // PlacementQuadrature's fold test
  EXPECT_LT(e["energy_error_J"].get<double>(), 1e-6);
  EXPECT_TRUE(e["peak_torque_Nm"].is_null());
  EXPECT_EQ(e["note"], studies::placement::kFoldedElbowNote);
  // the evaluations table's row (the case table above it lists the label too)
  const size_t row = p.html.rfind("<tr><td>tangent</td>");
  ASSERT_NE(row, std::string::npos);
  const std::string tr = p.html.substr(row, p.html.find("</tr>", row) - row);
  EXPECT_NE(tr.find("36.0427 ±"), std::string::npos) << tr;
  // the line starting on the outer circle (stretched elbow at rest): its energy is finite and
  // printed with its quadrature error, only its peak torque is withheld; it has a saving
  const json& o2 = pl["evaluations"][1];
  EXPECT_TRUE(o2["singular_trajectory"].get<bool>());
  ASSERT_TRUE(o2["energy_J"].is_number());
  ASSERT_TRUE(o2["energy_error_J"].is_number());
  EXPECT_LT(o2["energy_error_J"].get<double>(), 1e-9 * o2["energy_J"].get<double>());
  EXPECT_GT(o2["energy_error_J"].get<double>(), 0.0);
  EXPECT_TRUE(o2["peak_torque_Nm"].is_null());
  EXPECT_TRUE(o2["saving_J"].is_number());
  EXPECT_EQ(o2["note"], "peak torque unbounded (singular pose)");
  EXPECT_TRUE(o2["energy_convergence"]["quadrature"]["converged"].get<bool>());
  EXPECT_FALSE(o2["energy_convergence"]["peak_converged"].get<bool>());
  const size_t row2 = p.html.rfind("<tr><td>outer-start</td>");
  ASSERT_NE(row2, std::string::npos);
  const std::string tr2 = p.html.substr(row2, p.html.find("</tr>", row2) - row2);
  EXPECT_NE(tr2.find(" ± "), std::string::npos) << tr2;
  EXPECT_EQ(tr2.find("none (singular)"), std::string::npos) << tr2;
  // the Pareto fronts hold admissible placements only
  for (const json& f : pl["pareto"])
    for (const json& sg : f["singular"]) EXPECT_FALSE(sg.get<bool>());
}

TEST(PlacementResultsJson, AnInteriorOptimumSaysInterior) {
  const Page p = run_and_render(
      "study: placement\nname: interior-page\nplacement:\n  length_fraction: 0.2\n"
      "  programs: [poly345]\n  configurations: [2]\n  nx_s: 16\n  phi_step_deg: 3\n"
      "  map: {nx: 8, ny: 4}\n",
      "interior");
  const json& o = p.results["placement"]["optima"].at(0);
  EXPECT_EQ(o["decided_by"]["binding"], "interior");
  EXPECT_FALSE(o["decided_by"]["set_by_margin"].get<bool>());
  EXPECT_TRUE(o["margin_sensitivity"].empty());
  EXPECT_NE(p.results["message"].get<std::string>().find("interior: no constraint binds"),
            std::string::npos);
  EXPECT_NE(p.html.find("interior (clearances exceed the margin by"), std::string::npos);
  EXPECT_EQ(p.html.find("Margin sensitivity"), std::string::npos);
}

}  // namespace
}  // namespace armstudy::app
