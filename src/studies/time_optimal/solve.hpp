// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The time-optimal study: exact (reachability) solver, dynamic programming and Box's
/// Complex method on one problem, each solution re-checked by dense resampling.

#include <vector>

#include "studies/common.hpp"
#include "studies/time_optimal/result.hpp"
#include "studies/time_optimal/spec.hpp"

namespace armstudy::studies::time_optimal {

/// Solves `spec`. A path outside the workspace or through a singular pose, or limits that
/// hold the arm still, give Status::kUnsolvable with a message naming the limit (or the
/// reason) and the place on the path. @throws std::invalid_argument for an invalid spec
/// (e.g. a chain without 2 links, fewer than 2 path points, non-positive counts).
Result solve(const Spec& spec, const ProgressFn& progress = {});

/// The study's checks on its own answer: the exact duration no longer than every DP and
/// Complex duration (1e-9 relative) and the convergence table's, every limit met by the
/// exact solution (1e-6 relative) and by the others.
std::vector<Check> checks(const Result& result);

/// Relative limit overshoot tolerated for the exact solution under dense resampling (at
/// least; see limit_tolerance).
inline constexpr double kExactTolerance = 1e-6;

/// Relative limit overshoot tolerated for the DP and Complex solutions: they enforce the
/// limits at `checks_per_segment` + 1 points of each segment (doubled until they meet this),
/// not in between.
inline constexpr double kCoarseViolationTolerance = 1e-3;

/// The tolerance of a solver's `<name>_meets_limits` check and why.
struct LimitTolerance {
  double value = 0;  ///< relative overshoot
  std::string why;   ///< a sentence
};

/// A limit overshoot is tolerated within the error the solver's own method allows: slowing a
/// motion by a fraction e lowers its joint rates by e and its inertial torques and
/// accelerations by about 2 e, so an overshoot below the duration's own error is within the
/// answer's accuracy. For the exact solver the larger of kExactTolerance and the stated
/// error of its grid duration (its distance from the converged duration plus the
/// extrapolation's error); for DP and Complex the larger of kCoarseViolationTolerance and
/// their excess over the converged exact duration (their discretisation error).
LimitTolerance limit_tolerance(const Result& result, const SolverResult& solver);

}  // namespace armstudy::studies::time_optimal
