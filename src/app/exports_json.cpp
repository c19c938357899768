#include "app/exports_json.hpp"

#include "app/json_numbers.hpp"

namespace armstudy::app {

nlohmann::json model_export_entry(const std::string& file, const std::string& motion,
                                  std::span<const scene::PoseSample> keys) {
  nlohmann::json times = nlohmann::json::array();
  for (const auto& k : keys) times.push_back(json_number(k.t));
  return {{"file", file},
          {"kind", "mjcf"},
          {"what",
           "the case's MJCF, generated from its arm (the scene of the frames; the MuJoCo "
           "checks use the same bodies, masses and inertias), with one keyframe per frame "
           "of the strip of " +
               motion},
          {"motion", motion},
          {"keyframe_times_s", times}};
}

nlohmann::json csv_export_entry(const report::MotionCsv& table, const std::string& motion) {
  return {{"file", table.file}, {"kind", "motion_csv"}, {"what", table.what},
          {"motion", motion},   {"rows", table.rows()}, {"columns", table.headers()}};
}

}  // namespace armstudy::app
