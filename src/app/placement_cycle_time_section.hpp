// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// results.json's placement.cycle_time (studies/placement/study_results.hpp) from the
/// placement study's cycle-time objective (studies/placement/cycle_time_map.hpp).

#include <optional>

#include "studies/placement/result.hpp"
#include "studies/placement/spec.hpp"
#include "studies/placement/study_results.hpp"

namespace armstudy::app {

/// The section, or nothing when the spec has no cycle_time.
std::optional<studies::placement::StudyResults::CycleTimeSection> cycle_time_section(
    const studies::placement::Spec& spec, const studies::placement::Result& result);

}  // namespace armstudy::app
