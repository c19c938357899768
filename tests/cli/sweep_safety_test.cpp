// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Sweeps from untrusted files: the base case stays in its place and is named, never quoted;
// an axis that would be silently merged is refused; expansion owns its folder (removes its
// own cases no longer in the sweep, never a user's file) and writes the sweep's manifest.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "testing/cli.hpp"
#include "testing/files.hpp"

namespace {
namespace fs = std::filesystem;

using armstudy::testing::CliRun;
using armstudy::testing::run_cli;
using armstudy::testing::slurp;

using armstudy::testing::write_file;

const std::string kBase = "study: placement\nname: b\nplacement: {length_fraction: 0.5}\n";

CliRun expand(const fs::path& sweep, const fs::path& out, const std::string& more = "") {
  return run_cli("sweep expand " + sweep.string() + " --out " + out.string() + more);
}

TEST(SweepSafety, BaseOutsideTheSweepFolderIsRefusedAndNeverQuoted) {
  const fs::path dir = armstudy::testing::fresh_dir("sweep_base_place");
  fs::create_directories(dir / "sweeps");
  fs::create_directories(dir / "cases");
  const std::string secret = "https://ci:ghp_SECRETTOKEN0123456789@github.com\n";
  write_file(dir / "secret", secret);
  write_file(dir / "cases" / "base.yaml", kBase);
  fs::create_symlink(dir / "secret", dir / "sweeps" / "link.yaml");
  const std::string axes = "axes:\n  - path: placement.length_fraction\n    values: [0.4]\n";
  for (const std::string& base : {(dir / "secret").string(), std::string("../secret"),
                                  std::string("link.yaml"), std::string("../cases/base.yaml")}) {
    SCOPED_TRACE(base);
    write_file(dir / "sweeps" / "s.yaml", "sweep: s\nbase: " + base + "\n" + axes);
    const CliRun r = expand(dir / "sweeps" / "s.yaml", dir / "out");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("s.yaml:2:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(base[0] == '/' ? "'base' is an absolute path"
                                           : "which is outside the sweep file's folder"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("expected a path relative to the sweep file's folder"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("SECRET"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "out"));
  }
  // a folder the user names may hold it
  write_file(dir / "sweeps" / "s.yaml", "sweep: s\nbase: ../cases/base.yaml\n" + axes);
  CliRun r =
      expand(dir / "sweeps" / "s.yaml", dir / "out", " --base-dir " + (dir / "cases").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // a file in the folder that is not a case is named, not quoted
  write_file(dir / "sweeps" / "notes.txt", secret);
  write_file(dir / "sweeps" / "s.yaml", "sweep: s\nbase: notes.txt\n" + axes);
  r = expand(dir / "sweeps" / "s.yaml", dir / "out2");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("notes.txt, which is not a case file"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("SECRET"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

TEST(SweepSafety, AxesThatWouldBeSilentlyMergedAreRefusedNamingKeyAndLine) {
  const fs::path dir = armstudy::testing::fresh_dir("sweep_axes");
  write_file(dir / "base.yaml", kBase);
  struct Bad {
    std::string axes, expected;
  };
  for (const Bad& b : {
           Bad{"  - path: placement.length_fraction\n    values: [0.4]\n"
               "  - path: placement.length_fraction\n    values: [0.6]\n",
               "s.yaml:6:5: axis path 'placement.length_fraction' is also the axis at line 4"},
           Bad{"  - path: placement.length_fraction\n    values: [0.5, 0.50]\n",
               "s.yaml:4:5: axis 'placement.length_fraction' has value 2 (0.50) equal to value 1 "
               "(0.5)"},
           Bad{"  - path: name\n    values: [x, y]\n",
               "s.yaml:4:5: axis path 'name' is the case's name"},
           Bad{"  - path: sweep.name\n    values: [x, y]\n",
               "s.yaml:4:5: axis path 'sweep.name' is inside the 'sweep' mapping"},
       }) {
    SCOPED_TRACE(b.axes);
    write_file(dir / "s.yaml", "sweep: s\nbase: base.yaml\naxes:\n" + b.axes);
    const CliRun r = expand(dir / "s.yaml", dir / "out");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(b.expected), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "out"));
  }
  fs::remove_all(dir);
}

TEST(SweepSafety, ExpansionRemovesItsOwnStalePointsNeverAUsersFile) {
  const fs::path dir = armstudy::testing::fresh_dir("sweep_owns_folder");
  write_file(dir / "base.yaml", kBase);
  const fs::path out = dir / "cases";
  write_file(dir / "s.yaml",
             "sweep: s\nbase: base.yaml\naxes:\n  - path: placement.length_fraction\n"
             "    values: [0.3, 0.4, 0.6]\n");
  ASSERT_EQ(expand(dir / "s.yaml", out).exit_code, 0);
  fs::create_directories(out);
  write_file(out / "mine.yaml", "# my own case\n" + kBase);
  const auto manifest = [&] {
    return nlohmann::json::parse(slurp(out / "sweep-manifest.json"))["cases"];
  };
  ASSERT_EQ(manifest().size(), 3u);
  // the sweep edited: one point fewer
  write_file(dir / "s.yaml",
             "sweep: s\nbase: base.yaml\naxes:\n  - path: placement.length_fraction\n"
             "    values: [0.3, 0.4]\n");
  CliRun r = expand(dir / "s.yaml", out);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("no longer a point of the sweep"), std::string::npos) << r.output;
  size_t yamls = 0;
  for (const auto& e : fs::directory_iterator(out)) yamls += e.path().extension() == ".yaml";
  EXPECT_EQ(yamls, 3u) << "two points and the user's own file";
  EXPECT_EQ(slurp(out / "mine.yaml"), "# my own case\n" + kBase);
  EXPECT_EQ(manifest().size(), 2u);
  // a file of the user's where a case goes is refused, not replaced
  const std::string first = manifest()[0].get<std::string>();
  write_file(out / (first + ".yaml"), "# mine\n" + kBase);
  r = expand(dir / "s.yaml", out);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("was not written by 'armstudy sweep expand'"), std::string::npos)
      << r.output;
  EXPECT_EQ(slurp(out / (first + ".yaml")), "# mine\n" + kBase);
  // another sweep's folder is refused
  write_file(dir / "t.yaml",
             "sweep: t\nbase: base.yaml\naxes:\n  - path: placement.length_fraction\n"
             "    values: [0.7]\n");
  r = expand(dir / "t.yaml", out);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("holds the cases of sweep 's'"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

}  // namespace
