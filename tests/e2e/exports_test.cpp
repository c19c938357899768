// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The files a case folder holds for other tools, end to end through the CLI: model.xml and
// one motion CSV per solver, each named in results.json "exports", listed under "files"
// with its size and sha256; the CSVs parse, their header names every column with its unit
// and their numbers are results.json's, digit for digit; model.xml loads in MuJoCo with one
// keyframe per strip frame.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cases/case_info.hpp"
#include "scene/mujoco_model.hpp"
#include "testing/cli.hpp"
#include "testing/files.hpp"

namespace {
namespace fs = std::filesystem;
using armstudy::testing::run_cli;
using nlohmann::json;

using armstudy::testing::slurp;

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> columns;
};

// a plain CSV: one header row, then numbers (strtod must read every field whole)
Csv parse_csv(const std::string& text) {
  Csv c;
  std::stringstream in(text);
  std::string line;
  std::getline(in, line);
  std::stringstream h(line);
  for (std::string f; std::getline(h, f, ',');) c.header.push_back(f);
  c.columns.resize(c.header.size());
  while (std::getline(in, line)) {
    std::stringstream r(line);
    size_t i = 0;
    for (std::string f; std::getline(r, f, ','); ++i) {
      char* end = nullptr;
      const double v = std::strtod(f.c_str(), &end);
      EXPECT_TRUE(!f.empty() && *end == '\0') << "field '" << f << "' of line: " << line;
      if (i < c.columns.size()) c.columns[i].push_back(v);
    }
    EXPECT_EQ(i, c.header.size()) << line;
  }
  return c;
}

const std::vector<double>& column(const Csv& c, const std::string& name) {
  for (size_t i = 0; i < c.header.size(); ++i)
    if (c.header[i] == name) return c.columns[i];
  ADD_FAILURE() << "no column " << name;
  static const std::vector<double> none;
  return none;
}

// every export is a file of the folder, listed under "files" with its size and sha256
void expect_listed(const fs::path& dir, const json& results, const std::string& file) {
  ASSERT_TRUE(fs::exists(dir / file)) << file;
  const std::string bytes = slurp(dir / file);
  bool found = false;
  for (const json& f : results["files"])
    if (f["path"] == file) {
      found = true;
      EXPECT_EQ(f["bytes"].get<size_t>(), bytes.size()) << file;
      EXPECT_EQ(f["sha256"].get<std::string>(), armstudy::cases::sha256_hex(bytes)) << file;
    }
  EXPECT_TRUE(found) << file << " is not under files";
}

// model.xml loads (mj_loadXML) with one keyframe at each of the listed times
void expect_model(const fs::path& dir, const json& entry) {
  const armstudy::scene::MujocoModel mm =
      armstudy::scene::MujocoModel::from_file((dir / "model.xml").string());
  const auto& times = entry["keyframe_times_s"];
  ASSERT_EQ(mm.model()->nkey, static_cast<int>(times.size()));
  for (int k = 0; k < mm.model()->nkey; ++k)
    EXPECT_EQ(mm.model()->key_time[k], times[k].get<double>()) << k;
}

fs::path out_dir(const std::string& name) {
  return fs::temp_directory_path() / ("armstudy_exports_" + name + "_" + std::to_string(getpid()));
}

TEST(Exports, ThreeLinkTimeOptimalFolderHasModelXmlAndOneCsvPerSolverMatchingResultsJson) {
  // the bundled 3-link case on a smaller grid; its DP convergence table keeps the two
  // segment counts its source claim compares (10 and 50)
  const fs::path out = out_dir("to");
  fs::remove_all(out);
  fs::create_directories(out);
  std::string text = slurp(fs::path(ARMSTUDY_SOURCE_DIR) / "reports/cases/time-optimal-3link.yaml");
  for (const auto& [from, to] : std::map<std::string, std::string>{
           {"grid_points: 1000", "grid_points: 300"},
           {"convergence_segments: [10, 20, 50]", "convergence_segments: [10, 50]"}}) {
    const size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  }
  const fs::path yaml = out / "case.yaml";
  std::ofstream(yaml) << text;
  const auto r = run_cli("run --no-render --out " + (out / "out").string() + " " + yaml.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const fs::path dir = out / "out" / "time-optimal-3link";
  const json res = json::parse(slurp(dir / "results.json"));
  const json& ex = res["exports"];
  ASSERT_TRUE(ex.is_array());
  std::map<std::string, json> by_file;
  for (const json& e : ex) by_file[e["file"]] = e;
  ASSERT_EQ(by_file.count("model.xml"), 1u);
  EXPECT_EQ(by_file["model.xml"]["kind"], "mjcf");
  expect_listed(dir, res, "model.xml");
  expect_model(dir, by_file["model.xml"]);

  int csvs = 0;
  for (const json& s : res["time_optimal"]["solvers"]) {
    if (!s["solved"].get<bool>()) continue;
    const std::string file = "motion_" + s["name"].get<std::string>() + ".csv";
    SCOPED_TRACE(file);
    ASSERT_EQ(by_file.count(file), 1u);
    const json& e = by_file[file];
    EXPECT_EQ(e["kind"], "motion_csv");
    EXPECT_EQ(e["motion"], s["name"]);
    expect_listed(dir, res, file);
    const Csv c = parse_csv(slurp(dir / file));
    EXPECT_EQ(json(c.header), e["columns"]);
    const json& sm = s["samples"];
    ASSERT_EQ(c.columns.front().size(), sm["t_s"].size());
    EXPECT_EQ(e["rows"].get<size_t>(), sm["t_s"].size());
    // the numbers are results.json's, digit for digit (both shortest round trip)
    const auto same = [&](const std::string& col, const json& values) {
      const std::vector<double>& v = column(c, col);
      ASSERT_EQ(v.size(), values.size()) << col;
      for (size_t k = 0; k < v.size(); ++k)
        ASSERT_EQ(v[k], values[k].get<double>()) << col << " row " << k;
    };
    same("t [s]", sm["t_s"]);
    same("s [rad]", sm["s"]);
    same("sd [rad/s]", sm["sd"]);
    same("sdd [rad/s^2]", sm["sdd"]);
    for (int j = 0; j < 3; ++j) {
      const std::string n = std::to_string(j + 1);
      same("q" + n + " [rad]", sm["q_rad"][j]);
      same("qd" + n + " [rad/s]", sm["qd_rad_s"][j]);
      same("qdd" + n + " [rad/s^2]", sm["qdd_rad_s2"][j]);
      same("tau" + n + " [N m]", sm["tau_Nm"][j]);
    }
    ++csvs;
  }
  EXPECT_EQ(csvs, 3);  // exact, dp, complex
  EXPECT_EQ(ex.size(), 4u);
  fs::remove_all(out);
}

TEST(Exports, PendulumFolderHasModelXmlAtItsSnapshotsAndItsMotionAsCsv) {
  const fs::path out = out_dir("pendulum");
  fs::remove_all(out);
  const auto r = run_cli("run --no-render --out " + out.string() + " " +
                         (fs::path(ARMSTUDY_SOURCE_DIR) / "reports/cases/pendulum.yaml").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const fs::path dir = out / "pendulum";
  const json res = json::parse(slurp(dir / "results.json"));
  ASSERT_EQ(res["exports"].size(), 2u);
  const json& model = res["exports"][0];
  EXPECT_EQ(model["file"], "model.xml");
  expect_listed(dir, res, "model.xml");
  expect_model(dir, model);
  EXPECT_EQ(model["keyframe_times_s"].size(), res["pendulum"]["snapshots"].size());
  const json& e = res["exports"][1];
  ASSERT_EQ(e["file"], "motion_pendulum.csv");
  expect_listed(dir, res, "motion_pendulum.csv");
  const Csv c = parse_csv(slurp(dir / "motion_pendulum.csv"));
  EXPECT_EQ(json(c.header), e["columns"]);
  const json& series = res["pendulum"]["series"];
  const std::vector<double>& t = column(c, "t [s]");
  ASSERT_EQ(t.size(), series["t_s"].size());
  for (size_t k = 0; k < t.size(); ++k) {
    ASSERT_EQ(t[k], series["t_s"][k].get<double>()) << k;
    for (int j = 0; j < 4; ++j)
      ASSERT_EQ(column(c, "q" + std::to_string(j + 1) + " [rad]")[k],
                series["q_rad"][k][j].get<double>())
          << k;
  }
  fs::remove_all(out);
}

}  // namespace
