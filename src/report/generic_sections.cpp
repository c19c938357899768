// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// the parts of a page every study shares: axis labels from unit-suffixed keys and the table
// of a typed value written as JSON (to_json)
#include <algorithm>
#include <map>
#include <sstream>

#include "report/number_format.hpp"
#include "report/study_sections.hpp"

namespace armstudy::report {
namespace {

using nlohmann::json;

struct UnitSuffix {
  const char* suffix;
  const char* unit;
};
// longest first: "_rad_s2" before "_rad_s" before "_s"
constexpr UnitSuffix kUnits[] = {
    {"_rad_s2", "rad/s²"}, {"_rad_s", "rad/s"}, {"_m_s2", "m/s²"}, {"_m_s", "m/s"},
    {"_deg_s", "deg/s"},   {"_Nm", "N m"},      {"_J", "J"},       {"_W", "W"},
    {"_V", "V"},           {"_A", "A"},         {"_rad", "rad"},   {"_deg", "deg"},
    {"_kg", "kg"},         {"_pct", "%"},       {"_percent", "%"}, {"_ms", "ms"},
    {"_m", "m"},           {"_s", "s"},
};

// what a plotted quantity is called, by its key stem
std::string quantity_name(const std::string& stem) {
  static const std::map<std::string, std::string> names = {
      {"q", "joint angle"},    {"qd", "joint velocity"},        {"qdd", "joint acceleration"},
      {"tau", "joint torque"}, {"torque", "joint torque"},      {"power", "power"},
      {"theta", "angle"},      {"theta_d", "angular velocity"}, {"voltage", "voltage"},
      {"current", "current"},  {"sd", "path speed s'"},         {"s", "path position s"},
  };
  if (auto it = names.find(stem); it != names.end()) return it->second;
  std::string out = stem;
  std::replace(out.begin(), out.end(), '_', ' ');
  return out;
}

}  // namespace

std::string label_from_key(const std::string& key) {
  for (const auto& u : kUnits) {
    const std::string suf = u.suffix;
    if (key.size() > suf.size() && key.compare(key.size() - suf.size(), suf.size(), suf) == 0)
      return quantity_name(key.substr(0, key.size() - suf.size())) + " (" + u.unit + ")";
  }
  return quantity_name(key);
}

namespace {
void flatten_json(const json& j, const std::string& path, Table* t) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) flatten_json(v, path.empty() ? k : path + "." + k, t);
  } else if (j.is_array()) {
    std::string v = "[";
    for (size_t i = 0; i < j.size(); ++i) {
      if (j[i].is_string()) return;  // sentences: shown elsewhere
      if (!j[i].is_primitive()) return;
      v += (i ? ", " : "") + (j[i].is_number() ? format_sig(j[i].get<double>(), 6) : j[i].dump());
    }
    t->rows.push_back({path, v + "]"});
  } else if (!j.is_null()) {
    t->rows.push_back({path, j.is_number()   ? format_sig(j.get<double>(), 6)
                             : j.is_string() ? j.get<std::string>()
                                             : j.dump()});
  }
}
}  // namespace

Table json_table(const json& obj, std::string caption) {
  Table t;
  t.caption = std::move(caption);
  t.header = {"quantity", "value"};
  flatten_json(obj, "", &t);
  // the dotted key paths in words: "tray.circle_offset_m" -> "tray, circle offset (m)"
  for (auto& row : t.rows) {
    if (row.empty()) continue;
    std::string words, part;
    std::stringstream in(row[0]);
    while (std::getline(in, part, '.')) words += (words.empty() ? "" : ", ") + label_from_key(part);
    row[0] = words;
  }
  return t;
}

}  // namespace armstudy::report
