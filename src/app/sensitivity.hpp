// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The sensitivity part of a case (`sensitivity:`, cases/sensitivity_spec.hpp): the solved
/// case re-solved with each listed key at its value minus and plus its step, through the
/// study's own loader on a copy of the case file, warm-started from the nominal answer where
/// the study can (StudyRun::warm_start), without rendering. For each key: the headline key
/// figure (StudyRun::headline) at each step, its change, the central elasticity
///   ((f+ - f-) / f0) / ((k+ - k-) / k0)
/// and the constraints that bind at each step (StudyRun::binding). A step whose value the
/// case refuses, or at which the study finds no answer, says so (docs/sensitivity.md).

#include <optional>

#include "app/pipeline.hpp"
#include "report/sensitivity_record.hpp"
#include "studies/common.hpp"

namespace armstudy::app {

/// Runs the sensitivity part of `nominal` (solved; its `info.sensitivity` not empty).
/// `progress` gets fractions from `from` to `to` and the step being solved. nullopt when
/// the case lists no key or its study names no headline figure. Each step's answer is offered
/// to nominal.run (StudyRun::offer_start: kept when it meets the case's own limits for less).
std::optional<report::SensitivityRecord> run_sensitivity(const LoadedCase& nominal,
                                                         const studies::ProgressFn& progress,
                                                         double from = 0.95, double to = 0.99);

/// The case's YAML text with `key` (a sensitivity key) set to `values` (one number, or one
/// per entry of a list) and its sensitivity and source parts left out. @throws
/// std::invalid_argument when the key names no number of the text.
std::string case_text_with(const std::string& yaml, const std::string& key,
                           const std::vector<double>& values);

}  // namespace armstudy::app
