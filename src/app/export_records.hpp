// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// results.json "exports": what each file for other tools holds (model.xml, motion CSVs), as
/// the typed records (report::ExportRecord) a pipeline's write_exports returns to run_case.

#include <span>
#include <string>

#include "report/motion_csv.hpp"
#include "report/results_record.hpp"
#include "scene/replay.hpp"

namespace armstudy::app {

/// {file, kind "mjcf", what, motion, keyframe_times_s}: model.xml with its keyframes.
report::ExportRecord model_export_entry(const std::string& file, const std::string& motion,
                                        std::span<const scene::PoseSample> keys);

/// {file, kind "motion_csv", what, motion, rows, columns}: one motion CSV; `motion` names the
/// solver or optimiser (e.g. "exact", "idp").
report::ExportRecord csv_export_entry(const report::MotionCsv& table, const std::string& motion);

}  // namespace armstudy::app
