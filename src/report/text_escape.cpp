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
