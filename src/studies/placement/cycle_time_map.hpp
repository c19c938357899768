// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The cycle-time objective over root locations: the least traversal time of the
/// task line at every admissible node of the placement map (the energy maps' grid and
/// admissible set: the line at least the singularity margin inside both workspace circles),
/// on the exact solver's coarse grid, on all the sweep's threads; then the fastest node
/// refined by a compass search on the exact solver (the coarse grid, then the converged
/// one), and its duration converged by the time-optimal study (cycle_time.hpp).

#include <string>
#include <vector>

#include "studies/common.hpp"
#include "studies/placement/cycle_time.hpp"
#include "studies/placement/result.hpp"
#include "studies/placement/spec.hpp"

namespace armstudy::studies::placement {

/// The map of `configuration` (spec.cycle_time must be set; threads as spec.threads).
CycleTimeMap cycle_time_map(const Spec& spec, int configuration, const ProgressFn& progress = {});

/// Refines the fastest admissible node of `map` (cycle_time_map of the same configuration).
CycleTimeOptimum cycle_time_optimum(const Spec& spec, int configuration, const CycleTimeMap& map);

/// The trade-off between the two objectives for one program and configuration: the
/// placements admissible for both (the energy objective's feasible nodes of `energy.map` with
/// a motion in `map`) that no other beats in both the least cycle time and the program's
/// energy in T, and both optima; first filtered on the maps' own values, then each node
/// evaluated again (CycleEnergyPoint) and filtered once more. By increasing time.
std::vector<CycleEnergyPoint> cycle_energy_front(const Spec& spec, const ProgramConfig& energy,
                                                 const CycleTimeMap& map,
                                                 const CycleTimeOptimum& optimum);

/// The cycle-time objective of every configuration of the spec: its map, its optimum and
/// the least cycle time at each energy optimum of `energy` (solve's pairs) of that
/// configuration. `progress` goes from p0 to p1.
std::vector<CycleTime> cycle_times(const Spec& spec, const std::vector<ProgramConfig>& energy,
                                   const ProgressFn& progress, double p0, double p1);

/// The cycle-time objective's answer in one sentence for the study's summary: the fastest
/// cycle, how much faster it is than the least cycle at the energy optimum of `program` in
/// `configuration` (the summary's least energy), what the fastest motion costs at either
/// placement, and the program's energy in T `duration` at both. "" without an optimum.
std::string cycle_time_sentence(const std::vector<CycleTime>& cycle_time,
                                core::MotionProgram program, int configuration, double duration);

}  // namespace armstudy::studies::placement
