// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Text from files and names (case names, messages, check names, units) made safe for where
/// armstudy prints it: a terminal or log, XML (junit.xml) and Markdown tables (summary.md,
/// diff.md). Control characters, terminal escapes and bytes that are not UTF-8 never reach
/// any of them raw.

#include <string>

namespace armstudy::report {

/// For a terminal or log line: every control character (C0, DEL, C1: ESC, CR, NUL, ...) and
/// every byte that is not part of valid UTF-8 as `\xNN`, a newline as `\n`, a backslash as
/// `\\`; everything else as it is.
std::string terminal_text(const std::string& s);

/// For a message of several lines (MuJoCo's "fromto points too close\nObject name = ...")
/// on a terminal: each line as terminal_text, the lines after the first on lines of their
/// own indented by `indent` (never a literal `\n`).
std::string terminal_lines(const std::string& s, const std::string& indent = "  ");

/// For XML 1.0 text and attribute values: & < > " ' as entities, tab and newline as
/// character references, and every character XML 1.0 does not allow (C0 controls, U+FFFE,
/// U+FFFF, bytes that are not UTF-8) as the visible text `\xNN`.
std::string xml_text(const std::string& s);

/// Calls f(code point, bytes) for each UTF-8 character of s, and f(-1, byte) for each byte
/// that is not part of a valid one (overlong forms and surrogates included).
template <class F>
void for_each_utf8(const std::string& s, F&& f) {
  size_t i = 0;
  while (i < s.size()) {
    const auto b = static_cast<unsigned char>(s[i]);
    int n = b < 0x80 ? 1 : (b >> 5) == 6 ? 2 : (b >> 4) == 14 ? 3 : (b >> 3) == 30 ? 4 : 0;
    long cp = n == 1 ? b : n == 2 ? (b & 0x1f) : n == 3 ? (b & 0x0f) : (b & 0x07);
    bool ok = n > 0 && i + n <= s.size();
    for (int k = 1; ok && k < n; ++k) {
      const auto c = static_cast<unsigned char>(s[i + k]);
      ok = (c >> 6) == 2;
      cp = (cp << 6) | (c & 0x3f);
    }
    if (ok) {
      static constexpr long kMin[] = {0, 0, 0x80, 0x800, 0x10000};
      ok = cp >= kMin[n] && cp <= 0x10ffff && !(cp >= 0xd800 && cp <= 0xdfff);
    }
    if (!ok) {
      f(-1L, s.substr(i, 1));
      ++i;
      continue;
    }
    f(cp, s.substr(i, n));
    i += n;
  }
}

/// `\xNN` of a byte.
std::string hex_byte(unsigned char b);

}  // namespace armstudy::report
