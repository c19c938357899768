// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/overlay_wrap.hpp"

#include <algorithm>
#include <sstream>

namespace armstudy::scene {
namespace {

int line_width(const std::string& line, std::span<const int> w) {
  int px = 0;
  for (const char c : line) {
    const auto u = static_cast<unsigned char>(c);
    px += u < w.size() ? w[u] : (w.size() > 'M' ? w['M'] : 0);
  }
  return px;
}

}  // namespace

int overlay_text_width(const std::string& text, std::span<const int> char_width) {
  int widest = 0;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    widest = std::max(widest, line_width(line, char_width));
  return widest;
}

std::string wrap_overlay_text(const std::string& text, std::span<const int> char_width,
                              int max_px) {
  std::string out;
  std::istringstream in(text);
  bool first_line = true;
  for (std::string line; std::getline(in, line);) {
    if (!first_line) out += '\n';
    first_line = false;
    if (line_width(line, char_width) <= max_px) {
      out += line;
      continue;
    }
    std::string current;
    std::istringstream words(line);
    for (std::string word; words >> word;) {
      const std::string tried = current.empty() ? word : current + " " + word;
      if (!current.empty() && line_width(tried, char_width) > max_px) {
        out += current + '\n';
        current = word;
      } else {
        current = tried;
      }
    }
    out += current;
  }
  return out;
}

}  // namespace armstudy::scene
