// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// How much the answer depends on what the case assumed (`sensitivity:` in YAML): a list of
/// numeric keys of the case file, each re-solved at -step and +step around the value the
/// file gives it (app/sensitivity.hpp runs them; docs/sensitivity.md).
///
///   sensitivity:
///     - key: throwing.constraints.friction_coefficient   # a number written in the file
///       relative: 0.1                                     # +-10 % (the default)
///     - key: throwing.constraints.release_tolerance_deg
///       absolute: 0.25                                    # +-0.25 deg
///     - time_optimal.velocity_limit_rad_s                 # a list: every entry scaled, +-10 %
///
/// A key is a dotted path of mapping keys with `[N]` (1-based) into a list, as a sweep's
/// axis path; it must name a number (or a list of numbers, varied together by a relative
/// step) that the case file itself writes.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace armstudy::cases {

class Map;

/// The default relative step of a key given without one.
inline constexpr double kDefaultRelativeStep = 0.1;

/// The most keys a `sensitivity:` list may have: each is two re-solves of the case (and the
/// re-solves count in the case's work budget, docs/budgets.md).
inline constexpr size_t kMaxSensitivityKeys = 100;

/// One key to vary.
struct SensitivityItem {
  std::string key;       ///< dotted path into the case file
  bool relative = true;  ///< step is a share of the value (else in the key's own unit)
  double step = kDefaultRelativeStep;
  std::vector<double> nominal;  ///< the value(s) the file gives the key
  bool list = false;            ///< the key names a list of numbers
  std::string why;              ///< optional: what the key stands for, in words
};

/// The case's `sensitivity:` part.
struct SensitivitySpec {
  std::vector<SensitivityItem> items;
  bool empty() const { return items.empty(); }
};

/// Reads `sensitivity:` from the case's root mapping (nothing when absent); every problem
/// (a key naming no number of the file, a zero or negative step, both steps) goes to the
/// map's diagnostics with its line and column.
SensitivitySpec read_sensitivity(Map& root);

}  // namespace armstudy::cases
