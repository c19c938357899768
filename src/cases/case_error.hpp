// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// User-input errors of case files: `path:line:col: what is wrong; expected what`.

#include <stdexcept>
#include <string>
#include <vector>

namespace armstudy::cases {

/// One problem in a case file. line and column are 1-based; 0 when unknown.
struct CaseError {
  std::string path;
  int line = 0;
  int column = 0;
  std::string message;
  /// "path:line:col: message" (or "path: message" without a position); a control
  /// character of the path as \xNN.
  std::string format() const;
};

/// Every problem found in one file, thrown after the whole file was read.
class CaseErrors : public std::runtime_error {
 public:
  explicit CaseErrors(std::vector<CaseError> errors);
  const std::vector<CaseError>& errors() const { return errors_; }

 private:
  std::vector<CaseError> errors_;
};

}  // namespace armstudy::cases
