// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// What merge, diff and run read back from output folders comes from pull requests and
// other people's jobs: paths in results.json stay in their case folder, frames and files
// are bounded, names and messages never reach summary.md, junit.xml or the terminal raw,
// a sweep's merge is checked against its manifest, two results of one case are an error,
// a case whose listed files are gone is redone and an errored case is a failed case.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "testing/cli.hpp"
#include "testing/files.hpp"
#include "testing/output_folder.hpp"

namespace {
namespace fs = std::filesystem;
using armstudy::testing::fresh_dir;
using armstudy::testing::slurp;
using nlohmann::json;

using armstudy::testing::kBin;
using armstudy::testing::kSource;
using armstudy::testing::quick_case;
using armstudy::testing::run_cli;
using armstudy::testing::run_shell;
using armstudy::testing::write_file;
using CmdRun = armstudy::testing::CliRun;

// one case run once (--no-render) for the whole suite; each test edits a copy
class UntrustedResults : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // one folder per process: CTest runs the tests of this suite side by side
    root_ = fresh_dir("untrusted_results_" + std::to_string(::getpid()));
    const CmdRun r = run_cli("run --no-render --out " + (root_ / "run").string() + " " +
                             quick_case(root_, "a").string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }
  // a copy of the run's output folder as `name`
  static fs::path copy_run(const std::string& name) {
    const fs::path d = root_ / name;
    fs::remove_all(d);
    fs::copy(root_ / "run", d, fs::copy_options::recursive);
    for (const char* f : {"summary.md", "junit.xml"}) fs::remove(d / f);
    return d;
  }
  static void edit(const fs::path& rj, const std::function<void(json&)>& f) {
    json j = json::parse(slurp(rj));
    f(j);
    write_file(rj, j.dump(1));
  }
  static fs::path root_;
};
fs::path UntrustedResults::root_;

TEST_F(UntrustedResults, DiffReadsFramesOnlyInsideTheirCaseFolderAndBoundsTheirPixels) {
  const fs::path base = copy_run("frames_base"), now = copy_run("frames_new");
  // a PNG header saying 12000 x 12000 px: never decoded
  std::string big = std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
  big += std::string("\0\0\x2e\xe0\0\0\x2e\xe0\x08\x02\0\0\0", 13);
  write_file(base / "a" / "big.png", big + "1");
  write_file(now / "a" / "big.png", big + "2");
  fs::create_symlink("/dev/zero", base / "a" / "zero.png");
  fs::create_symlink("/dev/zero", now / "a" / "zero.png");
  for (const fs::path& d : {base, now})
    edit(d / "a" / "results.json", [](json& j) {
      j["frames"] = {"/dev/zero", "../../frames_new/a/big.png", "zero.png", "big.png"};
    });
  const CmdRun r = run_cli("diff " + base.string() + " " + now.string() + " --out " +
                           (root_ / "frames_diff").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const std::string md = slurp(root_ / "frames_diff" / "diff.md");
  EXPECT_NE(md.find("frame '/dev/zero' is an absolute path"), std::string::npos) << md;
  EXPECT_NE(md.find("is a path with '..'"), std::string::npos) << md;
  EXPECT_NE(md.find("frame 'zero.png' is a path through a symlink out of the case folder"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("a PNG of 12000 x 12000 px; expected a frame of at most 100000000 px"),
            std::string::npos)
      << md;
}

TEST_F(UntrustedResults, MergeAndDiffRefuseResultsBeyondTheirLimits) {
  const fs::path figures = copy_run("many_figures");
  edit(figures / "a" / "results.json", [](json& j) {
    const json first = j["key_figures"][0];
    for (int i = 0; i < 201; ++i) {
      json k = first;
      k["name"] = "f" + std::to_string(i);
      j["key_figures"].push_back(k);
    }
  });
  CmdRun r = run_cli("merge " + figures.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("key figures; expected at most 200"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(figures / "summary.md")) << "nothing is written";
  EXPECT_FALSE(fs::exists(figures / "sweep"));
  r = run_cli("diff " + figures.string() + " " + figures.string() + " --out " +
              (root_ / "limit_diff").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("key figures; expected at most 200"), std::string::npos) << r.output;
  // a results.json larger than 16 MiB is not parsed
  const fs::path large = copy_run("large_results");
  fs::resize_file(large / "a" / "results.json", (16u << 20) + 1);
  r = run_cli("merge " + large.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("16777217 bytes; expected a results.json of at most 16777216 bytes"),
            std::string::npos)
      << r.output;
}

TEST_F(UntrustedResults, ControlBytesGiveWellFormedJunitAndNoRawControlInSummaryOrTerminal) {
  const fs::path d = copy_run("control_bytes");
  edit(d / "a" / "results.json", [&](json& j) {
    j["status"] = "unsolvable";
    j["message"] = std::string("\x1b]0;title\x07") + "unsolved " + "\x1b[2J";
    j["checks"][0]["name"] = "check " + std::string("\x1b[1m") + "<&";
    j["checks"][0]["passed"] = false;
    j["key_figures"][0]["unit"] = "J\x1b[0m|";
  });
  // bytes that are not UTF-8 cannot be in JSON text: they come in as a folder's name
  const fs::path weird = d / ("b\x1b[2Jx\x01" + std::string("\xff"));
  fs::create_directories(weird);
  write_file(weird / "results.json", "{\"study\": \"" + std::string("p\\u001b[31m") + "\", " + "}");
  const CmdRun r = run_cli("merge " + d.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << "no raw escape on the terminal";
  const std::string md = slurp(d / "summary.md");
  ASSERT_FALSE(md.empty());
  for (char c : md)
    EXPECT_TRUE(static_cast<unsigned char>(c) >= 0x20 || c == '\n')
        << "raw control byte " << int(c) << " in summary.md";
  EXPECT_EQ(md.find('\x7f'), std::string::npos);
  EXPECT_EQ(md.find('\xff'), std::string::npos);
  EXPECT_NE(md.find("\\x1B[2J"), std::string::npos) << md;
  const CmdRun parse = run_shell(
      "python3 -c \"import sys, xml.etree.ElementTree as E; r = E.parse(sys.argv[1]).getroot(); "
      "print(r.get('failures'))\" " +
      (d / "junit.xml").string());
  EXPECT_EQ(parse.exit_code, 0) << parse.output << slurp(d / "junit.xml");
  EXPECT_EQ(parse.output, "3\n") << slurp(d / "junit.xml");
}

TEST_F(UntrustedResults, TwoResultsForOneCaseIdAreAFailedCaseNamingBothFolders) {
  const fs::path first = copy_run("dup_1"), second = copy_run("dup_2");
  // a stale passing copy in another folder under another folder name
  fs::rename(second / "a", second / "a-old");
  const CmdRun r = run_cli("merge " + first.string() + " " + second.string() + " --out " +
                           (root_ / "dup_out").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("case 'a' has results in " + (first / "a").string() + " and " +
                          (second / "a-old").string()),
            std::string::npos)
      << r.output;
  const std::string md = slurp(root_ / "dup_out" / "summary.md");
  EXPECT_EQ(md.rfind("# armstudy: 1 case(s), 1 failed", 0), 0u) << md;
}

TEST_F(UntrustedResults, SkipRedoesAPassedCaseWhoseListedFilesAreGoneOrChanged) {
  const fs::path out = copy_run("skip_files");
  const std::string run =
      "run --no-render --out " + out.string() + " " + (root_ / "a.yaml").string();
  CmdRun r = run_cli(run);
  ASSERT_NE(r.output.find("skipped 1 case(s)"), std::string::npos) << r.output;
  const json files = json::parse(slurp(out / "a" / "results.json"))["files"];
  ASSERT_GE(files.size(), 1u);
  const fs::path listed = out / "a" / files[0]["path"].get<std::string>();
  const std::string bytes = slurp(listed);
  fs::remove(listed);
  r = run_cli(run);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("skipped"), std::string::npos) << "a deleted file: " << r.output;
  EXPECT_EQ(slurp(listed), bytes);
  // the same size, other bytes
  std::string changed = bytes;
  changed[0] = changed[0] == 'x' ? 'y' : 'x';
  write_file(listed, changed);
  r = run_cli(run);
  EXPECT_EQ(r.output.find("skipped"), std::string::npos) << "a changed file: " << r.output;
  EXPECT_EQ(slurp(listed), bytes);
}

TEST_F(UntrustedResults, AnErroredCaseIsAFailedCaseInSummaryAndJunit) {
  const fs::path out = copy_run("errored");
  // writes beyond 64 KiB fail (EFBIG, "File too large"): the case's report cannot be written,
  // the small summary.md and junit.xml can; the earlier, passed report of the case stays
  const CmdRun r = run_shell("bash -c \"trap '' XFSZ; ulimit -f 64; exec " + kBin +
                             " run --force --no-render --out " + out.string() + " " +
                             (root_ / "a.yaml").string() + "\"");
  ASSERT_EQ(r.exit_code, 3) << r.output;
  const std::string md = slurp(out / "summary.md");
  EXPECT_EQ(md.rfind("# armstudy: 1 case(s), 1 failed", 0), 0u) << md;
  EXPECT_NE(md.find("the run ended in an error"), std::string::npos) << md;
  EXPECT_NE(slurp(out / "junit.xml").find("failures=\"1\""), std::string::npos);
}

TEST(SweepManifest, MergeOfAPartialSweepOrAnEmptyFolderFailsNamingWhatIsMissing) {
  const fs::path d = fresh_dir("merge_manifest");
  write_file(d / "base.yaml", "study: placement\nname: m\nplacement: {length_fraction: 0.5}\n");
  write_file(d / "s.yaml",
             "sweep: s\nbase: base.yaml\naxes:\n  - path: placement.length_fraction\n"
             "    values: [0.4, 0.6]\n");
  ASSERT_EQ(run_cli("sweep expand " + (d / "s.yaml").string() + " --out " + (d / "cases").string())
                .exit_code,
            0);
  const json ids = json::parse(slurp(d / "cases" / "sweep-manifest.json"))["cases"];
  ASSERT_EQ(ids.size(), 2u);
  // shard 0 of 2 only: the other case never ran
  CmdRun r = run_cli("run --no-render --shard 0/2 --out " + (d / "out").string() + " " +
                     (d / "cases").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(d / "out" / "sweep-manifest.json"));
  r = run_cli("merge " + (d / "out").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const std::string missing = ids[1].get<std::string>();
  EXPECT_NE(r.output.find("1 case(s) of sweep 's'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(missing), std::string::npos) << r.output;
  const std::string md = slurp(d / "out" / "summary.md");
  EXPECT_EQ(md.rfind("# armstudy: 2 case(s), 1 failed", 0), 0u) << md;
  EXPECT_NE(md.find(missing), std::string::npos) << md;
  // an empty folder: nothing merged is not "0 failed"
  fs::create_directories(d / "empty");
  r = run_cli("merge " + (d / "empty").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_FALSE(fs::exists(d / "empty" / "summary.md"));
  // given the manifest, an empty folder names every case
  r = run_cli("merge " + (d / "empty").string() + " --manifest " +
              (d / "cases" / "sweep-manifest.json").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("2 case(s) of sweep 's'"), std::string::npos) << r.output;
  fs::remove_all(d);
}

// --manifest with no case said "no case folder with a results.json" (there were two); an
// id listed twice counted twice; "", "../../../etc" and "/etc/passwd" were accepted as ids
TEST(SweepManifest, AManifestWithNoCaseARepeatedIdOrAnIdThatIsNoCaseNameIsRefused) {
  const fs::path d = fresh_dir("merge_bad_manifest");
  write_file(d / "base.yaml", "study: placement\nname: m\nplacement: {length_fraction: 0.5}\n");
  write_file(d / "s.yaml",
             "sweep: s\nbase: base.yaml\naxes:\n  - path: placement.length_fraction\n"
             "    values: [0.4, 0.6]\n");
  ASSERT_EQ(run_cli("sweep expand " + (d / "s.yaml").string() + " --out " + (d / "cases").string())
                .exit_code,
            0);
  const CmdRun ran =
      run_cli("run --no-render --out " + (d / "out").string() + " " + (d / "cases").string());
  ASSERT_EQ(ran.exit_code, 0) << ran.output;
  json m = json::parse(slurp(d / "cases" / "sweep-manifest.json"));
  const std::string id = m["cases"][0].get<std::string>();
  const std::vector<std::pair<json, std::string>> bad = {
      {json::array(), "\"cases\" is empty; expected the sweep's case ids"},
      {json::array({id, id}), "lists '" + id + "' twice; expected each case once"},
      {json::array({""}), "\"cases\" holds ''; expected case names"},
      {json::array({"../../../etc"}), "\"cases\" holds '../../../etc'; expected case names"},
      {json::array({"/etc/passwd"}), "\"cases\" holds '/etc/passwd'; expected case names"}};
  for (const auto& [cases, message] : bad) {
    m["cases"] = cases;
    write_file(d / "bad-manifest.json", m.dump());
    const auto before = slurp(d / "out" / "summary.md");
    const CmdRun r = run_cli("merge " + (d / "out").string() + " --manifest " +
                             (d / "bad-manifest.json").string());
    EXPECT_EQ(r.exit_code, 2) << cases << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
    EXPECT_EQ(slurp(d / "out" / "summary.md"), before) << "nothing is written";
  }
  fs::remove_all(d);
}

}  // namespace
