// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The one reader of files armstudy did not just write (cases/input_file.hpp): regular
// files only, a cap, never a wait; links refused where armstudy wrote the file itself.
#include "cases/input_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "testing/files.hpp"

namespace armstudy::cases {
namespace {
namespace fs = std::filesystem;

std::string why_not(const fs::path& p, const InputFileRules& rules) {
  try {
    read_input_file(p.string(), rules);
    return "";
  } catch (const InputFileError& e) {
    EXPECT_FALSE(e.runtime()) << e.what();  // the file is at fault: exit 2
    return e.what();
  }
}

TEST(InputFile, ResultsJsonThatIsALinkAFifoOrTooBigIsRefusedWithoutReading) {
  const fs::path d = armstudy::testing::fresh_dir("input_file");
  const InputFileRules results{100, "results.json file", false};
  { std::ofstream(d / "real.json") << "{}"; }
  EXPECT_EQ(read_input_file((d / "real.json").string(), results), "{}");
  fs::create_symlink(d / "real.json", d / "link.json");
  EXPECT_EQ(why_not(d / "link.json", results),
            (d / "link.json").string() +
                ": is a symbolic link; expected a regular results.json file, not a link");
  // a case file given by the user may be a link
  EXPECT_EQ(read_input_file((d / "link.json").string(), {100, "YAML file", true}), "{}");
  ASSERT_EQ(::mkfifo((d / "fifo.json").c_str(), 0600), 0);
  EXPECT_EQ(why_not(d / "fifo.json", results),
            (d / "fifo.json").string() +
                ": is a FIFO (named pipe); expected a regular results.json file");
  { std::ofstream(d / "big.json") << std::string(101, ' '); }
  EXPECT_EQ(why_not(d / "big.json", results),
            (d / "big.json").string() +
                ": is 101 bytes; expected a results.json file of at most 100 bytes");
  fs::remove_all(d);
}

TEST(InputFile, LinkLoopIsRefusedAtOnceSayingSo) {
  const fs::path d = armstudy::testing::fresh_dir("input_file_loop");
  fs::create_symlink(d / "b.yaml", d / "a.yaml");
  fs::create_symlink(d / "a.yaml", d / "b.yaml");
  EXPECT_EQ(why_not(d / "a.yaml", {100, "YAML file", true}),
            (d / "a.yaml").string() +
                ": cannot open the file: too many levels of symbolic links (a link loop?); "
                "expected a readable YAML file");
  fs::remove_all(d);
}

}  // namespace
}  // namespace armstudy::cases
