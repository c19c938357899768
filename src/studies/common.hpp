// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// What every study shares: its status, progress reporting and checks recorded as data.

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace armstudy::studies {

/// Outcome of a study. An unsolvable study is data, not an exception (TOPP-RA ReturnCode).
enum class Status {
  kSolved,      ///< the study has an answer
  kUnsolvable,  ///< the task cannot be done (unreachable, infeasible limits, ...); see message
};

/// Progress callback: fraction done in [0, 1] and a short stage label. Called from the
/// thread that runs the study, never concurrently; must be cheap.
using ProgressFn = std::function<void(double fraction, std::string_view stage)>;

/// A check a study ran on its own answer, with its measured value and tolerance.
struct Check {
  std::string name;         ///< e.g. "signed_work_rest_to_rest"
  std::string description;  ///< a sentence for a reader
  double value = 0;         ///< measured
  double tolerance = 0;     ///< the bound the value must meet (value <= tolerance)
  bool passed = false;
};

/// Makes a check that passes when value <= tolerance.
inline Check make_check(std::string name, std::string description, double value, double tolerance) {
  return Check{std::move(name), std::move(description), value, tolerance, value <= tolerance};
}

}  // namespace armstudy::studies
