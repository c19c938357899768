// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "app/export_records.hpp"

namespace armstudy::app {

report::ExportRecord model_export_entry(const std::string& file, const std::string& motion,
                                        std::span<const scene::PoseSample> keys) {
  report::ExportRecord e;
  e.file = file;
  e.kind = "mjcf";
  e.what =
      "the case's MJCF, generated from its arm (the scene of the frames; the MuJoCo checks use "
      "the same bodies, masses and inertias), with one keyframe per frame of the strip of " +
      motion;
  e.motion = motion;
  e.keyframe_times_s.emplace();
  for (const auto& k : keys) e.keyframe_times_s->push_back(k.t);  // not finite: written null
  return e;
}

report::ExportRecord csv_export_entry(const report::MotionCsv& table, const std::string& motion) {
  report::ExportRecord e;
  e.file = table.file;
  e.kind = "motion_csv";
  e.what = table.what;
  e.motion = motion;
  e.rows = static_cast<long long>(table.rows());
  e.columns = table.headers();
  return e;
}

}  // namespace armstudy::app
