// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The placement study: sweep, exact checks, refinement, maps, curves, Pareto front and
/// evaluations (Kopmaz 2016, Ch. 4-9, with the defects of docs/defects.md corrected).
/// One candidate's status and metrics (classify, evaluate_candidate): candidate.hpp.

#include "studies/common.hpp"
#include "studies/placement/candidate.hpp"
#include "studies/placement/result.hpp"
#include "studies/placement/spec.hpp"

namespace armstudy::studies::placement {

/// Solves the placement study. Pure computation; sweeps run on spec.threads threads and
/// `progress` (may be empty) is called from the calling thread only. An impossible task
/// (line longer than Lmax, no admissible placement) is Result.status kUnsolvable with a
/// message, never an exception.
/// @throws std::invalid_argument for a spec the case loader should have rejected (e.g.
/// samples < 3, a chain that is not a 2-link horizontal arm).
Result solve(const Spec& spec, const ProgressFn& progress = {});

}  // namespace armstudy::studies::placement
