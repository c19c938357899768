// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// What armstudy writes when things go wrong: refused case names, failed writes (a
// read-only folder, a full standard output; a full disk is in fault_injection_test.sh),
// the skip-if-done key, and merge over broken results.json files. Each test checks the exit code,
// the message and that nothing was lost or left half-written.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "report/results_record.hpp"
#include "testing/cli.hpp"
#include "testing/files.hpp"
#include "testing/output_folder.hpp"

namespace {
namespace fs = std::filesystem;
using armstudy::testing::fresh_dir;
using armstudy::testing::slurp;
using armstudy::testing::snapshot;

using armstudy::testing::kBin;
using armstudy::testing::kSource;
using armstudy::testing::quick_case;
using armstudy::testing::run_cli;
using armstudy::testing::run_shell;
using CmdRun = armstudy::testing::CliRun;

// what a failed or stopped run must never leave: temporary files and scratch folders
std::string leftovers(const fs::path& dir) {
  std::string found;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string f = e.path().filename().string();
    if (f.find(".part") != std::string::npos || f.rfind(".armstudy-", 0) == 0)
      found += e.path().string() + "\n";
  }
  return found;
}

TEST(OutputSafety, CaseNamesOfRunLevelFilesAreRefusedAtValidate) {
  const fs::path d = fresh_dir("names_reserved");
  // (placement_root_loci.svg: a study's figure over all its cases on the index page)
  for (const char* name : {"index.html", "summary.md", "junit.xml", "report.css", "sweep",
                           "sweep.csv", "sweep.json", "placement_root_loci.svg"}) {
    const fs::path c = quick_case(d, name);
    const CmdRun r = run_cli("validate " + c.string());
    EXPECT_EQ(r.exit_code, 2) << name << "\n" << r.output;
    EXPECT_NE(r.output.find(c.string() + ": case name '" + name + "' is the name of " + name),
              std::string::npos)
        << r.output;
    const CmdRun run = run_cli("run --no-render --out " + (d / "out").string() + " " + c.string());
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_FALSE(fs::exists(d / "out")) << "nothing is written for a refused case";
  }
  EXPECT_EQ(run_cli("validate " + quick_case(d, "sweep-1").string()).exit_code, 0)
      << "only the exact names";
  fs::remove_all(d);
}

TEST(OutputSafety, TwoCasesWithOneNameAreRefusedAtValidate) {
  const fs::path d = fresh_dir("names_twice");
  const fs::path a = quick_case(d, "twice");
  fs::copy_file(a, d / "copy.yaml");
  const CmdRun r = run_cli("validate " + a.string() + " " + (d / "copy.yaml").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("case name 'twice' is also the name of " + a.string()), std::string::npos)
      << r.output;
  fs::remove_all(d);
}

TEST(OutputSafety, AFailedWriteToStandardOutputIsAnError) {
  const fs::path d = fresh_dir("stdout_full");
  quick_case(d, "listed");
  for (const char* args : {"list --json ", "list ", "validate "}) {
    const std::string target =
        std::string(args) == "validate " ? (d / "listed.yaml").string() : d.string();
    const CmdRun r = run_shell("{ " + kBin + " " + args + target + " >/dev/full; }");
    EXPECT_EQ(r.exit_code, 3) << args << r.output;
    EXPECT_NE(r.output.find("cannot write to standard output: No space left on device"),
              std::string::npos)
        << args << r.output;
  }
  EXPECT_EQ(run_shell(kBin + " list --json " + d.string() + " >/dev/null").exit_code, 0);
  fs::remove_all(d);
}

// the skip-if-done key: case file, armstudy version and commit, render option, and passed
TEST(OutputSafety, SkipIfDoneRedoesACaseWhoseOutputIsStaleOrFailed) {
  const fs::path d = fresh_dir("skip_key");
  const fs::path c = quick_case(d, "skip-me");
  const std::string run = "run --no-render --out " + (d / "out").string() + " " + c.string();
  ASSERT_EQ(run_cli(run).exit_code, 0);
  const fs::path rj = d / "out/skip-me/results.json";
  const auto original = nlohmann::json::parse(slurp(rj));
  EXPECT_EQ(original["run_options"]["render"], false);
  const CmdRun again = run_cli(run);
  EXPECT_EQ(again.exit_code, 0);
  EXPECT_NE(again.output.find("skipped 1 case(s)"), std::string::npos) << again.output;

  const std::map<std::string, std::function<void(nlohmann::json&)>> stale = {
      {"an older armstudy", [](nlohmann::json& j) { j["armstudy_version"] = "0.0.0"; }},
      {"another commit", [](nlohmann::json& j) { j["git_commit"] = "0123456789ab"; }},
      {"made with frames", [](nlohmann::json& j) { j["run_options"]["render"] = true; }},
      {"no render option", [](nlohmann::json& j) { j.erase("run_options"); }},
      {"a failed check", [](nlohmann::json& j) { j["checks"][0]["passed"] = false; }},
      {"unsolved", [](nlohmann::json& j) { j["status"] = "unsolvable"; }},
  };
  for (const auto& [what, edit] : stale) {
    nlohmann::json j = original;
    edit(j);
    std::ofstream(rj, std::ios::trunc) << j.dump(2);
    const CmdRun r = run_cli(run);
    EXPECT_EQ(r.exit_code, 0) << what << "\n" << r.output;
    EXPECT_EQ(r.output.find("skipped"), std::string::npos) << what << ": kept a stale report\n"
                                                           << r.output;
    const auto redone = nlohmann::json::parse(slurp(rj));
    EXPECT_EQ(redone["armstudy_version"], original["armstudy_version"]) << what;
    EXPECT_EQ(redone["status"], "solved") << what;
    EXPECT_TRUE(redone["checks"][0]["passed"].get<bool>()) << what;
  }
  fs::remove_all(d);
}

TEST(OutputSafety, MergeCountsAndNamesEveryUnreadableResultsJson) {
  const fs::path d = fresh_dir("merge_broken");
  const fs::path out = d / "out";
  ASSERT_EQ(run_cli("run --no-render --out " + out.string() + " " + quick_case(d, "good").string())
                .exit_code,
            0);
  const std::string good = slurp(out / "good/results.json");
  auto json_with = [&](const std::function<void(nlohmann::json&)>& edit) {
    auto j = nlohmann::json::parse(good);
    edit(j);
    return j.dump(2);
  };
  const std::map<std::string, std::pair<std::string, std::string>> broken = {
      {"truncated", {good.substr(0, good.size() / 2), "truncated or not JSON"}},
      {"empty", {"", "truncated or not JSON"}},
      {"wrong-type",
       {json_with([](nlohmann::json& j) { j["checks"][0]["passed"] = "yes"; }),
        "/checks/0/passed: expected a boolean, found a string"}},
      {"wrong-name",
       {json_with([](nlohmann::json& j) { j["case"]["name"] = 7; }),
        "/case/name: expected a string, found an integer"}},
      {"future-schema",
       {json_with(
            [](nlohmann::json& j) { j["schema_version"] = armstudy::report::kSchemaVersion + 1; }),
        "schema_version " + std::to_string(armstudy::report::kSchemaVersion + 1) +
            " is not one this armstudy reads"}},
      // the study's section is read into its typed result: a misspelt key is named, never "n/a"
      {"misspelt-key",
       {json_with([](nlohmann::json& j) {
          auto& o = j["placement"]["optima"][0];
          o["energy_j"] = o["energy_J"];
          o.erase("energy_J");
        }),
        "/placement/optima/0/energy_j: unknown key 'energy_j'; did you mean 'energy_J'?"}},
      {"section-missing",
       {json_with([](nlohmann::json& j) { j.erase("placement"); }), "/placement: missing"}},
      // the shared record is typed as well
      {"misspelt-shared-key",
       {json_with([](nlohmann::json& j) {
          auto& k = j["key_figures"][0];
          k["unti"] = k["unit"];
          k.erase("unit");
        }),
        "/key_figures/0/unti: unknown key 'unti'; did you mean 'unit'?"}},
  };
  for (const auto& [name, contents] : broken) {
    fs::create_directories(out / name);
    std::ofstream(out / name / "results.json") << contents.first;
  }
  const CmdRun r = run_cli("merge " + out.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(8 failed)"), std::string::npos) << r.output;
  const std::string md = slurp(out / "summary.md"), junit = slurp(out / "junit.xml");
  EXPECT_EQ(md.rfind("# armstudy: 9 case(s), 8 failed", 0), 0u) << md;
  for (const auto& [name, contents] : broken) {
    const std::string file = (out / name / "results.json").string();
    EXPECT_NE(r.output.find(file + ": " + contents.second), std::string::npos) << name << "\n"
                                                                               << r.output;
    EXPECT_NE(md.find("| " + name + " |"), std::string::npos) << name << "\n" << md;
    EXPECT_NE(md.find(contents.second), std::string::npos) << name;
    // no results.json read: no run time
    EXPECT_NE(junit.find("." + name + "\" name=\"solve\" time=\"0.000\"><failure"),
              std::string::npos)
        << name << "\n"
        << junit;
  }
  EXPECT_TRUE(leftovers(out).empty()) << leftovers(out);
  fs::remove_all(d);
}

TEST(OutputSafety, MergeOfAMissingFolderIsAnErrorAndCreatesNothing) {
  const fs::path d = fresh_dir("merge_missing");
  const CmdRun r = run_cli("merge " + (d / "nope").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find((d / "nope").string() + ": no such folder"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(d / "nope"));
  std::ofstream(d / "file") << "x";
  const CmdRun f = run_cli("merge " + (d / "file").string() + " --out " + (d / "out").string());
  EXPECT_EQ(f.exit_code, 2) << f.output;
  EXPECT_NE(f.output.find("not a folder"), std::string::npos) << f.output;
  EXPECT_FALSE(fs::exists(d / "out"));
  fs::remove_all(d);
}

// a folder the user may not write into: why, exit 3, nothing written, the report kept
TEST(OutputSafety, AReadOnlyOutputFolderSaysPermissionDeniedAndWritesNothing) {
  const fs::path d = fresh_dir("eacces");
  const fs::path c = quick_case(d, "read-only");
  const fs::path out = d / "out";
  ASSERT_EQ(run_cli("run --no-render --out " + out.string() + " " + c.string()).exit_code, 0);
  std::ofstream(c, std::ios::app) << "# changed\n";
  const auto before = snapshot(out);
  fs::permissions(out, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                           fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
  fs::permissions(d, fs::perms::all);
  fs::permissions(c, fs::perms::owner_read | fs::perms::owner_write | fs::perms::others_read);
  // root may write anywhere: run as nobody then
  const std::string as_user =
      ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
  const CmdRun r =
      run_shell(as_user + kBin + " run --no-render --out " + out.string() + " " + c.string());
  fs::permissions(out, fs::perms::owner_all, fs::perm_options::add);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find(": Permission denied"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
  EXPECT_TRUE(snapshot(out) == before) << "the read-only folder changed";
  fs::remove_all(d);
}

}  // namespace

namespace {

// a live run is known by the lock it holds, not by host name and pid: a scratch folder
// whose name claims this host and a pid that does not exist here (a run in another pid
// namespace, a container) is kept while its lock is held, and removed once it is not
TEST(OutputSafety, LeftoversAreRemovedByTheirFreeLockNotByHostAndPid) {
  const fs::path d = fresh_dir("stale_lock");
  const fs::path c = quick_case(d, "locked");
  const fs::path out = d / "out";
  ASSERT_EQ(run_cli("run --no-render --out " + out.string() + " " + c.string()).exit_code, 0);
  char host[256] = {0};
  ::gethostname(host, sizeof host - 1);
  const fs::path live = out / (std::string(".armstudy-") + host + "-999999-0badc0de");
  const fs::path dead = out / (std::string(".armstudy-") + host + "-999998-0badc0de");
  for (const auto& s : {live, dead}) {
    fs::create_directories(s / "new/locked");
    std::ofstream(s / "new/locked/results.json") << "{}";
    std::ofstream(s / "lock");
  }
  // another process holds the live one's lock (as its run would) until the pipe closes
  FILE* holder =
      popen(("flock " + (live / "lock").string() + " -c 'echo locked; read x'").c_str(), "w");
  ASSERT_NE(holder, nullptr);
  for (int i = 0;
       i < 200 && run_shell("flock -n " + (live / "lock").string() + " true").exit_code == 0; ++i)
    ::usleep(20000);
  const CmdRun r = run_cli("run --no-render --force --out " + out.string() + " " + c.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(live / "new/locked/results.json")) << "a live run's folder was removed\n"
                                                            << r.output;
  EXPECT_FALSE(fs::exists(dead)) << "a dead run's folder was kept\n" << r.output;
  pclose(holder);  // the holder exits: its lock is free
  const CmdRun again = run_cli("run --no-render --force --out " + out.string() + " " + c.string());
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_FALSE(fs::exists(live)) << again.output;
  EXPECT_TRUE(leftovers(out).empty()) << leftovers(out);
  fs::remove_all(d);
}

// a kill between the two renames of the swap (file systems without RENAME_EXCHANGE) left
// the only copy of the report in the scratch folder's old/: the next run puts it back
TEST(OutputSafety, AReportAKillLeftAsideIsPutBack) {
  const fs::path d = fresh_dir("put_back");
  const fs::path c = quick_case(d, "aside");
  const fs::path out = d / "out";
  ASSERT_EQ(run_cli("run --no-render --out " + out.string() + " " + c.string()).exit_code, 0);
  const std::string report = slurp(out / "aside/results.json");
  const fs::path scratch = out / ".armstudy-elsewhere-1-12345678";
  fs::create_directories(scratch / "old");
  std::ofstream(scratch / "lock");
  fs::rename(out / "aside", scratch / "old/aside");
  // an earlier version's way: .<case>.old-<host>-<pid> of a process that is gone
  char host[256] = {0};
  ::gethostname(host, sizeof host - 1);
  fs::rename(out / "summary.md", out / (std::string(".summary.md.old-") + host + "-999997"));
  run_cli("validate " + c.string());  // validate touches nothing
  EXPECT_FALSE(fs::exists(out / "aside"));
  const fs::path other = quick_case(d, "other");
  const CmdRun next = run_cli("run --no-render --out " + out.string() + " " + other.string());
  EXPECT_EQ(next.exit_code, 0) << next.output;
  EXPECT_NE(next.output.find("put back " + (fs::weakly_canonical(out) / "aside").string()),
            std::string::npos)
      << next.output;
  EXPECT_EQ(slurp(out / "aside/results.json"), report);
  EXPECT_TRUE(leftovers(out).empty()) << leftovers(out);
  fs::remove_all(d);
}

}  // namespace

namespace {

// a time-optimal case on the exact grid and a small DP (no Complex) with `exact` as given
fs::path huge_grid_case(const fs::path& dir, const std::string& name, const std::string& exact) {
  const fs::path p = dir / (name + ".yaml");
  std::ofstream(p) << "study: time_optimal\nname: " << name
                   << "\ntime_optimal:\n"
                      "  path: {points_m: [[0.3, 0.1], [-0.1, 0.8]]}\n"
                      "  dp: {segments: 10, levels: 20, convergence_segments: []}\n"
                      "  complex: {enabled: false}\n"
                      "  exact: "
                   << exact << "\n";
  return p;
}

}  // namespace

// A valid case at the largest uniform exact grid wrote every node of it (a graded grid of
// up to 1e6 nodes likewise): results.json beyond the 16 MiB armstudy reads back, so the
// run exited 2 without junit.xml, and re-runs and merge refused the folder from then on.
// What it stores per grid point is now a subsample of at most 2001 points with its stride.
TEST(OutputSafety, AValidCaseAtItsLargestGridWritesAResultsJsonThatRunAndMergeReadBack) {
  const fs::path d = fresh_dir("huge_grid");
  const fs::path c = huge_grid_case(d, "huge-grid", "{grid_points: 100000, tolerance_rel: 0}");
  const fs::path out = d / "out";
  const std::string run = "run --no-render --no-sensitivity --out " + out.string() + " ";
  const CmdRun first = run_cli(run + c.string());
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const fs::path rj = out / "huge-grid/results.json";
  EXPECT_LT(fs::file_size(rj), 2u << 20) << "a summary of the grid, not every node";
  EXPECT_TRUE(fs::exists(out / "junit.xml"));
  const auto j = nlohmann::json::parse(slurp(rj));
  const auto& exact = j["time_optimal"]["solvers"][0];
  EXPECT_EQ(exact["intervals"], 99999);
  EXPECT_LE(exact["node_s"].size(), 2001u);
  EXPECT_GT(exact["node_stride"].get<int>(), 1);
  EXPECT_EQ(exact["node_s"].back(), j["time_optimal"]["path_length"]) << "the last node is kept";
  EXPECT_LE(j["time_optimal"]["mvc"]["s"].size(), 2001u);
  EXPECT_GT(j["time_optimal"]["mvc"]["stride"].get<int>(), 1);
  // read back: a re-run keeps it, --force replaces it, merge reads it
  const CmdRun again = run_cli(run + c.string());
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("skipped 1 case(s)"), std::string::npos) << again.output;
  const CmdRun forced = run_cli(run + "--force " + c.string());
  EXPECT_EQ(forced.exit_code, 0) << forced.output;
  const CmdRun merged = run_cli("merge " + out.string());
  EXPECT_EQ(merged.exit_code, 0) << merged.output;
  fs::remove_all(d);
}

// The pendulum wrote every output sample: pendulum.sample_s 1e-4 over the documented 60 s
// is 600,001 samples of 19 numbers, beyond the 16 MiB armstudy reads back. Its series is
// stored as the time-optimal study's are (app/stored_series.hpp): at most 2001 samples,
// every stride-th and the last, the stride written beside them.
TEST(OutputSafety, APendulumSeriesIsStoredAsAtMost2001SamplesWithItsStride) {
  const fs::path d = fresh_dir("long_pendulum");
  const fs::path c = d / "long-pendulum.yaml";
  std::ofstream(c) << "study: pendulum\nname: long-pendulum\n"
                      "pendulum: {duration_s: 3.0, sample_s: 1.0e-4}\n";
  const fs::path out = d / "out";
  const CmdRun r =
      run_cli("run --no-render --no-sensitivity --out " + out.string() + " " + c.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(slurp(out / "long-pendulum/results.json"));
  const auto& series = j["pendulum"]["series"];
  const int stride = series["stride"].get<int>();
  EXPECT_GT(stride, 1);
  EXPECT_LE(series["t_s"].size(), 2001u);
  EXPECT_GE(series["t_s"].size(), 1500u) << "the stride keeps close to 2001 of 30,001 samples";
  for (const char* key : {"q_rad", "qd_rad_s", "kinetic_J", "potential_J", "total_J", "ball_xy_m",
                          "circle_centre_xy_m"})
    EXPECT_EQ(series[key].size(), series["t_s"].size()) << key;
  EXPECT_GE(series["t_s"][1].get<double>(), (stride - 1) * 1e-4) << "every stride-th sample";
  EXPECT_DOUBLE_EQ(series["t_s"].back().get<double>(), 3.0) << "the last sample is kept";
  EXPECT_EQ(j["pendulum"]["snapshots"].size(), 24u) << "every snapshot, from every sample";
  fs::remove_all(d);
}

// a user's .armstudy-cache (no lock file, or one of its own) was removed as a killed run's
// scratch folder: only names armstudy gives (.armstudy-<host>-<pid>-<8 hex>) with its lock
// file are, or such a folder left empty by a kill before its lock file was made
TEST(OutputSafety, AUsersFolderOfArmstudysPrefixIsNeverRemoved) {
  const fs::path d = fresh_dir("user_cache");
  const fs::path out = d / "out";
  fs::create_directories(out / ".armstudy-cache");
  std::ofstream(out / ".armstudy-cache/data.bin") << "a user's cache";
  fs::create_directories(out / ".armstudy-locked");
  std::ofstream(out / ".armstudy-locked/lock");
  fs::create_directories(out / ".armstudy-host-12-0badc0de");  // a killed run's, without lock
  std::ofstream(out / ".armstudy-host-12-0badc0de/notes.txt") << "kept: not empty";
  fs::create_directories(out / ".armstudy-host-13-0badc0de");  // empty: a kill before the lock
  const auto old = fs::file_time_type::clock::now() - std::chrono::minutes(30);
  for (const auto& e : fs::recursive_directory_iterator(out)) fs::last_write_time(e.path(), old);
  const auto before = snapshot(out);
  const CmdRun r =
      run_cli("run --no-render --out " + out.string() + " " + quick_case(d, "beside").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  for (const char* f : {".armstudy-cache/data.bin", ".armstudy-locked/lock",
                        ".armstudy-host-12-0badc0de/notes.txt"})
    EXPECT_EQ(slurp(out / f), before.at(f)) << f << " was removed\n" << r.output;
  EXPECT_FALSE(fs::exists(out / ".armstudy-host-13-0badc0de")) << "an empty scratch folder stays";
  fs::remove_all(d);
}
