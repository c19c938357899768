#pragma once
/// results.json "exports": what each file for other tools holds (model.xml, motion CSVs).

#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "report/motion_csv.hpp"
#include "scene/replay.hpp"

namespace armstudy::app {

/// {file, kind "mjcf", what, motion, keyframe_times_s}: model.xml with its keyframes.
nlohmann::json model_export_entry(const std::string& file, const std::string& motion,
                                  std::span<const scene::PoseSample> keys);

/// {file, kind "motion_csv", what, motion, rows, columns}: one motion CSV; `motion` names the
/// solver or optimiser (e.g. "exact", "idp").
nlohmann::json csv_export_entry(const report::MotionCsv& table, const std::string& motion);

}  // namespace armstudy::app
