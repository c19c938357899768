// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The armstudy command as a user runs it: help, version, usage errors, exit codes,
// results.json contents and atomic output.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cases/case_info.hpp"
#include "testing/cli.hpp"
#include "testing/files.hpp"
#include "version.hpp"

namespace {
namespace fs = std::filesystem;

using armstudy::testing::CliRun;
using armstudy::testing::run_cli;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

fs::path temp_dir(const std::string& tag) {
  const fs::path d =
      fs::temp_directory_path() / ("armstudy_e2e_" + tag + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  return d;
}

using armstudy::testing::kSource;

TEST(Cli, HelpAndVersionExitZero) {
  const CliRun help = run_cli("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("run"), std::string::npos);
  EXPECT_NE(help.output.find("validate"), std::string::npos);
  for (const char* sub : {"run --help", "validate --help"}) {
    const CliRun r = run_cli(sub);
    EXPECT_EQ(r.exit_code, 0) << sub;
    EXPECT_NE(r.output.find("Usage"), std::string::npos) << sub;
  }
  const CliRun v = run_cli("--version");
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_EQ(v.output.rfind("armstudy ", 0), 0u) << v.output;
}

// --version names armstudy's version and commit and every library and browser it runs
// with, and never waits for a browser that does not answer
TEST(Cli, VersionNamesTheLibrariesAndTheBrowser) {
  const fs::path dir = temp_dir("version");
  fs::create_directories(dir);
  const fs::path hanging = dir / "hanging-browser";
  { std::ofstream(hanging) << "#!/bin/sh\nsleep 600\n"; }
  fs::permissions(hanging, fs::perms::owner_all);
  using armstudy::testing::Bounds;
  using armstudy::testing::run_bounded;
  const auto v = run_bounded({"--version"}, Bounds{.timeout_s = 60});
  ASSERT_EQ(v.exit_code, 0) << v.output;
  EXPECT_EQ(v.output.rfind(std::string("armstudy ") + armstudy::kVersion + " (commit ", 0), 0u)
      << v.output;
  for (const char* line : {"\nMuJoCo 2.", "\nOSMesa/Mesa ", "Mesa 2", "\nEigen 3.", "\nyaml-cpp 0.",
                           "\nNLopt 2.", "\nbrowser (--pdf) "})
    EXPECT_NE(v.output.find(line), std::string::npos) << line << " in\n" << v.output;
  const auto absent = run_bounded(
      {"--version"}, Bounds{.timeout_s = 60, .env = {{"ARMSTUDY_CHROMIUM", "/nonexistent"}}});
  EXPECT_NE(absent.output.find("\nbrowser (--pdf) not found"), std::string::npos) << absent.output;
  // a browser that never answers is killed (its shell and its sleep) after 5 s
  const auto hung = run_bounded(
      {"--version"}, Bounds{.timeout_s = 60, .env = {{"ARMSTUDY_CHROMIUM", hanging.string()}}});
  EXPECT_FALSE(hung.hung);
  EXPECT_EQ(hung.exit_code, 0);
  EXPECT_NE(hung.output.find("\nbrowser (--pdf) " + hanging.string() + ": version unknown"),
            std::string::npos)
      << hung.output;
  fs::remove_all(dir);
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(run_cli("").exit_code, 2);
  EXPECT_EQ(run_cli("run").exit_code, 2);                 // missing required cases
  EXPECT_EQ(run_cli("run --bogus x.yaml").exit_code, 2);  // unknown option
  EXPECT_EQ(run_cli("frobnicate").exit_code, 2);
  EXPECT_EQ(run_cli("run /nonexistent/case.yaml").exit_code, 2);
  EXPECT_EQ(run_cli("run --jobs 0 " + (kSource / "reports/cases/placement-example-2.yaml").string())
                .exit_code,
            2);
}

TEST(Cli, ValidateAcceptsEveryBundledCase) {
  for (const auto& e : fs::directory_iterator(kSource / "reports/cases")) {
    if (e.path().extension() != ".yaml") continue;
    const CliRun r = run_cli("validate " + e.path().string());
    EXPECT_EQ(r.exit_code, 0) << e.path() << "\n" << r.output;
  }
}

TEST(Cli, RunWritesResultsJsonWithProvenance) {
  const fs::path out = temp_dir("results");
  const fs::path c = kSource / "reports/cases/placement-example-2.yaml";
  const CliRun r = run_cli("run --no-render --out " + out.string() + " " + c.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(read_text(out / "placement-example-2" / "results.json"));
  EXPECT_EQ(j["study"], "placement");
  EXPECT_FALSE(j["armstudy_version"].get<std::string>().empty());
  EXPECT_EQ(j["case"]["name"], "placement-example-2");
  EXPECT_EQ(j["case"]["path"], c.string());
  EXPECT_EQ(j["case"]["sha256"], armstudy::cases::sha256_hex(read_text(c)));
  EXPECT_TRUE(j.contains("placement"));
  EXPECT_EQ(j["status"], "solved");
  // nothing temporary is left beside the case folder
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_EQ(e.path().filename().string().find(".placement"), std::string::npos) << e.path();
  fs::remove_all(out);
}

TEST(Cli, BadCaseLeavesAnEarlierReportUntouchedAndWritesNothing) {
  const fs::path out = temp_dir("atomic");
  const fs::path work = temp_dir("atomic_cases");
  fs::create_directories(work);
  const fs::path good = work / "case.yaml";
  fs::copy_file(kSource / "reports/cases/placement-example-2.yaml", good);
  ASSERT_EQ(run_cli("run --no-render --out " + out.string() + " " + good.string()).exit_code, 0);
  const fs::path results = out / "placement-example-2" / "results.json";
  const std::string before = read_text(results);
  // every file of the output folder (case folder, index, summary, junit) by content
  const auto snapshot = [&] {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(out))
      if (e.is_regular_file()) files[fs::relative(e.path(), out).string()] = read_text(e.path());
    return files;
  };
  const auto files_before = snapshot();

  // same case name, but a bad value: exit 2 and the earlier report stays as it was
  std::string text = read_text(good);
  text += "\ngravity: -1\n";
  std::ofstream(good, std::ios::trunc) << text;
  const CliRun bad = run_cli("run --no-render --out " + out.string() + " " + good.string());
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find(good.string() + ":"), std::string::npos) << bad.output;
  EXPECT_EQ(read_text(results), before);
  EXPECT_TRUE(snapshot() == files_before)
      << "the bad run changed or added files in the output folder";
  fs::remove_all(out);
  fs::remove_all(work);
}

TEST(Cli, DuplicateCaseNamesAreRejectedBeforeAnythingRuns) {
  const fs::path out = temp_dir("dupnames");
  const fs::path c = kSource / "reports/cases/placement-example-2.yaml";
  const CliRun r =
      run_cli("run --no-render --out " + out.string() + " " + c.string() + " " + c.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("expected unique names"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

// progress on stderr, plain lines in a log; on stdout one line per case: its answer
TEST(Cli, ProgressIsPlainLinesWithoutATerminalAndTheAnswerIsOnStdout) {
  const fs::path out = temp_dir("progress");
  fs::create_directories(out.parent_path());
  const fs::path err = out.string() + ".stderr";
  const fs::path c = kSource / "reports/cases/placement-example-2.yaml";
  // stdout alone through the pipe; stderr into a file
  const CliRun r =
      armstudy::testing::run_shell("{ " + armstudy::testing::kBin + " run --no-render --out " +
                                   out.string() + " " + c.string() + " 2>" + err.string() + "; }");
  const std::string progress = read_text(err);
  ASSERT_EQ(r.exit_code, 0) << r.output << progress;
  EXPECT_EQ(progress.find('\r'), std::string::npos) << "no carriage returns in a log";
  EXPECT_EQ(progress.find("\033["), std::string::npos) << "no terminal escapes in a log";
  EXPECT_NE(progress.find("placement-example-2: "), std::string::npos) << progress;
  EXPECT_EQ(progress.find("done: "), std::string::npos) << "the answer is on stdout\n" << progress;
  const std::string line = "done: placement-example-2 (placement, ";
  EXPECT_EQ(r.output.rfind(line, 0), 0u) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_NE(r.output.find(", " + (out / "placement-example-2").string() + "): least energy "),
            std::string::npos)
      << r.output;
  fs::remove_all(out);
  fs::remove(err);
}

// run --json: one JSON document on stdout (each case's result, exit code, seconds, folder,
// answer); results.json echoes the case's inputs and its run time, which junit.xml carries
TEST(Cli, RunJsonSummarisesTheRunOnStdoutAndJunitHasTimes) {
  const fs::path out = temp_dir("json");
  fs::create_directories(out.parent_path());
  const fs::path err = out.string() + ".stderr";
  const fs::path c = kSource / "reports/cases/pendulum.yaml";
  const CliRun r = armstudy::testing::run_shell(
      "{ " + armstudy::testing::kBin + " run --no-render --no-sensitivity --json --out " +
      out.string() + " " + c.string() + " 2>" + err.string() + "; }");
  ASSERT_EQ(r.exit_code, 0) << r.output << read_text(err);
  const auto j = nlohmann::json::parse(r.output);  // nothing else on stdout
  EXPECT_EQ(j["exit_code"], 0);
  EXPECT_EQ(j["out"], out.string());
  ASSERT_EQ(j["cases"].size(), 1u) << j.dump(2);
  const auto& k = j["cases"][0];
  EXPECT_EQ(k["name"], "pendulum");
  EXPECT_EQ(k["study"], "pendulum");
  EXPECT_EQ(k["result"], "done");
  EXPECT_EQ(k["folder"], (out / "pendulum").string());
  EXPECT_GT(k["seconds"].get<double>(), 0.0);
  const auto results = nlohmann::json::parse(read_text(out / "pendulum/results.json"));
  EXPECT_EQ(k["message"], results["message"]);
  EXPECT_NE(read_text(err).find("done: pendulum"), std::string::npos) << "the lines go to stderr";
  // the inputs echoed as the file writes them, the run time measured
  const auto& inputs = results["case"]["inputs"];
  EXPECT_EQ(inputs["study"], "pendulum");
  EXPECT_EQ(inputs["name"], "pendulum");
  EXPECT_GE(inputs.size(), 5u) << inputs.dump(2);
  const double run_s = results["run_time_s"];
  EXPECT_GT(run_s, 0.0);
  EXPECT_LE(run_s, k["seconds"].get<double>());
  const std::string junit = read_text(out / "junit.xml");
  char expected[96];
  std::snprintf(expected, sizeof expected, "name=\"solve\" time=\"%.3f\"", run_s);
  EXPECT_NE(junit.find(expected), std::string::npos) << junit;
  std::snprintf(expected, sizeof expected,
                "<testsuite name=\"pendulum\" tests=\"%zu\" "
                "failures=\"0\" errors=\"0\" time=\"%.3f\"",
                results["checks"].size() + 1, run_s);
  EXPECT_NE(junit.find(expected), std::string::npos) << junit;
  fs::remove_all(out);
  fs::remove(err);
}

// run --json answers in JSON when the run stops before any case runs (a missing or bad case
// file, an --out that is a file; an unknown option or a bad --shard stop the same way): one
// document on stdout, with the exit code and the error, and nothing written
TEST(Cli, RunJsonAnswersInJsonWhenNoCaseRuns) {
  const fs::path dir = temp_dir("json_refused");
  fs::create_directories(dir);
  const std::string c = (kSource / "reports/cases/pendulum.yaml").string();
  std::ofstream(dir / "bad.yaml") << "study: pendulum\nname: bad\npendulum: {duration_s: -1}\n";
  std::ofstream(dir / "a-file") << "not a folder\n";
  const std::string out = (dir / "out").string();
  struct Refused {
    std::string args, says;
  };
  for (const Refused& r : std::vector<Refused>{
           {"--out " + out + " " + (dir / "missing.yaml").string(), "missing.yaml"},
           {"--out " + out + " " + (dir / "bad.yaml").string(), "duration_s"},
           {"--out " + (dir / "a-file").string() + " " + c, "a file, not a folder"}}) {
    const CliRun run = armstudy::testing::run_shell("{ " + armstudy::testing::kBin +
                                                    " run --json " + r.args + " 2>/dev/null; }");
    EXPECT_EQ(run.exit_code, 2) << r.args << "\n" << run.output;
    nlohmann::json j;
    ASSERT_NO_THROW(j = nlohmann::json::parse(run.output)) << r.args << "\n" << run.output;
    EXPECT_EQ(j["exit_code"], 2) << j.dump(2);
    EXPECT_NE(j["error"].get<std::string>().find(r.says), std::string::npos) << j.dump(2);
    EXPECT_TRUE(j["cases"].empty()) << j.dump(2);
  }
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

// without --out a run writes armstudy-out/ in the current folder and names it on stderr; the
// repository's .gitignore ignores that folder wherever a run is started in it, so a run from
// the source tree never writes into a tracked folder
TEST(Cli, WithoutOutARunWritesArmstudyOutAndSaysSo) {
  const fs::path cwd = temp_dir("default_out");
  fs::create_directories(cwd);
  // shard 1 of 2 of one case: no case runs, but the run's folder and summaries are written
  const CliRun r = armstudy::testing::run_shell("cd " + cwd.string() + " && " +
                                                armstudy::testing::kBin + " run --shard 1/2 " +
                                                (kSource / "reports/cases/pendulum.yaml").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const std::string said = "no --out given: the output goes to " + (cwd / "armstudy-out").string();
  EXPECT_NE(r.output.find(said), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_directory(cwd / "armstudy-out")) << r.output;
  size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(cwd)) ++entries;
  EXPECT_EQ(entries, 1u) << "only armstudy-out/ is written in the current folder";
  fs::remove_all(cwd);
  if (!fs::exists(kSource / ".git")) GTEST_SKIP() << "the source is not a git checkout";
  for (const char* p : {"armstudy-out/pendulum/results.json", "src/armstudy-out/summary.md",
                        "reports/cases/armstudy-out/index.html"}) {
    const CliRun ignored =
        armstudy::testing::run_shell("git -C " + kSource.string() + " check-ignore -q " + p);
    EXPECT_EQ(ignored.exit_code, 0) << p << " is not ignored by the repository's .gitignore";
  }
}

// an unknown option is named, with the command's options, whatever else it causes
TEST(Cli, AnUnknownOptionIsNamed) {
  const std::string c = (kSource / "reports/cases/pendulum.yaml").string();
  for (const std::string& args : {"run " + c + " --jobz 2", "run --jobz 2 " + c}) {
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_NE(r.output.find("armstudy run: unknown option '--jobz' (did you mean '--jobs'?); "
                            "expected one of: "),
              std::string::npos)
        << args << "\n"
        << r.output;
    EXPECT_EQ(r.output.find("Path does not exist"), std::string::npos) << r.output;
  }
  const CliRun v = run_cli("validate --alow-large " + c);
  EXPECT_EQ(v.exit_code, 2);
  EXPECT_NE(v.output.find("armstudy validate: unknown option '--alow-large' (did you mean "
                          "'--allow-large'?)"),
            std::string::npos)
      << v.output;
}

}  // namespace

namespace {

// the bundled example 1 asks for a line of length Lmax: it only fits as a singular motion,
// and its file says `expect: unsolvable`: done (exit 0); without that line it exits 1
TEST(Cli, UnsolvableCaseExitsOneWithItsReasonUnlessTheCaseExpectsIt) {
  const fs::path out = temp_dir("unsolvable");
  const fs::path c = kSource / "reports/cases/placement-example-1.yaml";
  const CliRun expected = run_cli("run --no-render --out " + out.string() + " " + c.string());
  EXPECT_EQ(expected.exit_code, 0) << expected.output;
  EXPECT_NE(
      expected.output.find("could not be solved, as the case expects: no admissible placement"),
      std::string::npos)
      << expected.output;
  const auto j = nlohmann::json::parse(read_text(out / "placement-example-1" / "results.json"));
  EXPECT_EQ(j["status"], "unsolvable");
  EXPECT_EQ(j["case"]["expect"], "unsolvable");
  EXPECT_NE(j["message"].get<std::string>().find("singular"), std::string::npos);
  EXPECT_NE(read_text(out / "junit.xml").find("failures=\"0\""), std::string::npos);

  const fs::path work = temp_dir("unsolvable_case");
  fs::create_directories(work);
  std::string text = read_text(c);
  text.replace(text.find("\nexpect: unsolvable") + 1, 18, "expect: solved");
  std::ofstream(work / "case.yaml") << text;
  const CliRun r =
      run_cli("run --no-render --out " + out.string() + " " + (work / "case.yaml").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("FAILED: placement-example-1"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("could not be solved: no admissible placement"), std::string::npos)
      << r.output;
  fs::remove_all(out);
  fs::remove_all(work);
}

// a joint that must move but may not: exit 1, the message names the limit and the place
TEST(Cli, InfeasibleTimeOptimalCaseExitsOneNamingTheLimitAndThePlace) {
  const fs::path out = temp_dir("to_infeasible");
  const fs::path work = temp_dir("to_infeasible_case");
  fs::create_directories(work);
  const fs::path c = work / "case.yaml";
  std::ofstream(c) << "study: time_optimal\nname: frozen-elbow\ntime_optimal:\n"
                      "  path: {kind: line, points_m: [[0.3, 0.1], [-0.1, 0.8]]}\n"
                      "  velocity_limit_rad_s: [3.0, 0.0]\n";
  const CliRun r = run_cli("run --no-render --out " + out.string() + " " + c.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("joint 2 velocity limit 0 rad/s at s = 0.000 m"), std::string::npos)
      << r.output;
  const auto j = nlohmann::json::parse(read_text(out / "frozen-elbow" / "results.json"));
  EXPECT_EQ(j["status"], "unsolvable");
  fs::remove_all(out);
  fs::remove_all(work);
}

}  // namespace

namespace {

// `armstudy init STUDY`: a case of every study, on stdout and with -o, that validates; the
// fast studies' also run (--no-render); -o replaces only a case init wrote, never a user's
// file (nor an init case edited since)
TEST(Cli, InitWritesACaseOfEveryStudyThatValidatesAndRuns) {
  const fs::path dir = temp_dir("init");
  fs::create_directories(dir);
  for (const char* study : {"placement", "pendulum", "throwing", "time_optimal"}) {
    const fs::path file = dir / (std::string(study) + ".yaml");
    const CliRun printed = armstudy::testing::run_shell("{ " + armstudy::testing::kBin + " init " +
                                                        study + " 2>/dev/null; }");
    ASSERT_EQ(printed.exit_code, 0) << study << "\n" << printed.output;
    EXPECT_EQ(printed.output.rfind("# yaml-language-server: $schema=", 0), 0u) << printed.output;
    const CliRun written = run_cli(std::string("init ") + study + " -o " + file.string());
    ASSERT_EQ(written.exit_code, 0) << written.output;
    EXPECT_EQ(read_text(file), printed.output) << study;
    const CliRun valid = run_cli("validate " + file.string());
    EXPECT_EQ(valid.exit_code, 0) << study << "\n" << valid.output << "\n" << printed.output;
  }
  for (const char* study : {"pendulum", "time_optimal"}) {
    const fs::path file = dir / (std::string(study) + ".yaml");
    const CliRun r = run_cli("run --no-render --no-sensitivity --out " + (dir / "out").string() +
                             " " + file.string());
    EXPECT_EQ(r.exit_code, 0) << study << "\n" << r.output;
  }
  // a file init wrote is replaced; one the user wrote, or edited, is not
  const fs::path file = dir / "pendulum.yaml";
  EXPECT_EQ(run_cli("init pendulum -o " + file.string()).exit_code, 0);
  { std::ofstream(file, std::ios::app) << "# mine\n"; }
  const std::string edited = read_text(file);
  const CliRun refused = run_cli("init pendulum -o " + file.string());
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("armstudy never replaces a file it did not write"),
            std::string::npos)
      << refused.output;
  EXPECT_EQ(read_text(file), edited);
  const CliRun unknown = run_cli("init pendulm");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.output.find("unknown study 'pendulm'; expected one of: placement"),
            std::string::npos)
      << unknown.output;
  fs::remove_all(dir);
}

}  // namespace
