// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Hostile input refused before (or while) a tree is built: file kinds and size, text,
// document structure, aliases; merge keys; linear-time key checks; capped errors; numbers.
#include "cases/yaml_source.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cases/yaml_reader.hpp"
#include "testing/files.hpp"

namespace armstudy::cases {
namespace {
namespace fs = std::filesystem;

std::string first_error(const std::string& text) {
  Diagnostics d("f.yaml");
  if (parse_text(text, d) && d.empty()) return "";
  return d.errors().empty() ? "?" : d.errors()[0].format();
}

TEST(YamlSource, OnlyRegularFilesOfBoundedSizeAreRead) {
  const fs::path dir = armstudy::testing::fresh_dir("yaml_source_files");
  std::string bytes;
  {
    Diagnostics d("dir");
    EXPECT_FALSE(read_regular_file(dir.string(), d, &bytes));
    EXPECT_EQ(d.errors().at(0).format(), "dir: is a folder; expected a YAML file");
  }
  {
    Diagnostics d("/dev/zero");
    EXPECT_FALSE(read_regular_file("/dev/zero", d, &bytes));
    EXPECT_EQ(d.errors().at(0).message, "is a device; expected a regular YAML file");
  }
  {
    // a FIFO without a writer: refused at once, not waited on
    const fs::path fifo = dir / "fifo.yaml";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    Diagnostics d(fifo.string());
    EXPECT_FALSE(read_regular_file(fifo.string(), d, &bytes));
    EXPECT_EQ(d.errors().at(0).message, "is a FIFO (named pipe); expected a regular YAML file");
  }
  {
    // a sparse file past the cap is refused without being read
    const fs::path big = dir / "big.yaml";
    { std::ofstream(big) << "a: 1\n"; }
    fs::resize_file(big, kMaxFileBytes + 1);
    Diagnostics d(big.string());
    EXPECT_FALSE(read_regular_file(big.string(), d, &bytes));
    EXPECT_EQ(d.errors().at(0).message, "is 16.0 MiB; expected a YAML file of at most 16.0 MiB");
  }
  {
    Diagnostics d("missing.yaml");
    EXPECT_FALSE(read_regular_file((dir / "missing.yaml").string(), d, &bytes));
    EXPECT_EQ(d.errors().at(0).message,
              "cannot open the file: No such file or directory; expected a readable YAML file");
  }
  fs::remove_all(dir);
}

TEST(YamlSource, TextIsUtf8WithoutNulOrControlCharactersAndSaysWhere) {
  EXPECT_EQ(first_error("a: 1\nb: caf\xC3\xA9 \xFF\n"),
            "f.yaml:2:9: invalid UTF-8 (byte 0xFF); expected the file in UTF-8");
  EXPECT_EQ(first_error("a: \xC0\xAF\n"),
            "f.yaml:1:4: invalid UTF-8 (byte 0xC0); expected the file in UTF-8");  // overlong
  EXPECT_EQ(first_error("a: \xED\xA0\x80\n"),
            "f.yaml:1:4: invalid UTF-8 (byte 0xED); expected the file in UTF-8");  // surrogate
  EXPECT_EQ(first_error(std::string("a: 1\n\nb: x\0y\n", 13)),
            "f.yaml:3:5: a NUL byte; expected text (is this a binary or UTF-16 file?)");
  EXPECT_EQ(
      first_error("a: \x1b[31m\n"),
      "f.yaml:1:4: a control character (U+001B); expected printable text, tabs and line breaks");
  EXPECT_EQ(first_error("\xEF\xBB\xBF"
                        "a: 1\r\nb:\t2\n"),
            "");  // BOM, CRLF and tabs are text
}

TEST(YamlSource, OneDocumentOnly) {
  EXPECT_EQ(first_error("---\na: 1\n"), "");
  EXPECT_EQ(first_error("a: 1\n...\n# only a comment after the end\n"), "");
  EXPECT_EQ(
      first_error("a: 1\n---\nb: 2\n"),
      "f.yaml:2:1: a second YAML document (after '---' or '...'); expected one document per file");
  EXPECT_EQ(
      first_error("a: 1\n...\nb: 2\n"),
      "f.yaml:3:1: a second YAML document (after '---' or '...'); expected one document per file");
}

TEST(YamlSource, AliasesAreBoundedAndNeverRecursive) {
  // 10^6 nodes expanded from a few lines
  std::string bomb = "a: &a [x, x, x, x, x, x, x, x, x, x]\n";
  std::string prev = "a";
  for (const char* l : {"b", "c", "d", "e", "f"}) {
    bomb += std::string(l) + ": &" + l + " [";
    for (int i = 0; i < 10; ++i) bomb += (i ? ", *" : "*") + prev;
    bomb += "]\n";
    prev = l;
  }
  EXPECT_NE(first_error(bomb).find(
                "more than 200000 nodes, counting each alias (*) as the nodes it repeats"),
            std::string::npos);
  EXPECT_EQ(first_error("a: &a [1, *a]\n"),
            "f.yaml:1:11: an alias (*) refers to a node that contains it (a recursive alias); "
            "expected an alias to a complete node");
  EXPECT_EQ(first_error("a: &a {b: [c, {d: *a}]}\n").substr(0, 12), "f.yaml:1:19:");
  EXPECT_EQ(first_error("a: &a [1, 2]\nb: [*a, *a]\n"), "");  // ordinary aliases are fine
  EXPECT_NE(first_error("a: *nowhere\n").find("not valid YAML"), std::string::npos);
}

TEST(YamlSource, DeepNestingAndComplexKeysGetPlainMessages) {
  EXPECT_EQ(first_error("a: " + std::string(65, '[') + std::string(65, ']') + "\n").substr(0, 12),
            "f.yaml:1:67:");
  EXPECT_NE(first_error("a: " + std::string(100000, '[') + std::string(100000, ']') + "\n")
                .find("nested more than 64 levels deep"),
            std::string::npos);
  EXPECT_EQ(first_error("a: " + std::string(63, '[') + std::string(63, ']') + "\n"), "");
  EXPECT_EQ(first_error("? [a, b]\n: 1\n"),
            "f.yaml:1:3: a key is a list or a mapping (a complex key); expected a plain key name");
  EXPECT_EQ(first_error("x:\n  {a: 1}: 2\n"),
            "f.yaml:2:3: a key is a list or a mapping (a complex key); expected a plain key name");
}

TEST(YamlSource, BriefQuotesAreShortAndEscaped) {
  EXPECT_EQ(brief("abc"), "abc");
  EXPECT_EQ(brief("a\nb\tc\x01"), "a\\nb\\tc\\x01");
  const std::string passwd(5000, 'x');
  EXPECT_EQ(brief(passwd), std::string(60, 'x') + "... (5000 bytes)");
  EXPECT_EQ(brief("caf\xC3\xA9", 4), "caf\xC3\xA9");  // never cuts a character in two
  // a whole file as a plain scalar root is quoted briefly
  std::string lines;
  for (int i = 0; i < 100; ++i) lines += "root:x:0:0:root:/root:/bin/bash\n";
  const std::string e = first_error(lines);
  EXPECT_LT(e.size(), 200u) << e;
  EXPECT_NE(e.find("f.yaml:1:1: the file holds 'root:x:0:0:root:/root:/bin/bash "
                   "root:x:0:0:root:/root:/bin/b... (3199 bytes)'"),
            std::string::npos)
      << e;
}

TEST(YamlReader, MergeKeysFollowYaml11) {
  Diagnostics d("f.yaml");
  const YAML::Node n = YAML::Load(
      "base: &b {mass: 1, length: 2, com: 3}\n"
      "more: &m {length: 20, inertia: 30}\n"
      "link: {<<: [*b, *m], com: 0.5}\n");
  Map root(n, d, "");
  root.get("base");
  root.get("more");
  auto link = root.map("link");
  ASSERT_TRUE(link);
  EXPECT_EQ(*link->number("mass", NumberRule::positive("kg")), 1.0);    // merged
  EXPECT_EQ(*link->number("length", NumberRule::positive("m")), 2.0);   // first merge wins
  EXPECT_EQ(*link->number("com", NumberRule::any("m")), 0.5);           // own key wins
  EXPECT_EQ(*link->number("inertia", NumberRule::positive("")), 30.0);  // second merge
  link->finish();
  root.finish();
  EXPECT_TRUE(d.empty()) << d.errors()[0].format();
  // a quoted '<<' is an ordinary key
  Diagnostics d2("f.yaml");
  Map quoted(YAML::Load("'<<': {a: 1}\n"), d2, "");
  quoted.finish();
  ASSERT_EQ(d2.errors().size(), 1u);
  EXPECT_NE(d2.errors()[0].message.find("unknown key '<<'"), std::string::npos);
}

TEST(YamlReader, KeyChecksAreLinearAndErrorsCapped) {
  // 90 000 keys in one mapping, every one unknown and a tenth duplicated: quadratic checks
  // took minutes for this; errors stop at kMaxErrors and are counted
  std::string text;
  for (int i = 0; i < 90000; ++i) {
    text += 'k';
    text += std::to_string(i % 81000);
    text += ": 1\n";
  }
  Diagnostics d("f.yaml");
  const auto root_node = parse_text(text, d);
  ASSERT_TRUE(root_node);
  Map root(*root_node, d, "");
  root.get("study");
  root.finish();
  EXPECT_EQ(d.count(), 90000u);  // 9000 duplicates and 81000 unknown
  EXPECT_EQ(d.errors().size(), kMaxErrors);
  try {
    d.throw_if_any();
    FAIL();
  } catch (const CaseErrors& e) {
    EXPECT_EQ(e.errors().back().format(),
              "f.yaml: ... and 89950 more error(s) (only the first 50 are shown)");
  }
}

TEST(YamlReader, OverflowUnderflowAndDenormalsAreNamedAsSuch) {
  const auto err = [](const std::string& value) {
    Diagnostics d("f.yaml");
    Map m(YAML::Load("length: " + value + "\n"), d, "arm");
    m.number("length", NumberRule::positive("m"));
    return d.empty() ? std::string() : d.errors()[0].message;
  };
  EXPECT_EQ(err("1e400"),
            "'arm.length' is 1e400, which overflows a double (its largest is 1.8e308); "
            "expected a magnitude in [1e-100, 1e+100] or 0");
  EXPECT_EQ(err("1e-400"),
            "'arm.length' is 1e-400, which underflows a double to 0; expected 0 or a "
            "magnitude of at least 1e-100");
  EXPECT_EQ(err("4.9e-320"),
            "'arm.length' is 4.9e-320, a denormal number (below 2.2e-308 in magnitude, "
            "with lost precision); expected 0 or a magnitude of at least 1e-100");
  EXPECT_EQ(err("1e150"),
            "'arm.length' is 1e+150, outside the magnitudes armstudy computes with; "
            "expected 0 or a magnitude in [1e-100, 1e+100]");
  EXPECT_EQ(err("abc"), "'arm.length' is 'abc'; expected a number");
  EXPECT_EQ(err("0.4"), "");
  EXPECT_EQ(err("1e-16"), "");
}

}  // namespace
}  // namespace armstudy::cases
