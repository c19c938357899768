// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/markdown.hpp"

#include "report/text_escape.hpp"

namespace armstudy::report {

std::string md_cell(const std::string& s) {
  std::string o;
  for_each_utf8(s, [&](long cp, const std::string& bytes) {
    if (cp == '|')
      o += "\\|";
    else if (cp == '<')
      o += "&lt;";  // no HTML tag from a name reaches the page GitHub renders
    else if (cp == '\n' || cp == '\r' || cp == '\t')
      o += ' ';
    else if (cp < 0x20 || (cp >= 0x7f && cp <= 0x9f))  // controls and bytes that are not UTF-8
      for (const char b : bytes) o += hex_byte(static_cast<unsigned char>(b));
    else
      o += bytes;
  });
  return o;
}

}  // namespace armstudy::report
