// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/text_escape.hpp"

#include <cstdio>

namespace armstudy::report {

std::string hex_byte(unsigned char b) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "\\x%02X", b);
  return buf;
}

namespace {
// C0, DEL and C1 controls (ESC, CSI, NUL, CR, ...)
bool control(long cp) { return cp < 0x20 || (cp >= 0x7f && cp <= 0x9f); }

std::string escaped(long cp, const std::string& bytes) {
  if (cp < 0) return hex_byte(static_cast<unsigned char>(bytes[0]));
  std::string o;
  for (char c : bytes) o += hex_byte(static_cast<unsigned char>(c));
  return o;
}
}  // namespace

std::string terminal_text(const std::string& s) {
  std::string o;
  o.reserve(s.size());
  for_each_utf8(s, [&](long cp, const std::string& bytes) {
    if (cp == '\n')
      o += "\\n";
    else if (cp == '\\')
      o += "\\\\";
    else if (cp < 0 || control(cp))
      o += escaped(cp, bytes);
    else
      o += bytes;
  });
  return o;
}

std::string terminal_lines(const std::string& s, const std::string& indent) {
  std::string o;
  size_t at = 0;
  while (true) {
    const size_t nl = s.find('\n', at);
    std::string line = s.substr(at, nl == std::string::npos ? std::string::npos : nl - at);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    o += terminal_text(line);
    if (nl == std::string::npos || nl + 1 == s.size()) break;
    o += "\n" + indent;
    at = nl + 1;
  }
  return o;
}

std::string xml_text(const std::string& s) {
  std::string o;
  o.reserve(s.size());
  for_each_utf8(s, [&](long cp, const std::string& bytes) {
    switch (cp) {
      case '&': o += "&amp;"; return;
      case '<': o += "&lt;"; return;
      case '>': o += "&gt;"; return;
      case '"': o += "&quot;"; return;
      case '\'': o += "&apos;"; return;
      case '\t': o += "&#9;"; return;
      case '\n': o += "&#10;"; return;
      default: break;
    }
    if (cp < 0 || cp < 0x20 || cp == 0xfffe || cp == 0xffff || (cp >= 0x7f && cp <= 0x9f))
      o += escaped(cp, bytes);
    else
      o += bytes;
  });
  return o;
}

}  // namespace armstudy::report
