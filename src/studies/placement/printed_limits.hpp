// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The actuator limits at the samples a placement is printed at. The refinement keeps a
/// limit at the sweep's samples (spec.samples); the report prints each optimum and each
/// margin-sweep point at the finer samples where its doubling converged, where a peak that
/// sits on its limit can read a little higher (the sampling error of a peak, ~h^2). This
/// check names the largest such excess, relative to the limit, over every printed point.

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

/// The check "limits_at_printed_samples" (tolerance: the peaks' convergence tolerance, 1e-3),
/// or none when the case sets no torque or power limit.
std::optional<Check> printed_limits_check(const Spec& spec, const Result& result);

}  // namespace armstudy::studies::placement
