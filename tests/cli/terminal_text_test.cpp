// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Text from files printed on a terminal or in a log: no control character, terminal
// escape or byte that is not UTF-8 reaches it raw, and one line stays one line.
#include <gtest/gtest.h>

#include <string>

#include "report/text_escape.hpp"

namespace {

using armstudy::report::terminal_text;

TEST(TerminalText, EscapesControlsEscapesAndForeignBytesKeepsUtf8) {
  EXPECT_EQ(terminal_text("case \x1b[2J\x1b]0;t\x07 name"), "case \\x1B[2J\\x1B]0;t\\x07 name");
  EXPECT_EQ(terminal_text("one\ntwo\r"), "one\\ntwo\\x0D");
  EXPECT_EQ(terminal_text(std::string("nul\0", 4)), "nul\\x00");
  EXPECT_EQ(terminal_text("\xc2\x9b"
                          "csi \x7f del"),
            "\\xC2\\x9Bcsi \\x7F del");
  EXPECT_EQ(terminal_text("bad \xff\xc3 end"), "bad \\xFF\\xC3 end");
  EXPECT_EQ(terminal_text("overlong \xc0\xaf"), "overlong \\xC0\\xAF");
  EXPECT_EQ(terminal_text("a\\x1B"), "a\\\\x1B") << "an escape can not be faked";
  EXPECT_EQ(terminal_text("Länge 0,5 m ≤ 1 m"), "Länge 0,5 m ≤ 1 m");
}

// MuJoCo's "fromto points too close\nObject name = ..." was printed with a literal \n
TEST(TerminalText, AMessageOfSeveralLinesKeepsItsLinesIndentedAndEscapesTheRest) {
  using armstudy::report::terminal_lines;
  EXPECT_EQ(terminal_lines("XML Error: too close\nObject name = link2\x1b[2J"),
            "XML Error: too close\n  Object name = link2\\x1B[2J");
  EXPECT_EQ(terminal_lines("one line\n"), "one line");
  EXPECT_EQ(terminal_lines("a\r\nb", "    "), "a\n    b");
}

}  // namespace
