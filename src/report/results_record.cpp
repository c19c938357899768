// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/results_record.hpp"

namespace armstudy::report {

ResultsRecord read_record(const nlohmann::json& results) {
  if (!results.is_object())
    throw ResultsError(
        "", std::string("expected an object, found ") + fields_detail::type_name(results));
  const auto sv = results.find("schema_version");
  if (sv == results.end())
    throw ResultsError("/schema_version", "no schema_version: not an armstudy results.json");
  if (!sv->is_number_integer() || sv->get<long long>() != kSchemaVersion)
    throw ResultsError("/schema_version", "schema_version " + sv->dump() +
                                              " is not one this armstudy reads (" +
                                              std::to_string(kSchemaVersion) +
                                              "); read it with the armstudy that wrote it");
  const auto st = results.find("study");
  if (st == results.end()) throw ResultsError("/study", "missing");
  if (!st->is_string()) fields_detail::expected(*st, "/study", "a string");
  // everything but the study's own section, which its registry record reads
  const std::string study = st->get<std::string>();
  nlohmann::json shared = nlohmann::json::object();
  for (auto it = results.begin(); it != results.end(); ++it)
    if (it.key() != study) shared[it.key()] = it.value();
  return from_json<ResultsRecord>(shared);
}

}  // namespace armstudy::report
