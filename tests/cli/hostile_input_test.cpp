// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The CLI on hostile input: files that are not regular files, budgets and --allow-large,
// and sweeps whose point count overflows or is too large. Each refusal exits 2 quickly,
// says why and writes nothing.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "testing/cli.hpp"
#include "testing/files.hpp"
#include "testing/output_folder.hpp"

namespace {
namespace fs = std::filesystem;

using armstudy::testing::CliRun;
using armstudy::testing::run_cli;

using armstudy::testing::write_file;

TEST(HostileInput, DevicesFifosAndFoldersAreRefusedWithoutReading) {
  const fs::path dir = armstudy::testing::fresh_dir("cli_hostile_files");
  const fs::path fifo = dir / "fifo.yaml", out = dir / "out";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& cmd :
       std::vector<std::string>{"validate /dev/zero", "validate " + fifo.string(),
                                "run --no-render --out " + out.string() + " " + fifo.string(),
                                "validate " + dir.string()}) {
    SCOPED_TRACE(cmd);
    const CliRun r = run_cli(cmd);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_TRUE(r.output.find("is a device; expected a regular YAML file") != std::string::npos ||
                r.output.find("is a FIFO (named pipe); expected a regular YAML file") !=
                    std::string::npos ||
                r.output.find("is a folder; expected a YAML file") != std::string::npos)
        << r.output;
  }
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

TEST(HostileInput, BudgetIsJudgedByValidateAndRunAndRaisedByAllowLarge) {
  const fs::path dir = armstudy::testing::fresh_dir("cli_budget");
  const fs::path c = dir / "big.yaml";
  write_file(c,
             "study: placement\nname: big\nplacement:\n  length_fraction: 0.5\n  nx_s: 10000\n"
             "  phi_step_deg: 0.01\n");
  const CliRun v = run_cli("validate " + c.string());
  EXPECT_EQ(v.exit_code, 2) << v.output;
  EXPECT_NE(v.output.find(c.string() +
                          ":4:3: the placement sweep asks for about 2.9e+11 trajectory samples"),
            std::string::npos)
      << v.output;
  EXPECT_NE(v.output.find("more than the budget of 1e+10 trajectory samples"), std::string::npos)
      << v.output;
  EXPECT_NE(v.output.find("memory"), std::string::npos) << v.output;
  const CliRun r = run_cli("run --no-render --out " + (dir / "out").string() + " " + c.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--allow-large"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  const CliRun a = run_cli("validate --allow-large " + c.string());
  EXPECT_EQ(a.exit_code, 0) << a.output;
  // the documented range of samples is within the budget (and renders: a traced path is
  // drawn through at most 1000 segments)
  write_file(c, "study: placement\nname: big\nplacement: {length_fraction: 0.5, samples: 20001}\n");
  EXPECT_EQ(run_cli("validate " + c.string()).exit_code, 0);
  fs::remove_all(dir);
}

TEST(HostileInput, MergeKeysAreSupportedAsYamlDefinesThem) {
  const fs::path dir = armstudy::testing::fresh_dir("cli_merge");
  write_file(dir / "m.yaml",
             "study: placement\nname: merged\n"
             "arm:\n  links:\n    - &link {length: 0.4, mass: 4.0}\n"
             "    - {<<: *link, length: 0.2, mass: 2.0}\n"
             "placement: {length_fraction: 0.5}\n");
  const CliRun r = run_cli("validate " + (dir / "m.yaml").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // a merged mapping's keys are judged like the mapping's own, at their place
  write_file(dir / "m.yaml",
             "study: placement\nname: merged\n"
             "arm:\n  links:\n    - &link {length: 0.4, mas: 4.0}\n"
             "    - {<<: *link, length: 0.2}\n"
             "placement: {length_fraction: 0.5}\n");
  const CliRun bad = run_cli("validate " + (dir / "m.yaml").string());
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(
      bad.output.find("m.yaml:5:27: unknown key 'arm.links[2].mas' (from the merge key '<<'); "
                      "did you mean 'mass'?"),
      std::string::npos)
      << bad.output;
  fs::remove_all(dir);
}

TEST(HostileInput, SweepPointCountNeverOverflowsAndIsCapped) {
  const fs::path dir = armstudy::testing::fresh_dir("cli_sweep_count");
  write_file(dir / "base.yaml", "study: placement\nname: b\nplacement: {length_fraction: 0.5}\n");
  const std::string range = "    range: {from: 0.1, to: 0.9, steps: 65536}\n";
  write_file(dir / "huge.yaml",
             "sweep: huge\nbase: base.yaml\naxes:\n"
             "  - path: placement.length_fraction\n" +
                 range + "  - path: placement.duration_s\n" + range +
                 "  - path: placement.samples\n" + range + "  - path: placement.nx_s\n" + range);
  CliRun r =
      run_cli("sweep expand " + (dir / "huge.yaml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("huge.yaml:4:5: the sweep has about 1.84467e+19 points (grid of 65536 x "
                          "65536 x 65536 x 65536 values)"),
            std::string::npos)
      << r.output;
  write_file(dir / "big.yaml",
             "sweep: big\nbase: base.yaml\naxes:\n"
             "  - path: placement.length_fraction\n    range: {from: 0.1, to: 0.9, steps: 101}\n"
             "  - path: placement.duration_s\n    range: {from: 0.5, to: 2, steps: 100}\n");
  r = run_cli("sweep expand " + (dir / "big.yaml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(
                "the sweep has 10100 points (grid of 101 x 100 values); expected at most 10000"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  // a small sweep says its count before it writes
  write_file(dir / "small.yaml",
             "sweep: small\nbase: base.yaml\naxes:\n"
             "  - path: placement.length_fraction\n    values: [0.4, 0.6]\n");
  r = run_cli("sweep expand " + (dir / "small.yaml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const size_t said = r.output.find("sweep small: 2 case(s); writing them to");
  const size_t done = r.output.find("sweep small: 2 case(s), 2 file(s) written");
  EXPECT_NE(said, std::string::npos) << r.output;
  EXPECT_NE(done, std::string::npos) << r.output;
  EXPECT_LT(said, done);
  fs::remove_all(dir);
}

TEST(HostileInput, SweepNamesABadBaseWithoutQuotingIt) {
  const fs::path dir = armstudy::testing::fresh_dir("cli_sweep_base");
  std::string passwd;
  for (int i = 0; i < 40; ++i)
    passwd += "user" + std::to_string(i) + ":x:1000:1000::/home/u:/bin/sh\n";
  write_file(dir / "passwd", passwd);
  write_file(dir / "s.yaml", "sweep: s\nbase: passwd\naxes:\n  - path: a\n    values: [1]\n");
  const CliRun r =
      run_cli("sweep expand " + (dir / "s.yaml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("passwd, which is not a case file"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("user0"), std::string::npos) << "named, never quoted: " << r.output;
  EXPECT_LT(r.output.size(), 800u) << r.output;
  // a hostile axis path (a long one once overflowed std::regex's stack)
  write_file(dir / "base.yaml", "study: placement\nname: b\nplacement: {length_fraction: 0.5}\n");
  write_file(dir / "p.yaml", "sweep: p\nbase: base.yaml\naxes:\n  - path: " +
                                 std::string(200000, 'a') + "\n    values: [1]\n");
  const CliRun p =
      run_cli("sweep expand " + (dir / "p.yaml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(p.exit_code, 2) << p.output.substr(0, 500);
  EXPECT_NE(p.output.find("is not a parameter path like arm.links[2].length"), std::string::npos);
  EXPECT_LT(p.output.size(), 800u);
  fs::remove_all(dir);
}

}  // namespace

namespace {

// a file name made to move the terminal's cursor and retitle its window, printed by
// validate: never raw, its control characters as \xNN
TEST(HostileInput, AFileNameWithTerminalEscapesIsPrintedEscaped) {
  const fs::path dir = armstudy::testing::fresh_dir("cli_escaped_names");
  const std::string bad = "bad\x1b[2J\x1b]0;owned\x07.yaml", good = "good\x1b[31m.yaml";
  write_file(dir / bad, "study: placement\nname: my case\n");
  fs::rename(armstudy::testing::quick_case(dir, "fine"), dir / good);
  for (const std::string& f : {bad, good}) {
    const CliRun r = run_cli("validate '" + (dir / f).string() + "'");
    EXPECT_EQ(r.exit_code, f == bad ? 2 : 0) << r.output;
    EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << "a raw ESC in: " << r.output;
    EXPECT_EQ(r.output.find('\x07'), std::string::npos) << "a raw BEL in: " << r.output;
  }
  EXPECT_NE(run_cli("validate '" + (dir / bad).string() + "'")
                .output.find("bad\\x1B[2J\\x1B]0;owned\\x07.yaml:"),
            std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
