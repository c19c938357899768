// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Numbers in results.json: every double is written in the shortest form that reads back
// to the same double, so a figure can be re-checked from the file (a key figure equals the
// study section's number bit for bit; the time-optimal duration follows from the written
// nodes), and two runs of a case write the same bytes apart from the run times.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/json_numbers.hpp"
#include "testing/files.hpp"

namespace {
namespace fs = std::filesystem;
using nlohmann::json;

// small cases of every study, seconds each; run twice by the fixture
const std::vector<std::pair<std::string, std::string>> kNumberCases = {
    {"numbers-pendulum", "study: pendulum\nname: numbers-pendulum\npendulum: {duration_s: 0.4}\n"},
    {"numbers-placement",
     "study: placement\nname: numbers-placement\nplacement:\n  length_fraction: 0.4\n"
     "  nx_s: 6\n  phi_step_deg: 6\n  samples: 51\n  map: {nx: 12, ny: 6}\n"},
    {"numbers-throwing",
     "study: throwing\nname: numbers-throwing\nthrowing:\n"
     "  motors: {power_max_W: 1000, current_max_A: 100}\n"
     "  constraints: {release_tolerance_deg: 30}\n"
     "  idp: {stages: 4, steps_per_stage: 20, iterations: 2, max_passes: 1, candidates: 3, "
     "seeds: 1}\n"
     "  nlopt: {max_evaluations: 3}\n  checks: {allow_not_converged: true}\n"},
    {"numbers-time-optimal",
     "study: time_optimal\nname: numbers-time-optimal\ntime_optimal:\n"
     "  path: {kind: line, points_m: [[0.3, 0.1], [-0.1, 0.8]]}\n"
     "  dp: {segments: 10, levels: 40, states: [path_speed, joint1_velocity], "
     "convergence_segments: []}\n"
     "  complex: {max_iterations: 400}\n  exact: {grid_points: 200}\n"},
};

int run_quiet(const std::string& args) {
  const std::string cmd = std::string(ARMSTUDY_BINARY) + " " + args + " >/dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// run times: the only values that may differ between two runs of a case
bool is_run_time(const std::string& key) {
  return key == "solve_seconds" || key.find("run_time") != std::string::npos;
}

// the JSON with every run time set to null, and the size and hash of the report page,
// which prints the run times
json without_run_times(json j) {
  if (j.is_object()) {
    const bool key_figure = j.contains("name") && j["name"].is_string() && j.contains("value");
    if (key_figure && is_run_time(j["name"].get<std::string>())) j["value"] = nullptr;
    if (j.contains("path") && j["path"] == "index.html" && j.contains("sha256"))
      j["sha256"] = j["bytes"] = nullptr;
    for (auto it = j.begin(); it != j.end(); ++it)
      it.value() = is_run_time(it.key()) ? json(nullptr) : without_run_times(it.value());
  } else if (j.is_array()) {
    for (auto& v : j) v = without_run_times(v);
  }
  return j;
}

double key_figure(const json& results, const std::string& name) {
  for (const json& k : results.at("key_figures"))
    if (k.at("name") == name) return k.at("value").get<double>();
  ADD_FAILURE() << "no key figure " << name;
  return std::numeric_limits<double>::quiet_NaN();
}

uint64_t bits(double v) { return std::bit_cast<uint64_t>(v); }

class ResultsNumbers : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = armstudy::testing::fresh_dir("results_numbers_" + std::to_string(getpid()));
    std::string paths;
    for (const auto& [name, text] : kNumberCases) {
      std::ofstream(root_ / (name + ".yaml")) << text;
      paths += " " + (root_ / (name + ".yaml")).string();
    }
    // two separate runs, each case in its own process, as a user would run them
    for (const char* out : {"a", "b"})
      run_quiet("run" + paths + " --no-render --jobs 1 --out " + (root_ / out).string());
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }

  static json results(const char* run, const std::string& name) {
    const std::string text = armstudy::testing::slurp(root_ / run / name / "results.json");
    EXPECT_FALSE(text.empty()) << "no results.json for " << name << " in run " << run;
    return text.empty() ? json::object() : json::parse(text);
  }
  static fs::path root_;
};
fs::path ResultsNumbers::root_;

// significant digits of a number's text ("100.0" and "1e+02" have 1)
size_t significant_digits(const std::string& text) {
  std::string d;
  for (char c : text.substr(0, text.find_first_of("eE")))
    if (std::isdigit(static_cast<unsigned char>(c))) d += c;
  const size_t first = d.find_first_not_of('0');
  if (first == std::string::npos) return 1;
  return d.find_last_not_of('0') - first + 1;
}

// a number's text with every digit replaced by 'd', e.g. "-d.ddde+dd"
std::string shape(std::string text) {
  for (char& c : text)
    if (std::isdigit(static_cast<unsigned char>(c))) c = 'd';
  return text;
}

TEST(ResultsNumbersFormat, EveryFiniteDoubleReadsBackBitIdenticalInItsShortestForm) {
  std::vector<double> values = {0.0,
                                -0.0,
                                0.1,
                                1.0 / 3,
                                2.0 / 3,
                                1e-300,
                                5e-324,
                                1e308,
                                1e15,
                                1e-5,
                                1e-4,
                                123456789012345.0,
                                1.55262,
                                100.0,
                                -2.5e-7,
                                std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::min(),
                                std::numeric_limits<double>::denorm_min(),
                                std::numeric_limits<double>::epsilon(),
                                13 * M_PI / 36,
                                -7 * M_PI / 24,
                                9.81,
                                0.046,
                                7.9e-5,
                                123456789.123456789};
  std::mt19937_64 rng(20261201);
  while (values.size() < 100000) {
    const double v = std::bit_cast<double>(rng());  // every exponent and mantissa
    if (std::isfinite(v)) values.push_back(v);
  }
  std::uniform_real_distribution<double> physical(-10, 10);  // typical magnitudes too
  for (int i = 0; i < 100000; ++i) values.push_back(physical(rng) * std::pow(10.0, i % 9 - 4));
  json doc = json::array();
  size_t grisu_longer = 0;
  for (double v : values) {
    const std::string s = armstudy::app::shortest_number(v);
    // reads back to the same double, through nlohmann-json as every reader of the file does
    ASSERT_EQ(bits(json::parse(s).get<double>()), bits(v)) << s;
    // as short as the shortest round-trip digits std::to_chars gives
    char buf[40];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
    ASSERT_EQ(significant_digits(s), significant_digits(std::string(buf, r.ptr))) << s;
    // laid out as nlohmann-json lays it out wherever Grisu2 found a shortest form too (the
    // last digit may differ: std::to_chars takes the closest of several shortest forms)
    const std::string grisu = json(v).dump();
    if (significant_digits(grisu) == significant_digits(s))
      ASSERT_EQ(shape(s), shape(grisu)) << s << " vs " << grisu;
    else
      ++grisu_longer;
    doc.push_back(armstudy::app::json_number(v));
  }
  EXPECT_LT(grisu_longer, values.size() / 100);  // rare, and results_text fixes them
  // the file writer: every number of a document reads back bit-identical
  const json back = json::parse(armstudy::app::results_text(doc));
  ASSERT_EQ(back.size(), values.size());
  for (size_t i = 0; i < values.size(); ++i)
    ASSERT_EQ(bits(back[i].get<double>()), bits(values[i])) << i;
  EXPECT_EQ(armstudy::app::shortest_number(1.55262), "1.55262");
  EXPECT_EQ(armstudy::app::shortest_number(2.0), "2.0");
  EXPECT_EQ(armstudy::app::shortest_number(1e-5), "1e-05");
  EXPECT_EQ(armstudy::app::shortest_number(1.0 / 3), "0.3333333333333333");
  // strings and integers pass through unchanged; non-finite numbers are null
  EXPECT_EQ(armstudy::app::results_text(json{{"a", "1.5526199999999999"}, {"n", 7}}),
            "{\n  \"a\": \"1.5526199999999999\",\n  \"n\": 7\n}\n");
  for (double v : {std::nan(""), HUGE_VAL, -HUGE_VAL})
    EXPECT_TRUE(armstudy::app::json_number(v).is_null()) << v;
}

TEST_F(ResultsNumbers, KeyFiguresEqualTheStudySectionBitForBit) {
  // key figures were always written in full; the study sections used to be rounded
  const json p = results("a", "numbers-pendulum");
  ASSERT_TRUE(p.contains("pendulum"));
  EXPECT_EQ(bits(key_figure(p, "energy_exchanged_J")),
            bits(p["pendulum"]["energy"]["scale_J"].get<double>()));
  EXPECT_EQ(bits(key_figure(p, "energy_drift_relative")),
            bits(p["pendulum"]["energy"]["drift_relative"].get<double>()));

  const json t = results("a", "numbers-throwing");
  ASSERT_TRUE(t.contains("throwing"));
  EXPECT_EQ(bits(key_figure(t, "energy_eq8_J")),
            bits(t["throwing"]["energy_initial_J"].get<double>()));
  EXPECT_EQ(bits(key_figure(t, "energy_J")),
            bits(t["throwing"]["energy_optimised_J"].get<double>()));
  EXPECT_EQ(bits(key_figure(t, "energy_idp_J")),
            bits(t["throwing"]["optimum"]["energy_J"].get<double>()));
  EXPECT_EQ(bits(key_figure(t, "saving_percent")),
            bits(t["throwing"]["saving_percent"].get<double>()));
  EXPECT_EQ(bits(key_figure(t, "replay_error_rad")),
            bits(t["throwing"]["replay"]["max_error_rad"].get<double>()));

  const json l = results("a", "numbers-placement");
  ASSERT_TRUE(l.contains("placement"));
  double least = HUGE_VAL;
  for (const json& o : l["placement"]["optima"])
    least = std::min(least, o["energy_J"].get<double>());
  EXPECT_EQ(bits(key_figure(l, "min_energy_J")), bits(least));

  const json o = results("a", "numbers-time-optimal");
  ASSERT_TRUE(o.contains("time_optimal"));
  const json& exact = o["time_optimal"]["solvers"][0];
  ASSERT_EQ(exact["name"], "exact");
  EXPECT_EQ(bits(key_figure(o, "duration_s[exact]")), bits(exact["duration_s"].get<double>()));
  EXPECT_EQ(bits(key_figure(o, "path_length_m")),
            bits(o["time_optimal"]["path_length"].get<double>()));
}

TEST_F(ResultsNumbers, TimeOptimalDurationFollowsFromTheWrittenNodes) {
  // constant s'' per interval: dt = 2 ds / (s'_k + s'_k+1); from rounded nodes this was
  // ~1e-7 s off, from the full doubles it agrees to roundoff
  const json o = results("a", "numbers-time-optimal");
  ASSERT_TRUE(o.contains("time_optimal"));
  for (const json& s : o["time_optimal"]["solvers"]) {
    if (!s["solved"].get<bool>() || s["name"] == "dp_joint1") continue;  // q1'' law, not s''
    const auto ns = s["node_s"].get<std::vector<double>>();
    const auto sd = s["node_sd"].get<std::vector<double>>();
    ASSERT_EQ(ns.size(), sd.size());
    double t = 0;
    for (size_t k = 0; k + 1 < ns.size(); ++k) t += 2 * (ns[k + 1] - ns[k]) / (sd[k] + sd[k + 1]);
    const double d = s["duration_s"].get<double>();
    EXPECT_NEAR(t, d, 1e-12 * d) << s["name"];
  }
}

TEST_F(ResultsNumbers, TwoRunsWriteTheSameBytesApartFromRunTimes) {
  for (const auto& [name, text] : kNumberCases) {
    SCOPED_TRACE(name);
    const std::string a = armstudy::testing::slurp(root_ / "a" / name / "results.json");
    const std::string b = armstudy::testing::slurp(root_ / "b" / name / "results.json");
    ASSERT_FALSE(a.empty());
    ASSERT_FALSE(b.empty());
    // the file is exactly the parsed document written again: comparing the documents with
    // the run times removed compares the bytes
    const json ja = json::parse(a), jb = json::parse(b);
    EXPECT_EQ(a, armstudy::app::results_text(ja));
    EXPECT_EQ(b, armstudy::app::results_text(jb));
    const json ca = without_run_times(ja), cb = without_run_times(jb);
    if (ca != cb) {
      const json patch = json::diff(ca, cb);
      ADD_FAILURE() << "results.json differs between two runs beyond run times: "
                    << patch.dump(1).substr(0, 4000);
    }
  }
}

}  // namespace
