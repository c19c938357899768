// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The cycle-time objective over root locations: the least traversal time of the
/// task line at every admissible node of the placement map (the energy maps' grid and
/// admissible set: the line at least the singularity margin inside both workspace circles),
/// on the exact solver's coarse grid, on all the sweep's threads; then the fastest node
/// refined by a compass search on the exact solver (the coarse grid, then the converged
/// one), and its duration converged by the time-optimal study (cycle_time.hpp).

#include "studies/common.hpp"
#include "studies/placement/cycle_time.hpp"
#include "studies/placement/result.hpp"
#include "studies/placement/spec.hpp"

namespace armstudy::studies::placement {

/// The map of `configuration` (spec.cycle_time must be set; threads as spec.threads).
CycleTimeMap cycle_time_map(const Spec& spec, int configuration, const ProgressFn& progress = {});

/// Refines the fastest admissible node of `map` (cycle_time_map of the same configuration).
CycleTimeOptimum cycle_time_optimum(const Spec& spec, int configuration, const CycleTimeMap& map);

/// The cycle-time objective of every configuration of the spec: its map, its optimum and
/// the least cycle time at each energy optimum of `energy` (solve's pairs) of that
/// configuration. `progress` goes from p0 to p1.
std::vector<CycleTime> cycle_times(const Spec& spec, const std::vector<ProgramConfig>& energy,
                                   const ProgressFn& progress, double p0, double p1);

}  // namespace armstudy::studies::placement
