// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// `armstudy diff BASE NEW`: two runs of the same cases diff clean; a changed case file, a
// removed and an added case are exactly the entries of the diff; a tolerance that covers the
// change passes; a frame changed in a few pixels is found and drawn; bad input names the
// file; the page loads in headless Chromium like the reports. Sweep rows and tolerance
// lookup are checked on results data directly.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cases/case_error.hpp"
#include "cli/diff.hpp"
#include "scene/png_writer.hpp"
#include "testing/browser.hpp"
#include "testing/cli.hpp"
#include "testing/files.hpp"

namespace {
namespace fs = std::filesystem;
using armstudy::testing::slurp;
using nlohmann::json;

using armstudy::testing::CliRun;
using armstudy::testing::run_cli;
CliRun cli(const std::string& args) { return run_cli(args); }

std::string q(const fs::path& p) { return armstudy::testing::quote(p.string()); }

const fs::path kCases = fs::path(ARMSTUDY_SOURCE_DIR) / "reports/cases";

void write_text(const fs::path& p, const std::string& s) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << s;
}

// the rows of the markdown table under `heading` (first cell of each body row)
std::vector<std::string> table_cases(const std::string& md, const std::string& heading) {
  std::vector<std::string> names;
  const size_t at = md.find(heading);
  if (at == std::string::npos) return names;
  std::istringstream in(md.substr(at));
  std::string line;
  int seen = 0;
  while (std::getline(in, line)) {
    if (line.rfind("| ", 0) == 0) {
      if (++seen <= 1) continue;  // header
      names.push_back(line.substr(2, line.find(" |", 2) - 2));
    } else if (line.rfind("|---", 0) == 0) {
      continue;
    } else if (seen > 0) {
      break;
    }
  }
  return names;
}

// what the shared runs were made from: the binary and the bundled case files used
std::string diff_input_stamp() {
  std::ostringstream os;
  for (const fs::path& p : {fs::path(ARMSTUDY_BINARY), kCases / "placement-example-3.yaml",
                            kCases / "placement-example-5.yaml", kCases / "pendulum.yaml"})
    os << p.string() << ' ' << fs::last_write_time(p).time_since_epoch().count() << '\n';
  return os.str();
}

// Runs shared by the tests (ctest runs each test in its own process), made once per input
// change under a file lock: a base and a second run of the same cases (placement example 3
// without frames, the pendulum with frames), and folders derived from them.
class Diff : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::path(ARMSTUDY_BINARY).parent_path() / "diff_e2e";
    fs::create_directories(root_);
    const int lock =
        ::open((root_.parent_path() / "diff_e2e.lock").c_str(), O_CREAT | O_RDWR, 0644);
    ASSERT_GE(lock, 0);
    ::flock(lock, LOCK_EX);
    const std::string stamp = diff_input_stamp();
    if (slurp(root_ / "stamp") != stamp) make_runs();
    ::flock(lock, LOCK_UN);
    ::close(lock);
  }

  static void make_runs() {
    fs::remove_all(root_);
    fs::create_directories(root_);
    auto run_into = [](const fs::path& out, const std::string& files, bool render) {
      const CliRun r = cli("run " + files + " --out " + q(out) + (render ? "" : " --no-render"));
      ASSERT_EQ(r.exit_code, 0) << r.output;
    };
    for (const char* name : {"base", "again"}) {
      run_into(root_ / name, q(kCases / "placement-example-3.yaml"), false);
      run_into(root_ / name, q(kCases / "pendulum.yaml"), true);
    }
    // the same case with a slower motion (1.1 s instead of 1 s): every energy drops
    std::string yaml = slurp(kCases / "placement-example-3.yaml");
    const std::string from = "duration_s: 1.0", to = "duration_s: 1.1";
    ASSERT_NE(yaml.find(from), std::string::npos);
    yaml.replace(yaml.find(from), from.size(), to);
    write_text(root_ / "cases/placement-example-3.yaml", yaml);
    // "longer": the changed case beside the base's pendulum
    run_into(root_ / "longer", q(root_ / "cases/placement-example-3.yaml"), false);
    fs::copy(root_ / "base/pendulum", root_ / "longer/pendulum", fs::copy_options::recursive);
    // "mixed": the changed case, example 5 added, the pendulum removed
    fs::create_directories(root_ / "mixed");
    fs::copy(root_ / "longer/placement-example-3", root_ / "mixed/placement-example-3",
             fs::copy_options::recursive);
    run_into(root_ / "mixed", q(kCases / "placement-example-5.yaml"), false);
    write_text(root_ / "stamp", diff_input_stamp());
  }

  static fs::path out(const std::string& tag) { return root_ / ("diff-" + tag); }

  static fs::path root_;
};
fs::path Diff::root_;

TEST_F(Diff, TwoRunsOfTheSameCasesDiffClean) {
  const CliRun r =
      cli("diff " + q(root_ / "base") + " " + q(root_ / "again") + " --out " + q(out("clean")));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("nothing moved beyond tolerance"), std::string::npos) << r.output;
  const std::string md = slurp(out("clean") / "diff.md");
  EXPECT_EQ(md.rfind("# armstudy diff: nothing moved beyond tolerance", 0), 0u) << md;
  EXPECT_NE(md.find("2 case(s) have the same status, key figures, checks and frames"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("## Beyond tolerance"), std::string::npos) << md;
  EXPECT_NE(md.find("## Inputs\n\nEvery case of both runs has the same inputs."), std::string::npos)
      << md;
  EXPECT_TRUE(fs::exists(out("clean") / "diff.html"));
  EXPECT_FALSE(fs::exists(out("clean") / "diff-frames")) << "identical frames need no copies";
}

TEST_F(Diff, ChangedRemovedAndAddedCasesAreExactlyTheEntries) {
  const CliRun r =
      cli("diff " + q(root_ / "base") + " " + q(root_ / "mixed") + " --out " + q(out("mixed")));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const std::string md = slurp(out("mixed") / "diff.md");
  EXPECT_EQ(md.rfind("# armstudy diff: 3 case(s) moved beyond tolerance", 0), 0u) << md;
  const auto moved = table_cases(md, "## Beyond tolerance (3)");
  EXPECT_EQ(moved,
            (std::vector<std::string>{"pendulum", "placement-example-3", "placement-example-5"}))
      << md;
  EXPECT_NE(md.find("| pendulum | pendulum | removed (only in the base run): solved |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| placement-example-5 | placement | added (only in the new run): solved |"),
            std::string::npos)
      << md;
  // the changed case: its energies side by side with the change; without gravity the
  // energy is kinetic, and a rest-to-rest motion slowed by 1.1 needs 1/1.1^2 of it
  const auto base = json::parse(slurp(root_ / "base/placement-example-3/results.json"));
  const auto now = json::parse(slurp(root_ / "mixed/placement-example-3/results.json"));
  double e0 = 0, e1 = 0;
  for (const auto& k : base["key_figures"])
    if (k["name"] == "min_energy_J") e0 = k["value"];
  for (const auto& k : now["key_figures"])
    if (k["name"] == "min_energy_J") e1 = k["value"];
  ASSERT_GT(e0, 0);
  EXPECT_NEAR(e1 / e0, 1 / (1.1 * 1.1), 1e-4);
  const std::regex row(
      R"(\| min_energy_J \| ([0-9.]+) J \| ([0-9.]+) J \| (-[0-9.]+) J \| (-[0-9.]+) % \| exact \| \*\*BEYOND\*\* \|)");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(md, m, row)) << md;
  EXPECT_NEAR(std::stod(m[1]), e0, 1e-4 * e0);
  EXPECT_NEAR(std::stod(m[2]), e1, 1e-4 * e1);
  EXPECT_NEAR(std::stod(m[4]), 100 * (e1 - e0) / e0, 0.06);
  // nothing else: no sweep, nothing within tolerance, nothing unchanged
  EXPECT_EQ(md.find("## Changed within tolerance"), std::string::npos) << md;
  EXPECT_NE(md.find("0 case(s) have the same status"), std::string::npos) << md;
}

TEST_F(Diff, AToleranceThatCoversTheChangePasses) {
  // without tolerances the slower motion moves; with 30 % on placement figures it does not
  const CliRun strict =
      cli("diff " + q(root_ / "base") + " " + q(root_ / "longer") + " --out " + q(out("strict")));
  EXPECT_EQ(strict.exit_code, 1) << strict.output;
  const std::string strict_md = slurp(out("strict") / "diff.md");
  EXPECT_EQ(table_cases(strict_md, "## Beyond tolerance"),
            std::vector<std::string>{"placement-example-3"});
  // first the input that differs (from each results.json's case.inputs), then what moved
  const size_t inputs = strict_md.find("## Inputs that differ\n\n| case | input | base | new |");
  EXPECT_NE(inputs, std::string::npos) << strict_md;
  EXPECT_LT(inputs, strict_md.find("## Beyond tolerance")) << strict_md;
  EXPECT_EQ(table_cases(strict_md, "## Inputs that differ"),
            std::vector<std::string>{"placement-example-3"})
      << strict_md;
  EXPECT_NE(strict_md.find("| placement-example-3 | placement.duration_s | 1.0 | 1.1 |"),
            std::string::npos)
      << strict_md;
  const fs::path tol = root_ / "tolerances.yaml";
  write_text(tol, "# energies scale as 1/T^3\nstudies:\n  placement:\n    default: {rel: 0.3}\n");
  const CliRun r = cli("diff " + q(root_ / "base") + " " + q(root_ / "longer") + " --out " +
                       q(out("tol")) + " --tolerances " + q(tol));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const std::string md = slurp(out("tol") / "diff.md");
  EXPECT_EQ(table_cases(md, "## Changed within tolerance"),
            std::vector<std::string>{"placement-example-3"})
      << md;
  // a tolerance just short of the change (the energies drop by 17.4 %) does not cover it
  write_text(tol,
             "studies:\n  placement:\n    default: {rel: 0.3}\n    figures:\n      "
             "\"energy_J[*]\": {rel: 0.15}\n");
  EXPECT_EQ(cli("diff " + q(root_ / "base") + " " + q(root_ / "longer") + " --out " +
                q(out("tol2")) + " --tolerances " + q(tol))
                .exit_code,
            1);
}

TEST_F(Diff, AFrameChangedInAFewPixelsIsFoundAndDrawn) {
  const fs::path pix = root_ / "pix";
  fs::remove_all(pix);
  fs::copy(root_ / "base", pix, fs::copy_options::recursive);
  const fs::path frame = pix / "pendulum/pendulum_snapshots_strip.png";
  ASSERT_TRUE(fs::exists(frame));
  armstudy::scene::Image img = armstudy::scene::read_png(frame);
  const std::vector<std::pair<int, int>> spots = {
      {10, 10}, {11, 10}, {200, 40}, {img.width - 20, img.height - 20}, {300, 100}};
  for (const auto& [x, y] : spots) {
    auto c = img.at(x, y);
    c.g = static_cast<uint8_t>(c.g > 127 ? c.g - 40 : c.g + 40);
    img.set(x, y, c);
  }
  armstudy::scene::write_png(frame, img);
  // the new run says it used another renderer
  auto rj = json::parse(slurp(pix / "pendulum/results.json"));
  rj["provenance"]["gl_renderer"] = "llvmpipe (LLVM 99.0, 512 bits)";
  write_text(pix / "pendulum/results.json", rj.dump(2));

  const CliRun r = cli("diff " + q(root_ / "base") + " " + q(pix) + " --out " + q(out("pix")));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const std::string md = slurp(out("pix") / "diff.md");
  EXPECT_EQ(table_cases(md, "## Beyond tolerance"), std::vector<std::string>{"pendulum"}) << md;
  EXPECT_NE(
      md.find("pendulum_snapshots_strip.png | 5 px beyond ±0 (largest channel difference 40)"),
      std::string::npos)
      << md;
  EXPECT_NE(md.find("The runs rendered with different renderers"), std::string::npos) << md;
  EXPECT_NE(md.find("llvmpipe (LLVM 99.0, 512 bits)"), std::string::npos) << md;
  // the other frame is byte-identical and not drawn
  EXPECT_EQ(md.find("pendulum_snapshots_locus.png"), std::string::npos) << md;
  // the difference image: the changed pixels red, the rest grey, a box around them
  const fs::path diff_png = out("pix") / "diff-frames/pendulum/diff_pendulum_snapshots_strip.png";
  ASSERT_TRUE(fs::exists(diff_png));
  EXPECT_TRUE(fs::exists(out("pix") / "diff-frames/pendulum/base_pendulum_snapshots_strip.png"));
  EXPECT_TRUE(fs::exists(out("pix") / "diff-frames/pendulum/new_pendulum_snapshots_strip.png"));
  const auto d = armstudy::scene::read_png(diff_png);
  ASSERT_EQ(d.width, img.width);
  size_t red = 0;
  for (int y = 0; y < d.height; ++y)
    for (int x = 0; x < d.width; ++x) {
      const auto c = d.at(x, y);
      red += c.r == 220 && c.g == 0 && c.b == 0;
    }
  EXPECT_EQ(red, spots.size());
  for (const auto& [x, y] : spots) EXPECT_EQ(d.at(x, y).r, 220) << x << "," << y;
  const std::string html = slurp(out("pix") / "diff.html");
  EXPECT_NE(html.find("diff-frames/pendulum/diff_pendulum_snapshots_strip.png"), std::string::npos);
  // a per-channel tolerance above the change, or allowing 5 pixels, passes
  EXPECT_EQ(cli("diff " + q(root_ / "base") + " " + q(pix) + " --out " + q(out("pix40")) +
                " --pixel-tolerance 40")
                .exit_code,
            0);
  EXPECT_EQ(
      cli("diff " + q(root_ / "base") + " " + q(pix) + " --out " + q(out("pix5")) + " --pixels 5")
          .exit_code,
      0);
  EXPECT_EQ(
      cli("diff " + q(root_ / "base") + " " + q(pix) + " --out " + q(out("pix4")) + " --pixels 4")
          .exit_code,
      1);
}

TEST_F(Diff, BadInputNamesTheFileAndWritesNothing) {
  const fs::path bad = root_ / "bad";
  fs::remove_all(bad);
  fs::copy(root_ / "base", bad, fs::copy_options::recursive);
  const fs::path rj = bad / "placement-example-3/results.json";
  const std::string text = slurp(rj);
  write_text(rj, text.substr(0, text.size() / 2));
  for (const auto& [a, b] : {std::pair{root_ / "base", bad}, std::pair{bad, root_ / "base"}}) {
    const fs::path o = out("bad");
    fs::remove_all(o);
    const CliRun r = cli("diff " + q(a) + " " + q(b) + " --out " + q(o));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(rj.string() + ": truncated or not JSON"), std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(o / "diff.md"));
  }
  // valid JSON of the wrong shape
  auto j = json::parse(slurp(root_ / "base/placement-example-3/results.json"));
  j["key_figures"][0]["value"] = "fast";
  write_text(rj, j.dump());
  CliRun r = cli("diff " + q(root_ / "base") + " " + q(bad) + " --out " + q(out("bad")));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(rj.string() + ": /key_figures/0/value: expected a number"),
            std::string::npos)
      << r.output;
  // a missing folder, an empty one
  r = cli("diff " + q(root_ / "base") + " " + q(root_ / "no-such") + " --out " + q(out("bad")));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find((root_ / "no-such").string() + ": no such folder"), std::string::npos)
      << r.output;
  fs::create_directories(root_ / "empty");
  r = cli("diff " + q(root_ / "empty") + " " + q(root_ / "base") + " --out " + q(out("bad")));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no case folder with a results.json"), std::string::npos) << r.output;
  // a tolerances file with errors: every one as file:line:col
  const fs::path tol = root_ / "bad-tolerances.yaml";
  write_text(tol,
             "default: {rel: -1}\nstudies:\n  placemnt: {default: {abs: 1}}\n  time_optimal:\n    "
             "figurs: {}\n");
  r = cli("diff " + q(root_ / "base") + " " + q(root_ / "again") + " --out " + q(out("bad")) +
          " --tolerances " + q(tol));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(tol.string() + ":1:16: "), std::string::npos) << r.output;
  EXPECT_NE(
      r.output.find(tol.string() + ":3:3: unknown study 'placemnt'; did you mean 'placement'?"),
      std::string::npos)
      << r.output;
  EXPECT_NE(
      r.output.find(tol.string() +
                    ":5:5: unknown key 'studies.time_optimal.figurs'; did you mean 'figures'?"),
      std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(out("bad") / "diff.md"));
}

TEST_F(Diff, PageLoadsInChromiumWithoutConsoleMessagesOrMissingFiles) {
  // the pixel diff's page shows frame copies; the mixed diff's has tables only
  const CliRun a = cli("diff " + q(root_ / "base") + " " + q(root_ / "mixed") + " --out " +
                       q(out("page-mixed")));
  ASSERT_EQ(a.exit_code, 1) << a.output;
  const fs::path pix = root_ / "page-pix";
  fs::remove_all(pix);
  fs::copy(root_ / "base", pix, fs::copy_options::recursive);
  const fs::path frame = pix / "pendulum/pendulum_snapshots_locus.png";
  auto img = armstudy::scene::read_png(frame);
  for (int x = 100; x < 130; ++x) img.set(x, 100, {255, 0, 0});
  armstudy::scene::write_png(frame, img);
  ASSERT_EQ(
      cli("diff " + q(root_ / "base") + " " + q(pix) + " --out " + q(out("page-pix"))).exit_code,
      1);
  const fs::path work = root_ / "browser";
  fs::create_directories(work);
  int k = 0;
  for (const fs::path& page : {out("page-mixed") / "diff.html", out("page-pix") / "diff.html"}) {
    int targets = 0;
    const auto problems =
        armstudy::testing::page_problems(page, work, std::to_string(k++), &targets);
    for (const auto& p : problems) ADD_FAILURE() << page << ": " << p;
    EXPECT_GE(targets, 2) << page;
    const fs::path shot = work / ("shot" + std::to_string(k) + ".png");
    ASSERT_EQ(
        armstudy::testing::chromium(
            "--window-size=1000,1400 --screenshot=" + q(shot) + " " +
                armstudy::testing::quote(armstudy::testing::file_url(page)) + " > /dev/null 2>&1",
            work, "s" + std::to_string(k)),
        0);
    size_t colours = 0;
    EXPECT_GT(armstudy::testing::ink_fraction_png(shot, &colours), 0.02) << shot;
    EXPECT_GT(colours, 16u) << shot;
  }
  const std::string html = slurp(out("page-pix") / "diff.html");
  for (const char* f : {"base_", "new_", "diff_"})
    EXPECT_NE(html.find(std::string("diff-frames/pendulum/") + f + "pendulum_snapshots_locus.png"),
              std::string::npos)
        << f;
}

TEST(DiffCli, HelpAndUsageErrors) {
  const CliRun help = cli("diff --help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* w : {"Usage", "--tolerances", "--pixel-tolerance", "--out"})
    EXPECT_NE(help.output.find(w), std::string::npos) << w;
  EXPECT_EQ(cli("diff only-one-folder").exit_code, 2);
  EXPECT_EQ(cli("diff a b --pixel-tolerance 300").exit_code, 2);
  EXPECT_EQ(cli("diff a b --bogus").exit_code, 2);
}

// ---- on results data directly ----

using armstudy::cli::CaseOutput;

CaseOutput sweep_case(const std::string& name, double l2, double energy,
                      const std::string& status = "solved") {
  armstudy::report::ResultsRecord r;
  r.study = "placement";
  r.case_info.name = name;
  r.case_info.path = name + ".yaml";
  r.case_info.sha256 = std::string(64, 'a');
  r.case_info.sweep =
      armstudy::report::CaseRecord::Sweep{"ratio", {{"arm.links[2].length", std::to_string(l2)}}};
  r.status = status;
  r.key_figures = {{"min_energy_J", energy, "J", "least energy"},
                   {"run_time_s", energy / 7, "s", "run time"}};
  r.provenance.armstudy_version = "0.1.0";
  r.provenance.compiler = "gcc 12";
  return {fs::path("/nonexistent") / name, armstudy::report::write_record(r), r};
}

TEST(DiffRuns, SweepRowsAreComparedByCaseIdLargestChangeFirst) {
  std::vector<CaseOutput> base, now;
  for (int i = 0; i < 20; ++i) {
    const std::string n = "p-" + std::to_string(100 + i);
    base.push_back(sweep_case(n, 0.1 + 0.01 * i, 1.0 + i));
    double e = 1.0 + i;
    if (i == 3) e *= 1.01;   // +1 %
    if (i == 7) e *= 0.8;    // -20 %
    if (i == 11) e *= 1.05;  // +5 %
    if (i == 19) continue;   // removed
    now.push_back(sweep_case(n, 0.1 + 0.01 * i, e, i == 15 ? "unsolvable" : "solved"));
  }
  armstudy::cli::DiffTolerances tol;
  tol.studies.push_back({"placement", {}, {{"min_energy_J", {0, 0.03, false, "test"}}}});
  const auto d = armstudy::cli::diff_runs(base, now, tol, {});
  EXPECT_EQ(d.sweep_name, "ratio");
  EXPECT_EQ(d.sweep_rows_base, 20u);
  EXPECT_EQ(d.sweep_rows_new, 19u);
  std::vector<std::string> order;
  for (const auto& r : d.sweep) order.push_back(r.case_name);
  // beyond tolerance first (removed, status change: infinite; then -20 %, +5 %), then +1 %
  EXPECT_EQ(order, (std::vector<std::string>{"p-115", "p-119", "p-107", "p-111", "p-103"}));
  EXPECT_TRUE(d.sweep[2].beyond);
  EXPECT_NEAR(d.sweep[2].score, 0.2, 1e-12);
  EXPECT_EQ(d.sweep[2].figure, "min_energy_J");
  EXPECT_FALSE(d.sweep[4].beyond) << "1 % is within the 3 % tolerance";
  EXPECT_EQ(d.beyond_count(), 4u);
  // the run time changed everywhere it changed the energy, and never counts
  for (const auto& c : d.cases)
    for (const auto& f : c.figures)
      if (f.name == "run_time_s") {
        EXPECT_FALSE(f.beyond) << c.name;
      }
  const std::string md = armstudy::report::diff_markdown(d);
  EXPECT_LT(md.find("| p-107 |"), md.find("| p-103 |"));
  // failures first: the case that no longer solves heads the table of cases that moved
  EXPECT_EQ(table_cases(md, "## Beyond tolerance"),
            (std::vector<std::string>{"p-115", "p-107", "p-111", "p-119"}))
      << md;
  EXPECT_NE(md.find("## Sweep ratio: 5 of 20 row(s) changed, largest change first"),
            std::string::npos)
      << md;
}

TEST(DiffRuns, MarkdownStaysUnderItsLimitWithFailuresFirst) {
  std::vector<CaseOutput> base, now;
  for (int i = 0; i < 3000; ++i) {
    base.push_back(sweep_case("case-" + std::to_string(i), 0.1, 1.0));
    now.push_back(sweep_case("case-" + std::to_string(i), 0.1, i % 2 ? 1.0 + 1e-9 : 2.0));
  }
  armstudy::cli::DiffTolerances tol;
  tol.fallback = armstudy::report::FigureTolerance{0, 1e-6, false, "test"};
  const auto d = armstudy::cli::diff_runs(base, now, tol, {});
  EXPECT_EQ(d.beyond_count(), 1500u);
  const std::string md = armstudy::report::diff_markdown(d, 64 * 1024);
  EXPECT_LE(md.size(), 64u * 1024);
  EXPECT_NE(md.find("Truncated"), std::string::npos);
  EXPECT_LT(md.find("## Beyond tolerance"), md.find("Truncated"));
}

TEST(DiffTolerances, LookupOrderPatternsAndRunTimes) {
  const fs::path f = armstudy::testing::fresh_dir("diff_tol") / "t.yaml";
  write_text(f,
             "default: {rel: 1.0e-6}\nframes: {channel: 3, pixels: 10}\nstudies:\n  placement:\n"
             "    default: {abs: 0.5}\n    figures:\n      \"root_*_m[*]\": {abs: 0.001}\n"
             "      \"root_x_m[cycloidal,1]\": {abs: 0.002}\n  throwing:\n    figures:\n"
             "      idp_run_time_s: {rel: 0.5}\n");
  const auto t = armstudy::cli::load_diff_tolerances(f.string());
  EXPECT_EQ(t.pixel_channel, 3);
  EXPECT_EQ(t.pixels, 10u);
  EXPECT_EQ(t.lookup("placement", "root_x_m[cycloidal,1]").abs,
            0.002);  // exact name before patterns
  EXPECT_EQ(t.lookup("placement", "root_y_m[poly345,2]").abs, 0.001);
  EXPECT_EQ(t.lookup("placement", "min_energy_J").abs, 0.5);
  EXPECT_EQ(t.lookup("placement", "min_energy_J").source, f.string() + ":5:14");
  EXPECT_EQ(t.lookup("pendulum", "energy_exchanged_J").rel, 1e-6);
  EXPECT_TRUE(t.lookup("time_optimal", "run_time_s[exact]").ignore);
  EXPECT_FALSE(t.lookup("throwing", "idp_run_time_s").ignore);  // named: held to its tolerance
  EXPECT_EQ(t.lookup("throwing", "idp_run_time_s").rel, 0.5);
  EXPECT_THROW(armstudy::cli::load_diff_tolerances((f.parent_path() / "none.yaml").string()),
               armstudy::cases::CaseErrors);
  // the CI example's file reads
  const auto ci = armstudy::cli::load_diff_tolerances(
      (fs::path(ARMSTUDY_SOURCE_DIR) / "examples/ci/diff-tolerances.yaml").string());
  EXPECT_EQ(ci.pixel_channel, 8);
  EXPECT_TRUE(ci.lookup("throwing", "idp_run_time_s").ignore);
  EXPECT_EQ(ci.lookup("throwing", "energy_idp_J").rel, 1e-5);
}

}  // namespace
