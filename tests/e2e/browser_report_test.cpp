// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Every bundled case's report, opened in a real browser (headless Chromium): the page loads
// with no console message (CSP violations and script errors are console messages), every
// img/link/object target exists on disk, a screenshot is not blank, and report.pdf has at
// least one page per section that starts a new page, none of them blank.
#include <gtest/gtest.h>
#include <png.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
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
    os << p.filename().string() << ' ' << fs::last_write_time(p).time_since_epoch().count() << '\n';
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

// what CI reads of the bundled run: every results.json valid against the schema, every case
// ending as it expects with every check passed, a junit testcase per case and check,
// summary.md naming every case
TEST_F(BrowserReport, BundledResultsValidateAndCiFilesCountEveryCheck) {
  const fs::path src(ARMSTUDY_SOURCE_DIR);
  const std::string cmd =
      "/usr/bin/python3 " + quote((src / "scripts/validate_results.py").string()) + " " +
      quote((src / "results.schema.json").string()) + " " + quote(out_.string()) + " > /dev/null";
  EXPECT_EQ(run(cmd), 0) << "a bundled results.json does not validate against results.schema.json";
  size_t expected = 0, failures = 0;
  const std::string summary = slurp(out_ / "summary.md");
  for (const auto& n : bundled_case_names()) {
    const auto j = nlohmann::json::parse(slurp(out_ / n / "results.json"));
    expected += 1 + j["checks"].size();
    // every bundled case ends as it expects and passes every check: junit.xml counts the
    // failures, and there must be none
    const std::string expect = j["case"].value("expect", std::string("solved"));
    failures += j["status"] != expect;
    EXPECT_EQ(j["status"], expect) << n;
    for (const auto& c : j["checks"]) {
      failures += !c["passed"].get<bool>();
      EXPECT_TRUE(c["passed"].get<bool>()) << n << ": check " << c["name"] << " failed, value "
                                           << c["value"] << ", tolerance " << c["tolerance"];
    }
    EXPECT_NE(summary.find(n), std::string::npos) << n << " missing from summary.md";
  }
  const std::string junit = slurp(out_ / "junit.xml");
  size_t testcases = 0;
  for (size_t at = junit.find("<testcase "); at != std::string::npos;
       at = junit.find("<testcase ", at + 1))
    ++testcases;
  EXPECT_EQ(testcases, expected);
  size_t failed = 0;
  for (size_t at = junit.find("<failure"); at != std::string::npos;
       at = junit.find("<failure", at + 1))
    ++failed;
  EXPECT_EQ(failed, failures);
}

}  // namespace

namespace {

// the page's Content-Security-Policy as the templates write it: no script, nothing fetched
constexpr const char* kCsp =
    "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src 'self'; "
    "style-src 'self'; base-uri 'none'; form-action 'none'\">";

// whitespace runs as one space (pdftotext breaks lines where the page does)
std::string squeezed(const std::string& s) {
  std::string out;
  for (char c : s) {
    const bool space = std::isspace(static_cast<unsigned char>(c));
    if (space && (out.empty() || out.back() == ' ')) continue;
    out += space ? ' ' : c;
  }
  return out;
}

// text without tags, code and preformatted blocks
std::string text_of(std::string html) {
  html = std::regex_replace(html, std::regex(R"(<pre[\s\S]*?</pre>)"), " ");
  html = std::regex_replace(html, std::regex(R"(<code>[\s\S]*?</code>)"), " ");
  return std::regex_replace(html, std::regex(R"(<[^>]*>)"), " ");
}

// what the page uses as labels before its appendix: headings, table headers and first
// cells, key figure names, the bold title of a caption; and the whole answer box
std::string labels_before_appendix(std::string html) {
  for (const char* start : {"<section id=\"parameters\"", "<section id=\"case\"", "<footer"}) {
    const size_t at = html.find(start);
    if (at != std::string::npos) html.resize(at);
  }
  html = std::regex_replace(html, std::regex(R"(<head>[\s\S]*?</head>)"), " ");
  static const std::regex kLabel(
      R"re(<(h[1-4]|th|dt|strong)\b[^>]*>([\s\S]*?)</\1>|<tr>\s*<td[^>]*>([\s\S]*?)</td>)re");
  std::string out;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), kLabel);
       it != std::sregex_iterator(); ++it)
    out += " " + text_of((*it)[2].str() + (*it)[3].str());
  const size_t box = html.find("<section id=\"answer\"");
  if (box != std::string::npos)
    out += " " + text_of(html.substr(box, html.find("</section>", box) - box));
  return out;
}

std::string sha256_of(const fs::path& file, const fs::path& work) {
  const fs::path out = work / "sha256.txt";
  if (run("sha256sum " + quote(file.string()) + " > " + quote(out.string())) != 0) return "";
  return slurp(out).substr(0, 64);
}

// page 1 of every report: the answer in one sentence, the key picture and the verdict of
// the checks, in the PDF a reviewer prints as well as in the page; a screenshot of it is
// kept (browser_e2e/page1/<case>.png) to look at
TEST_F(BrowserReport, PageOneHoldsTheAnswerTheKeyPictureAndTheCheckVerdict) {
  const fs::path shots = out_.parent_path() / "page1";
  fs::create_directories(shots);
  for (const auto& name : bundled_case_names()) {
    const auto j = nlohmann::json::parse(slurp(out_ / name / "results.json"));
    const std::string html = slurp(out_ / name / "index.html");
    const size_t box = html.find("<section id=\"answer\"");
    ASSERT_NE(box, std::string::npos) << name << ": no answer box";
    const std::string answer = html.substr(box, html.find("</section>", box) - box);
    // the key picture is in the box and on disk
    std::smatch m;
    ASSERT_TRUE(std::regex_search(answer, m, std::regex(R"re(<img src="([^"]+)")re"))) << name;
    const std::string picture = m[1];
    EXPECT_TRUE(fs::exists(out_ / name / picture)) << name << ": " << picture;
    if (!j["frames"].empty()) {
      EXPECT_TRUE(picture.ends_with(".png"))
          << name << ": a rendered motion answers with its frame";
    }
    // the verdict counts the checks
    const size_t checks = j["checks"].size();
    size_t failed = 0;
    for (const auto& c : j["checks"]) failed += !c["passed"].get<bool>();
    const std::string verdict =
        checks == 0 ? "The study ran no checks"
        : failed == 0
            ? (checks == 1 ? "check passed" : "All " + std::to_string(checks) + " checks passed")
            : std::to_string(failed) + " of " + std::to_string(checks) + " checks FAILED";
    EXPECT_NE(answer.find(verdict), std::string::npos)
        << name << ": verdict '" << verdict << "' missing";
    // the printed page 1 says the same: the answer's first words, the verdict, the picture
    const fs::path txt = work_ / (name + "-page1.txt");
    ASSERT_EQ(run("pdftotext -f 1 -l 1 " + quote((out_ / name / "report.pdf").string()) + " " +
                  quote(txt.string())),
              0);
    const std::string page1 = squeezed(slurp(txt));
    EXPECT_NE(page1.find("The answer"), std::string::npos) << name;
    const std::string message = squeezed(j["message"].get<std::string>());
    EXPECT_NE(page1.find(message.substr(0, std::min<size_t>(40, message.size()))),
              std::string::npos)
        << name << ": page 1 does not start with the answer '" << message << "'";
    EXPECT_NE(page1.find(verdict), std::string::npos) << name << ": page 1 lacks the verdict";
    if (picture.ends_with(".png")) {
      const fs::path list = work_ / (name + "-images.txt");
      ASSERT_EQ(run("pdfimages -list -f 1 -l 1 " + quote((out_ / name / "report.pdf").string()) +
                    " > " + quote(list.string())),
                0);
      size_t lines = 0;
      std::istringstream in(slurp(list));
      for (std::string l; std::getline(in, l);) lines += !l.empty();
      EXPECT_GE(lines, 3u) << name << ": page 1 of the PDF has no image";  // 2 header lines
    }
    ASSERT_EQ(
        run("pdftoppm -png -r 60 -f 1 -l 1 -singlefile " +
            quote((out_ / name / "report.pdf").string()) + " " + quote((shots / name).string())),
        0);
  }
}

// labels are words: no results.json key (snake_case like energy_eq8_J or dp_joint1) is printed as a
// label, nor anywhere in the answer box, outside code and the appendix (which shows the
// case file's own keys)
TEST_F(BrowserReport, NoMachineKeyNamesAsLabels) {
  static const std::regex kKey(R"(\b[a-z][a-z0-9]+(?:_[A-Za-z0-9]+)+\b)");
  for (const auto& name : bundled_case_names()) {
    const std::string text = labels_before_appendix(slurp(out_ / name / "index.html"));
    std::set<std::string> found;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), kKey);
         it != std::sregex_iterator(); ++it)
      found.insert((*it)[0]);
    std::string all;
    for (const auto& f : found) all += " " + f;
    EXPECT_TRUE(found.empty()) << name << ": machine keys on the page:" << all;
  }
  // the key figures carry their human label in results.json too
  for (const auto& name : bundled_case_names()) {
    const auto j = nlohmann::json::parse(slurp(out_ / name / "results.json"));
    for (const auto& k : j["key_figures"]) {
      ASSERT_TRUE(k.contains("label")) << name << ": " << k.dump();
      EXPECT_FALSE(std::regex_search(k["label"].get<std::string>(), kKey))
          << name << ": " << k.dump();
    }
  }
}

// every motion is an animation on the page (CSS over its sprite sheet, no script: the CSP is
// the templates' own) and a video beside it that decodes to the frames at the motion's speed
TEST_F(BrowserReport, EveryMotionHasAnAnimationAndAVideoThatDecodes) {
  size_t videos = 0;
  for (const auto& name : bundled_case_names()) {
    const fs::path dir = out_ / name;
    const auto j = nlohmann::json::parse(slurp(dir / "results.json"));
    const std::string html = slurp(dir / "index.html"), css = slurp(dir / "report.css");
    EXPECT_NE(html.find(kCsp), std::string::npos) << name << ": the CSP changed";
    EXPECT_EQ(html.find("<script"), std::string::npos) << name;
    if (j["status"] == "solved") {
      EXPECT_FALSE(j["animations"].empty()) << name << ": no animation";
    }
    std::map<std::string, std::string> listed;  // files with their sha256
    for (const auto& f : j["files"]) listed[f["path"]] = f["sha256"];
    for (const auto& a : j["animations"]) {
      const std::string cls = "a-" + a["name"].get<std::string>();
      EXPECT_NE(html.find("class=\"anim " + cls + "\""), std::string::npos) << name << ": " << cls;
      EXPECT_NE(css.find(".anim." + cls + " {"), std::string::npos) << name << ": " << cls;
      EXPECT_NE(css.find("@keyframes " + cls + " {"), std::string::npos) << name << ": " << cls;
      for (const char* key : {"sprite", "still", "video"}) {
        ASSERT_TRUE(a[key].is_string())
            << name << ": " << cls << " has no " << key << " (ffmpeg missing?)";
        const std::string f = a[key];
        ASSERT_TRUE(fs::exists(dir / f)) << name << ": " << f;
        EXPECT_EQ(listed[f], sha256_of(dir / f, work_))
            << name << ": " << f << " not in files with its sha256";
      }
      EXPECT_NE(html.find("href=\"" + a["video"].get<std::string>() + "\""), std::string::npos)
          << name;
      // the video: as many frames as the animation, at the motion's real speed
      const fs::path probe = work_ / "probe.json";
      ASSERT_EQ(run("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                    "stream=nb_read_frames,duration -of json " +
                    quote((dir / a["video"].get<std::string>()).string()) + " > " +
                    quote(probe.string())),
                0)
          << name << ": " << a["video"];
      const auto p = nlohmann::json::parse(slurp(probe))["streams"][0];
      const int frames = a["frames"], decoded = std::stoi(p["nb_read_frames"].get<std::string>());
      const double fps = a["fps"], duration = std::stod(p["duration"].get<std::string>());
      EXPECT_EQ(decoded, frames) << name << ": " << a["video"];
      EXPECT_NEAR(duration, frames / fps, 0.5 / fps) << name << ": " << a["video"];
      // frame k at t0 + k / fps: the last frame is the motion's end
      EXPECT_NEAR((frames - 1) / fps, a["duration_s"].get<double>(), 1e-6) << name;
      ++videos;
    }
  }
  EXPECT_GE(videos, 5u);
}

// a page of a binary PGM (P5) from pdftoppm -gray: its share of dark pixels and how far
// down its content reaches (the last row holding a dark pixel, as a fraction of the height)
struct PageInk {
  double ink = -1, reach = -1;
};
PageInk page_ink(const fs::path& pgm) {
  std::ifstream in(pgm, std::ios::binary);
  std::string magic;
  int w = 0, h = 0, maxv = 0;
  in >> magic >> w >> h >> maxv;
  in.get();
  if (magic != "P5" || w <= 0 || h <= 0 || maxv != 255) return {};
  std::vector<unsigned char> px(static_cast<size_t>(w) * h);
  in.read(reinterpret_cast<char*>(px.data()), static_cast<std::streamsize>(px.size()));
  size_t ink = 0;
  int last_row = -1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (px[static_cast<size_t>(y) * w + x] < 200) ++ink, last_row = y;
  return {static_cast<double>(ink) / px.size(), (last_row + 1.0) / h};
}

// the headings of the sections that start a printed page (class="new-page"): each starts a
// part, so the page before it may end early
std::vector<std::string> part_headings(const std::string& html) {
  static const std::regex kPart(R"re(<section id="[^"]*" class="new-page">\s*<h2>([^<]*)</h2>)re");
  std::vector<std::string> out = {"Appendix A."};
  for (auto it = std::sregex_iterator(html.begin(), html.end(), kPart);
       it != std::sregex_iterator(); ++it)
    out.push_back(squeezed((*it)[1].str()));
  return out;
}

// page economy: the page counts of every report, with each page's ink and reach (kept in
// browser_e2e/page_counts.txt), and no page mostly blank but the last one of a part (page 1,
// the answer; the page before the appendix or before a section that starts a page; the last
// page): the content of every other page reaches past the middle of the page and inks at
// least 2 % of it (a page of text inks 4 % or more at 24 dpi)
TEST_F(BrowserReport, PdfPagesAreNotMostlyBlankAndTheirCountsAreRecorded) {
  constexpr double kMinReach = 0.5, kMinInk = 0.02;
  std::ofstream counts(out_.parent_path() / "page_counts.txt");
  counts << "# case pages, then per page: ink share / reach of the content down the page\n";
  for (const auto& name : bundled_case_names()) {
    const fs::path pdf = out_ / name / "report.pdf";
    const fs::path prefix = work_ / ("eco-" + name);
    ASSERT_EQ(run("pdftoppm -gray -r 24 " + quote(pdf.string()) + " " + quote(prefix.string())), 0);
    std::vector<fs::path> pgm;
    for (const auto& e : fs::directory_iterator(work_))
      if (e.path().filename().string().rfind("eco-" + name + "-", 0) == 0) pgm.push_back(e.path());
    std::sort(pgm.begin(), pgm.end());
    ASSERT_FALSE(pgm.empty()) << name;
    RecordProperty(name + "_pages", static_cast<int>(pgm.size()));
    const auto parts = part_headings(slurp(out_ / name / "index.html"));
    counts << name << " " << pgm.size();
    for (size_t k = 0; k < pgm.size(); ++k) {
      const PageInk p = page_ink(pgm[k]);
      char cell[32];
      std::snprintf(cell, sizeof cell, " %.3f/%.2f", p.ink, p.reach);
      counts << cell;
      ASSERT_GE(p.ink, 0) << name << ": page " << k + 1 << " did not rasterise";
      if (k + 1 == pgm.size()) continue;  // the last page
      // the page after starts a part
      const fs::path txt = work_ / "next-page.txt";
      ASSERT_EQ(run("pdftotext -f " + std::to_string(k + 2) + " -l " + std::to_string(k + 2) + " " +
                    quote(pdf.string()) + " " + quote(txt.string())),
                0);
      const std::string next = squeezed(slurp(txt));
      if (std::any_of(parts.begin(), parts.end(),
                      [&](const std::string& h) { return next.rfind(h, 0) == 0; }))
        continue;
      EXPECT_GE(p.reach, kMinReach) << name << ": page " << k + 1 << " of " << pgm.size()
                                    << " is mostly blank (its content ends at " << p.reach
                                    << " of the page) and no part starts on the next";
      EXPECT_GE(p.ink, kMinInk) << name << ": page " << k + 1 << " of " << pgm.size()
                                << " is nearly blank";
    }
    counts << "\n";
  }
}

// Chromium shrinks every page of a PDF to fit an element wider than the page (a table of
// many columns printed the throwing report at 75 %): the tallest words after page 1 (the
// title's page), the section headings (1.3 rem of 10.5 pt), print at their size (pdftotext's
// word boxes are 1.164 font sizes tall: DejaVu Sans' ascent and descent). Every page from 2
// on is read: page 2 need not start a section (a long answer continues there)
TEST_F(BrowserReport, PdfIsPrintedAtFullSize) {
  static const std::regex kWord(
      R"re(<word xMin="[\d.]+" yMin="([\d.]+)" xMax="[\d.]+" yMax="([\d.]+)")re");
  constexpr double kHeading = 1.3 * 10.5 * 1.164;
  for (const auto& name : bundled_case_names()) {
    const fs::path box = work_ / (name + "-bbox.html");
    ASSERT_EQ(run("pdftotext -f 2 -bbox " + quote((out_ / name / "report.pdf").string()) + " " +
                  quote(box.string())),
              0);
    const std::string html = slurp(box);
    double tallest = 0;
    for (auto it = std::sregex_iterator(html.begin(), html.end(), kWord);
         it != std::sregex_iterator(); ++it)
      tallest = std::max(tallest, std::stod((*it)[2]) - std::stod((*it)[1]));
    EXPECT_NEAR(tallest, kHeading, 0.5)
        << name << ": the headings after page 1 print at " << tallest / 1.164 << " pt, not "
        << kHeading / 1.164 << " pt: the page was shrunk to fit something too wide";
  }
}

}  // namespace
