// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// MuJoCo's error text (mj_loadXML's buffer, its error handler's message) as one line of an
/// armstudy message: MuJoCo's spans lines ("Error: fromto points too close ...\nObject name =
/// ..."), which a terminal or a log would show as a literal "\n" once escaped. Header-only:
/// the scene library, which does not link model_import, says MuJoCo's errors the same way.

#include <algorithm>
#include <string>
#include <string_view>

namespace armstudy::model_import {

/// `text` with its leading "Error: " dropped, its lines joined by "; " and blanks trimmed.
inline std::string mujoco_message(std::string_view text) {
  if (text.rfind("Error: ", 0) == 0) text.remove_prefix(7);
  std::string out;
  while (!text.empty()) {
    const size_t end = std::min(text.find_first_of("\r\n"), text.size());
    std::string_view line = text.substr(0, end);
    text.remove_prefix(std::min(end + 1, text.size()));
    while (!line.empty() && line.front() == ' ') line.remove_prefix(1);
    while (!line.empty() && line.back() == ' ') line.remove_suffix(1);
    if (line.empty()) continue;
    if (!out.empty()) out += "; ";
    out += line;
  }
  return out;
}

}  // namespace armstudy::model_import
