// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/results_fields.hpp"

#include <utility>

namespace armstudy::report {

std::string unit_of_key(const std::string& key) {
  // longest suffix first: "_rad_s2" before "_rad_s" before "_rad" before "_s"
  static const std::pair<const char*, const char*> kUnits[] = {
      {"_Nm_s_per_rad", "N m s/rad"},
      {"_V_s_per_rad", "V s/rad"},
      {"_Nm_per_A", "N m/A"},
      {"_kg_m2", "kg m^2"},
      {"_rad_s2", "rad/s^2"},
      {"_deg_s", "deg/s"},
      {"_m_s2", "m/s^2"},
      {"_rad_s", "rad/s"},
      {"_sd_m_s", "m/s"},
      {"_m_s", "m/s"},
      {"_percent", "%"},
      {"_ohm", "ohm"},
      {"_deg", "deg"},
      {"_rad", "rad"},
      {"_Nm", "N m"},
      {"_kg", "kg"},
      {"_J", "J"},
      {"_W", "W"},
      {"_V", "V"},
      {"_A", "A"},
      {"_N", "N"},
      {"_m", "m"},
      {"_s", "s"},
  };
  for (const auto& [suffix, unit] : kUnits) {
    const std::string s = suffix;
    if (key.size() > s.size() && key.compare(key.size() - s.size(), s.size(), s) == 0) return unit;
  }
  return "";
}

}  // namespace armstudy::report
