// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Never hang, never crash: a FIFO, device or link loop where armstudy reads a
// file, PLplot without its driver, too few open files and every study's failure path end
// promptly in a message and an exit code (2 bad input, 1 unsolvable, 3 runtime), never in
// a prompt, a wait for a writer or a signal. Each run is bounded (testing::run_bounded):
// a hang fails the test instead of the suite.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "testing/cli.hpp"
#include "testing/files.hpp"

namespace {
namespace fs = std::filesystem;
using armstudy::testing::BoundedRun;
using armstudy::testing::Bounds;
using armstudy::testing::fresh_dir;
using armstudy::testing::run_bounded;
using armstudy::testing::slurp;

using armstudy::testing::kSource;

bool has(const BoundedRun& r, const std::string& text) {
  return r.output.find(text) != std::string::npos;
}

std::string how(const BoundedRun& r) {
  return (r.hung ? "HUNG; " : "") + (r.signal ? "signal " + std::to_string(r.signal) + "; " : "") +
         "exit " + std::to_string(r.exit_code) + "\n" + r.output;
}

// the bundled pendulum case (quick: 0.1 s without frames) under another name, with one
// piece of its text replaced
fs::path pendulum_case(const fs::path& dir, const std::string& name,
                       const std::string& replace_from = "", const std::string& replace_to = "") {
  std::string text = slurp(kSource / "reports/cases/pendulum.yaml");
  text.replace(text.find("\nname: pendulum") + 7, 8, name);
  if (!replace_from.empty()) text.replace(text.find(replace_from), replace_from.size(), replace_to);
  const fs::path p = dir / (name + ".yaml");
  std::ofstream(p) << text;
  return p;
}

// an output folder of one pendulum case run without frames
fs::path pendulum_output(const fs::path& dir) {
  const fs::path c = pendulum_case(dir, "swing");
  const fs::path out = dir / "out";
  const BoundedRun r = run_bounded({"run", "--no-render", "--out", out.string(), c.string()});
  EXPECT_EQ(r.exit_code, 0) << how(r);
  return out;
}

TEST(NeverHang, ResultsJsonThatIsAFifoIsRefusedByRunMergeAndDiff) {
  const fs::path d = fresh_dir("fifo_results");
  const fs::path out = pendulum_output(d);
  const fs::path other = d / "other";
  fs::copy(out, other, fs::copy_options::recursive);
  fs::remove(out / "swing" / "results.json");
  ASSERT_EQ(::mkfifo((out / "swing" / "results.json").c_str(), 0600), 0);

  const BoundedRun run =
      run_bounded({"run", "--no-render", "--out", out.string(), (d / "swing.yaml").string()},
                  {.timeout_s = 30});
  EXPECT_EQ(run.exit_code, 2) << how(run);
  EXPECT_TRUE(has(run, "its results.json is not a regular file")) << how(run);
  const BoundedRun merge = run_bounded({"merge", out.string()}, {.timeout_s = 30});
  EXPECT_EQ(merge.exit_code, 2) << how(merge);
  EXPECT_TRUE(has(merge, "is a FIFO (named pipe)")) << how(merge);
  for (const auto& [a, b] : {std::pair{out, other}, std::pair{other, out}}) {
    const BoundedRun diff = run_bounded(
        {"diff", a.string(), b.string(), "--out", (d / "diff").string()}, {.timeout_s = 30});
    EXPECT_EQ(diff.exit_code, 2) << how(diff);
    EXPECT_TRUE(has(diff, "is a FIFO (named pipe)")) << how(diff);
  }
  EXPECT_FALSE(fs::exists(d / "diff" / "diff.md"));
  fs::remove_all(d);
}

TEST(NeverHang, ResultsJsonThatIsALinkIsRefusedByMerge) {
  const fs::path d = fresh_dir("link_results");
  const fs::path out = pendulum_output(d);
  fs::rename(out / "swing" / "results.json", d / "elsewhere.json");
  fs::create_symlink(d / "elsewhere.json", out / "swing" / "results.json");
  const BoundedRun merge = run_bounded({"merge", out.string()}, {.timeout_s = 30});
  EXPECT_EQ(merge.exit_code, 2) << how(merge);
  EXPECT_TRUE(has(merge, "is a symbolic link; expected a regular results.json file")) << how(merge);
  fs::remove_all(d);
}

TEST(NeverHang, FrameThatIsAFifoOrADeviceIsRefusedByDiff) {
  const fs::path d = fresh_dir("fifo_frame");
  const fs::path base = pendulum_output(d);
  // one frame listed in both runs: the base's a file, the new one's a FIFO, then a device
  auto j = nlohmann::json::parse(slurp(base / "swing" / "results.json"));
  j["frames"] = {"strip.png"};
  std::ofstream(base / "swing" / "results.json") << j.dump();
  std::ofstream(base / "swing" / "strip.png") << "not a png, but bytes";
  const fs::path now = d / "now";
  fs::copy(base, now, fs::copy_options::recursive);
  fs::remove(now / "swing" / "strip.png");
  ASSERT_EQ(::mkfifo((now / "swing" / "strip.png").c_str(), 0600), 0);
  BoundedRun r = run_bounded({"diff", base.string(), now.string(), "--out", (d / "diff").string()},
                             {.timeout_s = 30});
  EXPECT_EQ(r.exit_code, 2) << how(r);
  EXPECT_TRUE(has(r, "strip.png: is a FIFO (named pipe); expected a regular PNG frame")) << how(r);
  EXPECT_FALSE(fs::exists(d / "diff" / "diff.md"));
  // a link to a device is a path out of the case folder: never opened, a difference named
  // in diff.md (the confinement of paths from results.json)
  fs::remove(now / "swing" / "strip.png");
  fs::create_symlink("/dev/zero", now / "swing" / "strip.png");
  r = run_bounded({"diff", base.string(), now.string(), "--out", (d / "diff").string()},
                  {.timeout_s = 30});
  EXPECT_EQ(r.exit_code, 1) << how(r);
  EXPECT_NE(slurp(d / "diff" / "diff.md").find("a path through a symlink out of the case folder"),
            std::string::npos);
  fs::remove_all(d);
}

// the run's index.html and summary.md list every case folder of --out: another folder's
// results.json that is a FIFO is never opened (an unreadable row in the index; no summary,
// exit 2, naming it)
TEST(NeverHang, AFifoResultsJsonInAnotherFolderOfOutIsNotReadForTheIndex) {
  const fs::path d = fresh_dir("fifo_other_results");
  const fs::path out = d / "out";
  fs::create_directories(out / "someone-else");
  ASSERT_EQ(::mkfifo((out / "someone-else" / "results.json").c_str(), 0600), 0);
  const fs::path c = pendulum_case(d, "swing");
  const BoundedRun r =
      run_bounded({"run", "--no-render", "--out", out.string(), c.string()}, {.timeout_s = 60});
  EXPECT_FALSE(r.hung) << how(r);
  // the case is done; the run's summary cannot count a case whose result is a FIFO
  EXPECT_EQ(r.exit_code, 2) << how(r);
  EXPECT_TRUE(has(r, "someone-else/results.json: is a FIFO (named pipe)")) << how(r);
  EXPECT_TRUE(fs::exists(out / "swing" / "results.json"));
  EXPECT_NE(slurp(out / "index.html").find("someone-else"), std::string::npos);
  fs::remove_all(d);
}

TEST(NeverHang, TolerancesThatAreAFifoOrALinkLoopAreRefused) {
  const fs::path d = fresh_dir("fifo_tolerances");
  const fs::path out = pendulum_output(d);
  ASSERT_EQ(::mkfifo((d / "tol.yaml").c_str(), 0600), 0);
  fs::create_symlink(d / "loop_b.yaml", d / "loop_a.yaml");
  fs::create_symlink(d / "loop_a.yaml", d / "loop_b.yaml");
  for (const char* f : {"tol.yaml", "loop_a.yaml"}) {
    const BoundedRun r = run_bounded({"diff", out.string(), out.string(), "--out",
                                      (d / "diff").string(), "--tolerances", (d / f).string()},
                                     {.timeout_s = 30});
    EXPECT_EQ(r.exit_code, 2) << f << ": " << how(r);
    EXPECT_TRUE(has(r, "is a FIFO (named pipe)") || has(r, "symbolic links (a link loop?)"))
        << how(r);
  }
  fs::remove_all(d);
}

// PLplot without its drivers fell back to asking for a device on stdin: it hung with stdin
// open, and exited 1 ("unsolvable") with stdin at /dev/null
TEST(NeverHang, PlplotWithoutItsDriverIsARuntimeErrorNamingPlplotDrvDir) {
  const fs::path d = fresh_dir("plplot_driver");
  const fs::path c = pendulum_case(d, "swing");
  for (bool stdin_open : {true, false}) {
    Bounds b{30, stdin_open, 0, {{"PLPLOT_DRV_DIR", "/nonexistent"}}};
    const BoundedRun r =
        run_bounded({"run", "--no-render", "--out", (d / "out").string(), c.string()}, b);
    EXPECT_EQ(r.exit_code, 3) << how(r);
    EXPECT_TRUE(has(r, "PLPLOT_DRV_DIR is '/nonexistent'")) << how(r);
    EXPECT_FALSE(has(r, "Enter device number")) << how(r);
  }
  EXPECT_FALSE(fs::exists(d / "out" / "swing")) << "no report without its plots";
  fs::remove_all(d);
}

// `ulimit -n 10` with frames: killed by SIGPIPE (exit 141) without a word
TEST(NeverHang, TooFewOpenFilesIsARuntimeErrorBeforeAnythingIsWritten) {
  const fs::path d = fresh_dir("open_files");
  const fs::path c = pendulum_case(d, "swing");
  const BoundedRun r =
      run_bounded({"run", "--out", (d / "out").string(), c.string()}, {60, false, 10});
  EXPECT_EQ(r.exit_code, 3) << how(r);
  EXPECT_TRUE(has(r, "the limit of open files (ulimit -n) is 10")) << how(r);
  EXPECT_FALSE(fs::exists(d / "out"));
  // a command that reads only the case file runs under the same limit
  const BoundedRun v = run_bounded({"validate", c.string()}, {30, false, 10});
  EXPECT_EQ(v.exit_code, 0) << how(v);
  fs::remove_all(d);
}

// every study's failure path ends in its message and exit 1, never a signal (a failed
// pendulum integration crashed with SIGSEGV in its results section)
TEST(NeverCrash, EveryStudysFailurePathExitsOneWithItsMessage) {
  const fs::path d = fresh_dir("study_failures");
  struct Failing {
    std::string study, name;
    fs::path file;
    std::string message;
  };
  std::string placement = slurp(kSource / "reports/cases/placement-example-1.yaml");
  placement.replace(placement.find("\nexpect: unsolvable"), 19, "");
  std::ofstream(d / "placement.yaml") << placement;
  std::ofstream(d / "time_optimal.yaml")
      << "study: time_optimal\nname: frozen-elbow\ntime_optimal:\n"
         "  path: {kind: line, points_m: [[0.3, 0.1], [-0.1, 0.8]]}\n"
         "  velocity_limit_rad_s: [3.0, 0.0]\n";
  std::ofstream(d / "throwing.yaml")
      << "study: throwing\nname: throw-too-high\nthrowing:\n  task: {landing_height_m: 50.0}\n"
         "  motors: {power_max_W: 1000, current_max_A: 100}\n"
         "  constraints: {release_tolerance_deg: 30}\n"  // a feasible throw, too low
         "  idp: {max_passes: 2, seeds: 1, iterations: 1, stages: 4, steps_per_stage: 10, "
         "candidates: 2}\n  nlopt: {enabled: false}\n  threads: 1\n";
  const Failing cases[] = {
      {"placement", "placement-example-1", d / "placement.yaml",
       "could not be solved: no admissible placement"},
      {"time_optimal", "frozen-elbow", d / "time_optimal.yaml",
       "the joint 2 velocity limit 0 rad/s at s = 0.000 m allows no motion"},
      {"throwing", "throw-too-high", d / "throwing.yaml",
       "could not be solved: the ball never reaches"},
      {"pendulum", "pendulum-too-many-steps",
       pendulum_case(d, "pendulum-too-many-steps", "max_steps: 10000000", "max_steps: 100"),
       "could not be solved: the pendulum integration failed: integrate_dopri5: too many steps"}};
  for (const auto& f : cases) {
    const fs::path out = d / ("out_" + f.study);
    const BoundedRun r =
        run_bounded({"run", "--no-render", "--out", out.string(), f.file.string()});
    EXPECT_EQ(r.exit_code, 1) << f.study << ": " << how(r);
    EXPECT_TRUE(has(r, f.message)) << f.study << ": " << how(r);
    // the failed case still has its report and results.json, status unsolvable
    const auto j = nlohmann::json::parse(slurp(out / f.name / "results.json"), nullptr, false);
    EXPECT_EQ(j.value("status", ""), "unsolvable") << f.study;
  }
  fs::remove_all(d);
}

}  // namespace

namespace {

// a FIFO or /dev/zero among the templates (ARMSTUDY_TEMPLATE_DIR) hung the run after the
// solve, or read 2.2 GB and blamed memory: they are read as every input is, before the
// solve, and refused saying which and why
TEST(NeverHang, TemplatesThatAreAFifoOrADeviceAreRefusedBeforeTheSolve) {
  const fs::path d = fresh_dir("fifo_templates");
  const fs::path c = pendulum_case(d, "swing");
  for (const char* bad : {"report.css", "case.html"}) {
    const fs::path t = d / (std::string("templates-") + bad);
    fs::create_directories(t);
    for (const char* f : {"case.html", "index.html", "report.css"})
      fs::copy_file(kSource / "templates" / f, t / f);
    fs::remove(t / bad);
    if (std::string(bad) == "report.css")
      ASSERT_EQ(::mkfifo((t / bad).c_str(), 0600), 0);
    else
      fs::create_symlink("/dev/zero", t / bad);
    const BoundedRun r =
        run_bounded({"run", "--no-render", "--out", (d / "out").string(), c.string()},
                    {30, false, 0, {{"ARMSTUDY_TEMPLATE_DIR", t.string()}}});
    EXPECT_FALSE(r.hung) << how(r);
    EXPECT_EQ(r.exit_code, 2) << how(r);
    EXPECT_TRUE(has(r, "the report template " + (t / bad).string() + ": is a")) << how(r);
    EXPECT_TRUE(has(r, "is a FIFO (named pipe)") || has(r, "is a device")) << how(r);
    EXPECT_TRUE(has(r, "nothing was run")) << how(r);
    EXPECT_FALSE(has(r, "swing:")) << "refused before the solve\n" << how(r);
    EXPECT_FALSE(fs::exists(d / "out" / "swing"));
  }
  fs::remove_all(d);
}

// an empty --tolerances file asked for "a YAML mapping with 'study:' and 'name:'" (a case)
TEST(NeverHang, AnEmptyTolerancesFileAsksForTolerancesNotACase) {
  const fs::path d = fresh_dir("empty_tolerances");
  const fs::path out = pendulum_output(d);
  std::ofstream(d / "tol.yaml") << "# nothing yet\n";
  const BoundedRun r =
      run_bounded({"diff", out.string(), out.string(), "--out", (d / "diff").string(),
                   "--tolerances", (d / "tol.yaml").string()},
                  {.timeout_s = 30});
  EXPECT_EQ(r.exit_code, 2) << how(r);
  EXPECT_TRUE(has(r, "the file is empty; expected a YAML mapping of tolerances")) << how(r);
  EXPECT_FALSE(has(r, "'study:'")) << how(r);
  fs::remove_all(d);
}

}  // namespace
