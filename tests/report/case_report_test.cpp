// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/case_report.hpp"

#include <gtest/gtest.h>

#include "testing/files.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "app/pipeline.hpp"
#include "report/results_fields.hpp"
#include "report/results_record.hpp"
#include "report/study_sections.hpp"
#include "studies/pendulum/study_results.hpp"
#include "studies/placement/study_results.hpp"
#include "studies/throwing/study_results.hpp"
#include "studies/time_optimal/study_results.hpp"

namespace armstudy::report {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

using armstudy::testing::slurp;

// the study's report sections and answer-box lines, from its registry record
StudySections sections_of(const cases::CaseInfo& info) {
  return app::find_study(info.study)->report;
}
StudyAnswer answer_of(const cases::CaseInfo& info) { return app::find_study(info.study)->answer; }

fs::path fresh_dir(const std::string& name) {
  return armstudy::testing::fresh_dir("case_report_test_" + name);
}

cases::CaseInfo hostile_info(const std::string& study) {
  cases::CaseInfo info;
  info.name = "hostile-" + study;
  info.study = study;
  info.description = "a <b>bold</b> & 'quoted' \"description\"";
  info.path = "cases/hostile.yaml";
  info.sha256 = std::string(64, 'a');
  info.yaml = "name: hostile\nstudy: " + study +
              "\ndescription: \"<script>alert('x')</script> & more\"\narm:\n  links:\n"
              "    - {length_m: 0.4, mass_kg: 4}\n    - {length_m: 0.2, mass_kg: 2}\n";
  return info;
}

// the study's section as its pipeline writes it: the typed results
// (src/studies/<study>/study_results.hpp), partly filled
json study_section(const std::string& study) {
  std::vector<double> ts;
  for (int i = 0; i <= 40; ++i) ts.push_back(i / 40.0);
  auto s1 = [&](double a) {
    std::vector<double> v;
    for (double t : ts) v.push_back(std::sin(a * t));
    return v;
  };
  auto s2 = [&](double a) {
    std::vector<std::array<double, 2>> v;
    for (double t : ts) v.push_back({std::sin(a * t), std::cos(a * t)});
    return v;
  };
  auto rows2 = [&](double a) {  // one row per joint
    return std::vector<std::vector<double>>{s1(a), s1(a + 1)};
  };
  auto s4 = [&](double a) {
    std::vector<std::vector<double>> v;
    for (double t : ts) v.push_back({0.0, 0.0, std::sin(a * t), 0.3 * std::cos(a * t)});
    return v;
  };
  if (study == "placement") {
    studies::placement::StudyResults s;
    s.length_m = 0.5;
    s.annulus_m = {0.2, 0.6};
    for (int conf = 1; conf <= 2; ++conf) {
      const studies::placement::StudyResults::Id id{"cycloidal", conf};
      studies::placement::StudyResults::Optimum o;
      static_cast<studies::placement::StudyResults::Id&>(o) = id;
      o.energy_J = 10.0 + conf;
      o.root_xy_m = {0.25, 0.3};
      o.series = {1,     ts,    s1(conf), s1(2), s1(3),  s1(4), s1(5),
                  s1(6), s1(7), s1(8),    s1(9), s1(10), s1(1)};
      s.optima.push_back(o);
      studies::placement::StudyResults::Curve c;
      static_cast<studies::placement::StudyResults::Id&>(c) = id;
      c.x_s_m = 0.5;
      c.phi_deg = {100, 110, 120, 130};
      c.energy_J = {12.0, 11.0, NAN, 13.0};
      c.status = "os.o";
      s.curves.push_back(c);
      studies::placement::StudyResults::Map m;
      static_cast<studies::placement::StudyResults::Id&>(m) = id;
      m.x_m = {0.0, 0.1, 0.2, 0.3, 0.4};
      m.y_m = {0.0, 0.1, 0.2};
      m.energy_J_rows = {"- - - - -", "3 2.5 2 2.5 3", "4 3 2.2 3 4"};
      m.status_rows = {".....", "soooo", "ooxoo"};
      m.optimum_xy_m = std::array<double, 2>{0.2, 0.1};
      s.maps.push_back(m);
      studies::placement::StudyResults::Pareto pr;
      static_cast<studies::placement::StudyResults::Id&>(pr) = id;
      pr.joint = 1;
      pr.peak_torque_Nm = {{5, 1}, {7, 1.5}, {9, 2}};
      pr.energy_J = {14, 12, 11};
      pr.x_s_m = {0.3, 0.35, 0.4};
      pr.phi_deg = {100, 110, 120};
      pr.singular = {false, false, false};
      s.pareto.push_back(pr);
    }
    return to_json(s);
  }
  if (study == "pendulum") {
    studies::PendulumStudyResults s;
    s.series = {ts, s4(3), s4(4), s1(2), s1(3), s1(0), s2(1), s2(2), std::nullopt};
    s.snapshots.push_back({0.0, 0, {0, 0, -1.5, -0.6}, {0.1, -0.1}});
    s.energy.initial_J = -0.2;
    s.energy.drift_J = 1e-13;
    return to_json(s);
  }
  if (study == "throwing") {
    using TS = studies::ThrowingStudyResults;
    TS s;
    auto rows = [](const std::vector<std::array<double, 2>>& v) {
      TS::Rows r;
      for (const auto& x : v) r.push_back({x[0], x[1]});
      return r;
    };
    s.run = TS::Optimised{};  // not emplace(): clang 14 (the sanitizer build) refuses it
    TS::Optimised& o = *s.run;
    for (TS::Motion* m : {&o.initial, &o.optimum}) {
      m->energy_J = 20.0;
      m->series.t_s = ts;
      m->series.q_rad = s4(5);
      m->series.voltage_V = rows(s2(6));
      m->series.current_A = rows(s2(7));
      m->series.torque_Nm = rows(s2(8));
      m->series.power_W = rows(s2(9));
      m->series.ball_xy_m = rows(s2(1));
    }
    s.limits.voltage_max_V = 24;
    s.limits.current_max_A = 5;
    s.limits.theta4_limit_rad = {-1, 1};
    o.idp.convergence = {{1, 1, 21, 0, {}, 0, 0}, {2, 1, 20, 0, {}, 0, 0}};
    return to_json(s);
  }
  studies::time_optimal::StudyResults s;
  for (const char* name : {"exact", "dp", "complex"}) {
    studies::time_optimal::StudyResults::Solver v;
    v.name = name;
    v.solved = true;
    v.duration_s = 1.5;
    v.samples = studies::time_optimal::StudyResults::Samples{};
    v.samples->t_s = ts;
    v.samples->s = ts;
    v.samples->sd = s1(1);
    v.samples->tau_Nm = rows2(1);
    v.samples->qd_rad_s = rows2(2);
    s.solvers.push_back(v);
  }
  s.mvc.s = ts;
  s.mvc.sd = s1(0.5);
  s.limits.torque_Nm = {10, 4};
  s.limits.velocity_rad_s = {3, 4};
  return to_json(s);
}

// a results.json as run_case writes it: the shared record and the study's section
json synthetic_results(const cases::CaseInfo& info) {
  ResultsRecord r;
  r.armstudy_version = "0.1.0";
  r.git_commit = "0123456789ab";
  r.study = info.study;
  r.case_info.name = info.name;
  r.case_info.path = info.path;
  r.case_info.sha256 = info.sha256;
  r.provenance = {"0.1.0", "0123456789ab", "2.2.2", "a compiler", "a CPU", {}, {}, {}};
  r.status = "solved";
  r.message = "optimum <found> & checked";
  r.checks = {{"work_energy", "signed work equals ΔE < 1e-9", 1e-12, 1e-9, true}};
  r.key_figures = {{"energy_J", 12.5, "J", "energy"}};
  json j = write_record(r);
  j[info.study] = study_section(info.study);
  return j;
}

std::vector<std::string> attribute_targets(const std::string& html) {
  std::vector<std::string> out;
  static const std::regex re(R"re((?:src|href)="([^"#]+)")re");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), re); it != std::sregex_iterator();
       ++it)
    out.push_back((*it)[1]);
  return out;
}

TEST(CaseReport, EveryValueIsHtmlEscaped) {
  const auto info = hostile_info("placement");
  const fs::path d = fresh_dir("escape");
  write_case_report(d, info, synthetic_results(info), sections_of(info), answer_of(info));
  const std::string html = slurp(d / "index.html");
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<b>bold"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(&apos;x&apos;)&lt;/script&gt; &amp; more"),
            std::string::npos);
  EXPECT_NE(html.find("optimum &lt;found&gt; &amp; checked"), std::string::npos);
}

// a description written "\e]0;title\a\e[31m" (YAML's escapes) landed raw in the page
TEST(CaseReport, ControlCharactersOfADescriptionAreShownAsTextNotWrittenRaw) {
  auto info = hostile_info("placement");
  info.description = "red \x1b[31m bell \x07 tab\tend";
  const fs::path d = fresh_dir("control_escape");
  write_case_report(d, info, synthetic_results(info), sections_of(info), answer_of(info));
  const std::string html = slurp(d / "index.html");
  EXPECT_EQ(html.find('\x1b'), std::string::npos);
  EXPECT_EQ(html.find('\x07'), std::string::npos);
  EXPECT_NE(html.find("red \\x1B[31m bell \\x07 tab\tend"), std::string::npos);
}

TEST(CaseReport, PageForbidsNetworkFetchesWithContentSecurityPolicy) {
  const auto info = hostile_info("pendulum");
  const fs::path d = fresh_dir("csp");
  write_case_report(d, info, synthetic_results(info), sections_of(info), answer_of(info));
  const std::string html = slurp(d / "index.html");
  const auto csp = html.find("http-equiv=\"Content-Security-Policy\"");
  ASSERT_NE(csp, std::string::npos);
  EXPECT_NE(html.find("default-src 'none'", csp), std::string::npos);
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
}

TEST(CaseReport, EachStudyDrawsItsFiguresAndEveryLinkedFileExists) {
  // figures the issue asks for: placement 5 time series + energy, energy over phi, one map per
  // program and configuration, root loci, pareto; pendulum energies, drift, angles, rates,
  // path; throwing voltages, currents, torques, powers, theta4, theta3, locus, idp convergence;
  // time-optimal phase plane, torque and velocity of each joint
  const std::map<std::string, int> expected = {
      {"placement", 6 + 1 + 2 + 1 + 1}, {"pendulum", 5}, {"throwing", 8}, {"time_optimal", 5}};
  for (const auto& [study, figures] : expected) {
    const auto info = hostile_info(study);
    const fs::path d = fresh_dir("links_" + study);
    write_case_report(d, info, synthetic_results(info), sections_of(info), answer_of(info));
    std::ofstream(d / "results.json") << synthetic_results(info).dump();
    const std::string html = slurp(d / "index.html");
    int images = 0;
    for (const auto& t : attribute_targets(html)) {
      if (t == "../index.html") continue;  // the page of all cases, written after the run
      EXPECT_TRUE(fs::exists(d / t)) << study << ": " << t;
      images += t.ends_with(".svg");
    }
    EXPECT_GE(images, figures) << study;
  }
}

TEST(CaseReport, IndexListsEveryCaseFolderWithItsKeyFigures) {
  const fs::path out = fresh_dir("index");
  for (const std::string study : {"placement", "time_optimal"}) {
    const auto info = hostile_info(study);
    fs::create_directories(out / info.name);
    const json r = synthetic_results(info);
    std::ofstream(out / info.name / "results.json") << r.dump();
    write_case_report(out / info.name, info, r, sections_of(info), answer_of(info));
  }
  fs::create_directories(out / ".hidden-tmp");
  std::ofstream(out / ".hidden-tmp" / "results.json") << "{}";
  EXPECT_EQ(write_index(out, app::index_studies()), 2);
  const std::string html = slurp(out / "index.html");
  EXPECT_NE(html.find("href=\"hostile-placement/index.html\""), std::string::npos);
  EXPECT_NE(html.find("href=\"hostile-time_optimal/index.html\""), std::string::npos);
  EXPECT_NE(html.find("12.5 J"), std::string::npos);
  EXPECT_EQ(html.find("hidden-tmp"), std::string::npos);
  for (const auto& t : attribute_targets(html)) EXPECT_TRUE(fs::exists(out / t)) << t;
}

TEST(CaseReport, LabelsCarryTheUnitOfTheKey) {
  EXPECT_EQ(label_from_key("energy_J"), "energy (J)");
  EXPECT_EQ(label_from_key("qd_rad_s"), "joint velocity (rad/s)");
  EXPECT_EQ(label_from_key("tau_Nm"), "joint torque (N m)");
  EXPECT_EQ(label_from_key("phi_deg"), "phi (deg)");
  EXPECT_EQ(label_from_key("count"), "count");
}

TEST(Pdf, MissingChromiumIsAClearError) {
  const fs::path d = fresh_dir("nochrome");
  std::ofstream(d / "a.html") << "<html><body>x</body></html>";
  setenv("ARMSTUDY_CHROMIUM", (d / "no-such-browser").c_str(), 1);
  try {
    print_pdf(d / "a.html", d / "a.pdf");
    FAIL() << "expected PdfError";
  } catch (const PdfError& e) {
    EXPECT_NE(std::string(e.what()).find("apt-get install chromium"), std::string::npos)
        << e.what();
  }
  unsetenv("ARMSTUDY_CHROMIUM");
  EXPECT_FALSE(fs::exists(d / "a.pdf"));
}

TEST(CaseReport, UndrawableDataCostsTheFigureNotTheReport) {
  auto info = hostile_info("pendulum");
  json r = synthetic_results(info);
  // every kinetic energy unknown: that plot has nothing finite on one curve, the page stays
  for (auto& v : r["pendulum"]["series"]["q_rad"])
    v = json::array({nullptr, nullptr, nullptr, nullptr});
  for (auto& v : r["pendulum"]["series"]["qd_rad_s"])
    v = json::array({nullptr, nullptr, nullptr, nullptr});
  const fs::path d = fresh_dir("undrawable");
  ASSERT_NO_THROW(write_case_report(d, info, r, sections_of(info), answer_of(info)));
  const std::string html = slurp(d / "index.html");
  EXPECT_NE(html.find("could not be drawn"), std::string::npos);
  EXPECT_NE(html.find("fig01_energies.svg"), std::string::npos);
}

}  // namespace
}  // namespace armstudy::report
