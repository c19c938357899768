#pragma once
/// The placement study: sweep, exact checks, refinement, maps, curves, Pareto front and
/// evaluations (Kopmaz 2016, Ch. 4-9, with the defects of docs/defects.md corrected).

#include "studies/common.hpp"
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

/// Metrics and status of the thesis's line (x_s, phi) for one program table and
/// configuration, with the spec's margin and limits. Used by the sweep, the refinement
/// and the evaluations.
Candidate evaluate_candidate(const Spec& spec, const Arm2& arm, const ProgramTable& table,
                             int configuration, double x_s, double phi);

/// The status of a reachable candidate from its boundary distance, metrics and the spec's
/// margin and limits.
CandidateStatus classify(const Spec& spec, double boundary_distance, const LineMetrics& m);

}  // namespace armstudy::studies::placement
