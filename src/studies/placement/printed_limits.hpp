// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The actuator limits on the printed placements' motions. The refinement keeps a limit on
/// the continuous motion (its peaks refined between the samples, peaks.hpp) and the report
/// prints each optimum's and each margin-sweep point's peaks the same way, so a printed
/// peak above its limit is a real violation, beyond the peaks' resolution (below 1e-13
/// relative). This check names the largest such excess, relative to the limit, over every
/// printed point.

#include "studies/common.hpp"
#include "studies/placement/result.hpp"
#include "studies/placement/spec.hpp"

namespace armstudy::studies::placement {

/// The largest relative excess of a printed point's peak torque or power over its limit
/// (0 when every printed point keeps every limit), with the point that sets it.
struct PrintedLimitExcess {
  double relative = 0;  ///< max over points, joints, limits of (peak / limit - 1), >= 0
  std::string where;    ///< e.g. "cycloidal, conf. 1, margin 0.02 m: elbow power 12.001 W"
  int points = 0;       ///< printed points checked
};

PrintedLimitExcess printed_limit_excess(const Spec& spec, const Result& result);

/// The check "limits_at_printed_samples" (tolerance: 1e-12 relative, the continuous peaks'
/// resolution with room for roundoff), or none when the case sets no torque or power limit.
std::optional<Check> printed_limits_check(const Spec& spec, const Result& result);

}  // namespace armstudy::studies::placement
