// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/case_error.hpp"

namespace armstudy::cases {
namespace {
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
  if (line <= 0) return path + ": " + message;
  return path + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message;
}

CaseErrors::CaseErrors(std::vector<CaseError> errors)
    : std::runtime_error(join(errors)), errors_(std::move(errors)) {}

}  // namespace armstudy::cases
