// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The sweep table: one row per case of a sweep, its point and its key figures. merge builds
/// it from the cases' results.json (cli::sweep_table) and writes it as sweep.json; diff
/// compares two of them row by row; the sweep report plots it. Its keys are written once,
/// in the `fields` lists below (report/results_fields.hpp makes the writer and reader).

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/results_fields.hpp"

namespace armstudy::report {

/// One case of the sweep.
struct SweepRow {
  std::string case_name;
  std::string status;  ///< "ok" (passed) or "failed"
  /// the value of every parameter of the table at this case, as the case file writes it;
  /// none when the case does not set it
  std::map<std::string, std::optional<std::string>> parameters;
  /// every figure of the table at this case; none when the case has no number for it
  std::map<std::string, std::optional<double>> key_figures;
};

template <class V>
void fields(V& v, SweepRow& x) {
  v("case", x.case_name, "the case id (its folder's name)");
  v("status", x.status, "ok: the case ended as it expects and passed its checks; else failed");
  v("parameters", x.parameters, "the case's value of each sweep parameter (its YAML text)");
  v("key_figures", x.key_figures, "the case's value of each key figure (null: none)");
}

/// The whole table (sweep.json).
struct SweepTable {
  std::vector<std::string> parameters;  ///< the sweep's key paths, sorted
  /// the key figures, in the studies' own order (the first is the headline)
  std::vector<std::string> figures;
  std::map<std::string, std::string> units;  ///< each figure's unit ("" for none)
  std::vector<SweepRow> rows;                ///< sorted by case id
};

template <class V>
void fields(V& v, SweepTable& x) {
  v("parameters", x.parameters, "the sweep's parameters (key paths of the base case), sorted");
  v("figures", x.figures, "the key figures, in the studies' order (the first is the headline)");
  v("units", x.units, "each key figure's unit (empty for none)");
  v("rows", x.rows, "one row per case, sorted by case id");
}

/// `j` is a sweep table's JSON: an object of exactly the table's keys (how armstudy knows
/// a sweep.json of its own before it replaces it).
inline bool has_sweep_table_keys(const nlohmann::json& j) {
  if (!j.is_object()) return false;
  std::set<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.insert(it.key());
  return keys == field_keys<SweepTable>();
}

}  // namespace armstudy::report
