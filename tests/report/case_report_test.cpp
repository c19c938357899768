#include "report/case_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "report/study_sections.hpp"

namespace armstudy::report {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("armstudy_case_report_test_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
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

// a results.json as run_case writes it, with a time series of two owners
json synthetic_results(const cases::CaseInfo& info) {
  json j;
  j["schema_version"] = 1;
  j["armstudy_version"] = "0.1.0";
  j["git_commit"] = "0123456789ab";
  j["study"] = info.study;
  j["case"] = {{"name", info.name}, {"path", info.path}, {"sha256", info.sha256}};
  j["status"] = "solved";
  j["message"] = "optimum <found> & checked";
  j["checks"] = json::array({{{"name", "work_energy"},
                               {"description", "signed work equals ΔE < 1e-9"},
                               {"value", 1e-12},
                               {"tolerance", 1e-9},
                               {"passed", true}}});
  j["key_figures"] = json::array({{{"name", "energy_J"}, {"value", 12.5}, {"unit", "J"}}});
  json section;
  section["lmax_m"] = 1.131;
  json optima = json::array();
  for (int conf = 1; conf <= 2; ++conf) {
    json o = {{"program", "cycloidal"}, {"configuration", conf}, {"energy_J", 10.0 + conf}};
    json series;
    for (int i = 0; i <= 50; ++i) {
      const double t = i * 0.02;
      series["t_s"].push_back(t);
      series["q_rad"].push_back({std::sin(t * conf), std::cos(t)});
      series["power_W"].push_back({t * conf, -t});
    }
    o["series"] = series;
    optima.push_back(o);
  }
  section["optima"] = optima;
  j[info.study] = section;
  j["frames"] = json::array();
  return j;
}

std::vector<std::string> attribute_targets(const std::string& html) {
  std::vector<std::string> out;
  static const std::regex re(R"re((?:src|href)="([^"#]+)")re");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), re); it != std::sregex_iterator(); ++it)
    out.push_back((*it)[1]);
  return out;
}

TEST(CaseReport, EveryValueIsHtmlEscaped) {
  const auto info = hostile_info("placement");
  const fs::path d = fresh_dir("escape");
  write_case_report(d, info, synthetic_results(info));
  const std::string html = slurp(d / "index.html");
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<b>bold"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(&apos;x&apos;)&lt;/script&gt; &amp; more"), std::string::npos);
  EXPECT_NE(html.find("optimum &lt;found&gt; &amp; checked"), std::string::npos);
}

TEST(CaseReport, PageForbidsNetworkFetchesWithContentSecurityPolicy) {
  const auto info = hostile_info("pendulum");
  const fs::path d = fresh_dir("csp");
  write_case_report(d, info, synthetic_results(info));
  const std::string html = slurp(d / "index.html");
  const auto csp = html.find("http-equiv=\"Content-Security-Policy\"");
  ASSERT_NE(csp, std::string::npos);
  EXPECT_NE(html.find("default-src 'none'", csp), std::string::npos);
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
}

TEST(CaseReport, EveryLinkedFileExistsBesideThePage) {
  for (const std::string study : {"placement", "pendulum", "throwing", "time_optimal"}) {
    const auto info = hostile_info(study);
    const fs::path d = fresh_dir("links_" + study);
    write_case_report(d, info, synthetic_results(info));
    std::ofstream(d / "results.json") << synthetic_results(info).dump();
    const std::string html = slurp(d / "index.html");
    int images = 0;
    for (const auto& t : attribute_targets(html)) {
      if (t == "../index.html") continue;  // the page of all cases, written after the run
      EXPECT_TRUE(fs::exists(d / t)) << study << ": " << t;
      images += t.ends_with(".svg");
    }
    // both owners' angle and power series are plotted
    EXPECT_GE(images, 2) << study;
  }
}

TEST(CaseReport, IndexListsEveryCaseFolderWithItsKeyFigures) {
  const fs::path out = fresh_dir("index");
  for (const std::string study : {"placement", "time_optimal"}) {
    const auto info = hostile_info(study);
    fs::create_directories(out / info.name);
    const json r = synthetic_results(info);
    std::ofstream(out / info.name / "results.json") << r.dump();
    write_case_report(out / info.name, info, r);
  }
  fs::create_directories(out / ".hidden-tmp");
  std::ofstream(out / ".hidden-tmp" / "results.json") << "{}";
  EXPECT_EQ(write_index(out), 2);
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
    EXPECT_NE(std::string(e.what()).find("apt-get install chromium"), std::string::npos) << e.what();
  }
  unsetenv("ARMSTUDY_CHROMIUM");
  EXPECT_FALSE(fs::exists(d / "a.pdf"));
}

}  // namespace
}  // namespace armstudy::report
