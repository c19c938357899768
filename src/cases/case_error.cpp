// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/case_error.hpp"

#include <cstdio>

namespace armstudy::cases {
namespace {
// a file's name as printed: a control character (an ESC of a name made to move the
// terminal's cursor) as the visible text \xNN, the rest as it is
std::string shown_path(const std::string& path) {
  std::string out;
  for (const char ch : path) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7F) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      out += hex;
    } else {
      out += ch;
    }
  }
  return out;
}

std::string join(const std::vector<CaseError>& errors) {
  std::string s;
  for (const CaseError& e : errors) {
    if (!s.empty()) s += "\n";
    s += e.format();
  }
  return s;
}
}  // namespace

std::string CaseError::format() const {
  if (line <= 0) return shown_path(path) + ": " + message;
  return shown_path(path) + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
         message;
}

CaseErrors::CaseErrors(std::vector<CaseError> errors)
    : std::runtime_error(join(errors)), errors_(std::move(errors)) {}

}  // namespace armstudy::cases
