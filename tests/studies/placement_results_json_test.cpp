// The "placement" section of results.json as placement_pipeline.cpp documents it, produced by the
// pipeline from a case file (what the report and CI read).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli/pipeline.hpp"

namespace armstudy::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json run_case_file(const std::string& yaml, studies::Status* status) {
  const fs::path dir = fs::temp_directory_path() / ("armstudy_placement_json_" + std::to_string(::getpid()));
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
    EXPECT_TRUE(j["counts"].contains(k)) << k;
  EXPECT_EQ(j["counts"]["total"].get<int>(),
            j["counts"]["unreachable"].get<int>() + j["counts"]["singular"].get<int>() +
                j["counts"]["clear"].get<int>());
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
    EXPECT_NEAR(o["series"]["energy_J"].back().get<double>(), o["energy_J"].get<double>(), 1e-5);
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
        // an energy wherever the line is inside the annulus, '-' where it is not
        EXPECT_EQ(tok == "-", st[i] == '.') << "row " << r << " col " << i;
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

}  // namespace
}  // namespace armstudy::app
