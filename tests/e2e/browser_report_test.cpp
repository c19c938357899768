// Every bundled case's report, opened in a real browser (headless Chromium): the page loads
// with no console message (CSP violations and script errors are console messages), every
// img/link/object target exists on disk, a screenshot is not blank, and report.pdf has at
// least one page per section that starts a new page, none of them blank.
#include <gtest/gtest.h>
#include <png.h>

#include <sys/file.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "testing/browser.hpp"
#include "testing/files.hpp"

namespace {
namespace fs = std::filesystem;

using armstudy::testing::chromium;
using armstudy::testing::file_url;
using armstudy::testing::ink_fraction_png;
using armstudy::testing::quote;
using armstudy::testing::run;
using armstudy::testing::slurp;

// the case names of the bundled case files ("name:" at the top level)
std::vector<std::string> bundled_case_names() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(fs::path(ARMSTUDY_SOURCE_DIR) / "reports/cases")) {
    if (e.path().extension() != ".yaml") continue;
    std::istringstream in(slurp(e.path()));
    std::string line;
    while (std::getline(in, line))
      if (line.rfind("name:", 0) == 0) {
        std::string n = line.substr(5);
        n.erase(0, n.find_first_not_of(" \t\"'"));
        n.erase(n.find_last_not_of(" \t\"'\r") + 1);
        names.push_back(n);
        break;
      }
  }
  std::sort(names.begin(), names.end());
  return names;
}

// share of dark pixels of a binary PGM (P5) page from pdftoppm -gray
double ink_fraction_pgm(const fs::path& pgm) {
  std::ifstream in(pgm, std::ios::binary);
  std::string magic;
  int w = 0, h = 0, maxv = 0;
  in >> magic >> w >> h >> maxv;
  in.get();
  if (magic != "P5" || w <= 0 || h <= 0 || maxv != 255) return -1;
  std::vector<unsigned char> px(static_cast<size_t>(w) * h);
  in.read(reinterpret_cast<char*>(px.data()), static_cast<std::streamsize>(px.size()));
  size_t ink = 0;
  for (unsigned char v : px) ink += v < 200;
  return static_cast<double>(ink) / px.size();
}

// what the shared output was made from: the binary, the case files and the templates
std::string input_stamp() {
  std::ostringstream os;
  auto add = [&](const fs::path& p) {
    os << p.filename().string() << ' '
       << fs::last_write_time(p).time_since_epoch().count() << '\n';
  };
  add(ARMSTUDY_BINARY);
  for (const char* dir : {"reports/cases", "templates"}) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(fs::path(ARMSTUDY_SOURCE_DIR) / dir))
      files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) add(f);
  }
  return os.str();
}

// runs fn(i) for i in [0, n) on two threads (chromium is slow to start, the machine has 2 cores)
template <typename Fn>
void for_each_parallel(size_t n, Fn fn) {
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i = next++; i < n; i = next++) fn(i);
  };
  std::thread other(worker);
  worker();
  other.join();
}

class BrowserReport : public ::testing::Test {
 protected:
  // the run over every bundled case is shared by the tests of this suite (ctest runs each
  // test in its own process): made once per input change, under a file lock
  static void SetUpTestSuite() {
    const fs::path base = fs::path(ARMSTUDY_BINARY).parent_path() / "browser_e2e";
    fs::create_directories(base);
    out_ = base / "out";
    work_ = base / ("work-" + std::to_string(::getpid()));
    fs::remove_all(work_);
    fs::create_directories(work_);
    const int lock = ::open((base / ".lock").c_str(), O_CREAT | O_RDWR, 0644);
    ASSERT_GE(lock, 0);
    ::flock(lock, LOCK_EX);
    const std::string stamp = input_stamp();
    const fs::path stamp_file = base / "stamp", status_file = base / "status";
    if (fs::exists(out_ / "index.html") && slurp(stamp_file) == stamp && fs::exists(status_file)) {
      run_status_ = std::stoi(slurp(status_file));
    } else {
      fs::remove_all(out_);
      fs::remove(stamp_file);
      // every bundled case, with frames and PDFs, as CI runs them
      const std::string cmd = std::string(ARMSTUDY_BINARY) + " run --pdf -j 2 --out " +
                              quote(out_.string()) + " " +
                              quote((fs::path(ARMSTUDY_SOURCE_DIR) / "reports/cases").string()) +
                              " > " + quote((base / "run.log").string()) + " 2>&1";
      run_status_ = run(cmd);
      std::ofstream(status_file) << run_status_;
      std::ofstream(stamp_file) << stamp;
    }
    run_log_ = slurp(base / "run.log");
    ::flock(lock, LOCK_UN);
    ::close(lock);
  }
  static void TearDownTestSuite() { fs::remove_all(work_); }

  // every page: the index and each bundled case's report
  static std::vector<fs::path> pages() {
    std::vector<fs::path> p = {out_ / "index.html"};
    for (const auto& n : bundled_case_names()) p.push_back(out_ / n / "index.html");
    return p;
  }

  static fs::path work_, out_;
  static int run_status_;
  static std::string run_log_;
};
fs::path BrowserReport::work_, BrowserReport::out_;
int BrowserReport::run_status_ = -1;
std::string BrowserReport::run_log_;

TEST_F(BrowserReport, RunWritesEveryBundledCaseReportWithPdfAndTheIndex) {
  // every bundled case ends as it expects (example 1 expects to be unsolvable)
  EXPECT_EQ(run_status_, 0) << run_log_;
  const auto names = bundled_case_names();
  ASSERT_GE(names.size(), 5u) << "the bundled cases are missing";
  EXPECT_TRUE(fs::exists(out_ / "index.html"));
  const std::string index = slurp(out_ / "index.html");
  for (const auto& n : names) {
    EXPECT_TRUE(fs::exists(out_ / n / "index.html")) << n;
    EXPECT_TRUE(fs::exists(out_ / n / "report.pdf")) << n;
    EXPECT_NE(index.find("href=\"" + n + "/index.html\""), std::string::npos) << n;
  }
}

TEST_F(BrowserReport, PagesLoadWithoutConsoleMessagesOrMissingResources) {
  static const std::regex kTarget(R"re(\b(?:src|href|data)="([^"]*)")re");
  const auto all = pages();
  std::vector<int> status(all.size(), -1);
  for_each_parallel(all.size(), [&](size_t k) {
    const fs::path dom = work_ / ("dom" + std::to_string(k) + ".html");
    const fs::path log = work_ / ("console" + std::to_string(k) + ".log");
    status[k] = chromium("--enable-logging=stderr --v=0 --dump-dom " + quote(file_url(all[k])) +
                             " > " + quote(dom.string()) + " 2> " + quote(log.string()),
                         work_, std::to_string(k));
  });
  for (size_t k = 0; k < all.size(); ++k) {
    const fs::path& page = all[k];
    ASSERT_TRUE(fs::exists(page)) << page;
    const fs::path dom = work_ / ("dom" + std::to_string(k) + ".html");
    const fs::path log = work_ / ("console" + std::to_string(k) + ".log");
    ASSERT_EQ(status[k], 0) << page << ": " << slurp(log);
    const std::string html = slurp(dom);
    // the browser built the page (it did not stop at an error page)
    EXPECT_NE(html.find("<h1>"), std::string::npos) << page;
    EXPECT_NE(html.find("Content-Security-Policy"), std::string::npos) << page;
    // console messages: CSP violations, script errors, failed resources
    std::istringstream lines(slurp(log));
    std::string line;
    while (std::getline(lines, line))
      EXPECT_EQ(line.find(":CONSOLE"), std::string::npos) << page << ": " << line;
    // every referenced file exists beside the page; nothing points to the network
    int targets = 0;
    for (auto it = std::sregex_iterator(html.begin(), html.end(), kTarget);
         it != std::sregex_iterator(); ++it) {
      const std::string t = (*it)[1];
      if (t.empty() || t[0] == '#') continue;
      EXPECT_EQ(t.find("://"), std::string::npos) << page << " points to " << t;
      EXPECT_TRUE(fs::exists(page.parent_path() / t)) << page << ": missing " << t;
      ++targets;
    }
    EXPECT_GE(targets, 2) << page << " links to nothing";
  }
}

TEST_F(BrowserReport, ScreenshotsAreNotBlank) {
  const auto all = pages();
  std::vector<int> status(all.size(), -1);
  for_each_parallel(all.size(), [&](size_t k) {
    const fs::path png = work_ / ("shot" + std::to_string(k) + ".png");
    status[k] = chromium("--window-size=1000,1400 --screenshot=" + quote(png.string()) + " " +
                             quote(file_url(all[k])) + " > /dev/null 2>&1",
                         work_, "s" + std::to_string(k));
  });
  for (size_t k = 0; k < all.size(); ++k) {
    const fs::path png = work_ / ("shot" + std::to_string(k) + ".png");
    ASSERT_EQ(status[k], 0) << all[k];
    size_t colours = 0;
    const double ink = ink_fraction_png(png, &colours);
    EXPECT_GT(ink, 0.02) << all[k] << ": screenshot " << png << " is nearly blank";
    EXPECT_GT(colours, 16u) << all[k] << ": screenshot " << png << " has almost no colours";
  }
}

TEST_F(BrowserReport, PdfHasAPagePerSectionAndNoBlankPage) {
  for (const auto& name : bundled_case_names()) {
    const fs::path pdf = out_ / name / "report.pdf";
    ASSERT_TRUE(fs::exists(pdf)) << name;
    // each section marked new-page starts a page; the header and first sections fill one
    const std::string html = slurp(out_ / name / "index.html");
    int expected = 1;
    for (size_t p = html.find("class=\"new-page\""); p != std::string::npos;
         p = html.find("class=\"new-page\"", p + 1))
      ++expected;
    const fs::path info = work_ / (name + ".pdfinfo");
    ASSERT_EQ(run("pdfinfo " + quote(pdf.string()) + " > " + quote(info.string()) + " 2>&1"), 0)
        << slurp(info);
    std::smatch m;
    const std::string text = slurp(info);
    ASSERT_TRUE(std::regex_search(text, m, std::regex(R"(Pages:\s+(\d+))"))) << text;
    const int pages = std::stoi(m[1]);
    EXPECT_GE(pages, expected) << name;
    const fs::path prefix = work_ / ("pdf-" + name);
    ASSERT_EQ(run("pdftoppm -gray -r 24 " + quote(pdf.string()) + " " + quote(prefix.string())), 0);
    int rasterised = 0;
    for (const auto& e : fs::directory_iterator(work_)) {
      const std::string f = e.path().filename().string();
      if (f.rfind("pdf-" + name + "-", 0) != 0 || e.path().extension() != ".pgm") continue;
      ++rasterised;
      EXPECT_GT(ink_fraction_pgm(e.path()), 0.003) << name << ": page " << f << " is blank";
    }
    EXPECT_EQ(rasterised, pages) << name;
  }
}

}  // namespace

namespace {

// what CI reads of the bundled run: every results.json valid against the schema, a junit
// testcase per case and check, summary.md naming every case
TEST_F(BrowserReport, BundledResultsValidateAndCiFilesCountEveryCheck) {
  const fs::path src(ARMSTUDY_SOURCE_DIR);
  const std::string cmd = "/usr/bin/python3 " + quote((src / "scripts/validate_results.py").string()) +
                          " " + quote((src / "results.schema.json").string()) + " " +
                          quote(out_.string()) + " > /dev/null";
  EXPECT_EQ(run(cmd), 0) << "a bundled results.json does not validate against results.schema.json";
  size_t expected = 0, failures = 0;
  const std::string summary = slurp(out_ / "summary.md");
  for (const auto& n : bundled_case_names()) {
    const auto j = nlohmann::json::parse(slurp(out_ / n / "results.json"));
    expected += 1 + j["checks"].size();
    failures += j["status"] != j["case"].value("expect", std::string("solved"));
    for (const auto& c : j["checks"]) failures += !c["passed"].get<bool>();
    EXPECT_NE(summary.find(n), std::string::npos) << n << " missing from summary.md";
  }
  const std::string junit = slurp(out_ / "junit.xml");
  size_t testcases = 0;
  for (size_t at = junit.find("<testcase "); at != std::string::npos; at = junit.find("<testcase ", at + 1))
    ++testcases;
  EXPECT_EQ(testcases, expected);
  size_t failed = 0;
  for (size_t at = junit.find("<failure"); at != std::string::npos; at = junit.find("<failure", at + 1))
    ++failed;
  EXPECT_EQ(failed, failures);
}

}  // namespace
