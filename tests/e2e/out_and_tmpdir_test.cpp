// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Usage and environment: `--out ""` or a file as --out is bad usage (exit 2, not 3),
// and a TMPDIR that is no folder does not stop --pdf.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "testing/cli.hpp"
#include "testing/files.hpp"

namespace {
namespace fs = std::filesystem;
using armstudy::testing::BoundedRun;
using armstudy::testing::fresh_dir;
using armstudy::testing::run_bounded;

using armstudy::testing::kSource;

TEST(OutOption, EmptyOrAFileIsBadUsageAndTheFileIsUntouched) {
  const fs::path d = fresh_dir("out_option");
  const std::string c = (kSource / "reports/cases/pendulum.yaml").string();
  { std::ofstream(d / "notes.txt") << "mine"; }
  const std::string file = (d / "notes.txt").string();
  const std::vector<std::vector<std::string>> commands = {
      {"run", "--no-render", "--out", "", c},
      {"run", "--no-render", "--out", file, c},
      {"run", "--no-render", "--out", file + "/sub", c},
      {"merge", d.string(), "--out", ""},
      {"diff", d.string(), d.string(), "--out", file},
      {"sweep", "expand", (kSource / "reports/sweeps/placement-link-ratio.yaml").string(), "--out",
       file}};
  for (const auto& args : commands) {
    const BoundedRun r = run_bounded(args, {30});
    EXPECT_EQ(r.exit_code, 2) << args[0] << " " << args[args.size() - 2] << ": " << r.output;
    EXPECT_NE(r.output.find("--out"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("expected a folder"), std::string::npos) << r.output;
  }
  EXPECT_EQ(armstudy::testing::slurp(d / "notes.txt"), "mine");
  fs::remove_all(d);
}

// TMPDIR naming a missing folder made every print fail; Chromium's profile goes to /tmp
TEST(PdfOption, MissingTmpdirFallsBackToTmpAndSaysSo) {
  if (std::system("command -v chromium-headless-shell >/dev/null || command -v chromium "
                  ">/dev/null") != 0)
    GTEST_SKIP() << "no Chromium";
  const fs::path d = fresh_dir("missing_tmpdir");
  const std::string c = (kSource / "reports/cases/pendulum.yaml").string();
  const BoundedRun r = run_bounded({"run", "--no-render", "--pdf", "--out", d.string(), c},
                                   {120, false, 0, {{"TMPDIR", "/nonexistent-tmpdir"}}});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("TMPDIR is '/nonexistent-tmpdir', which is not a folder"),
            std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::exists(d / "pendulum" / "report.pdf")) << r.output;
  fs::remove_all(d);
}

}  // namespace
