// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// One candidate line of the placement study: its status (unreachable, singular, over a
/// limit, feasible) and its metrics. Used by the sweep (solve.cpp), the refinement
/// (refine.cpp) and the evaluations; neither of those includes the other.

#include "studies/placement/arm2.hpp"
#include "studies/placement/result.hpp"
#include "studies/placement/spec.hpp"

namespace armstudy::studies::placement {

/// m, a line this far outside the annulus touches it
inline constexpr double kTouch = 1e-9;
/// m, a line this much closer than the margin is on it (a refinement along the constraint
/// ends within roundoff of it, on either side)
inline constexpr double kMarginTol = 1e-12;

/// Whether the sampled peaks of `m` are within the spec's torque and power limits.
bool within_limits(const Spec& spec, const LineMetrics& m);

/// The status of a reachable candidate from its boundary distance, metrics and the spec's
/// margin and limits.
CandidateStatus classify(const Spec& spec, double boundary_distance, const LineMetrics& m);

/// Metrics and status of the thesis's line (x_s, phi) for one program table and
/// configuration, with the spec's margin and limits. Used by the sweep, the refinement
/// and the evaluations.
Candidate evaluate_candidate(const Spec& spec, const Arm2& arm, const ProgramTable& table,
                             int configuration, double x_s, double phi);

}  // namespace armstudy::studies::placement
