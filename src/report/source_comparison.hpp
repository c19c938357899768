// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The case's source beside armstudy: every figure and claim the source prints for the case
/// (the case file's `source:`, cases/source_spec.hpp) with armstudy's values read from the
/// case's own results.json, the difference, and the verdict. run_case writes it to
/// results["source"]; the report shows one line of it on page 1 and the table on page 2.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "cases/source_spec.hpp"
#include "report/page.hpp"
#include "report/results_record.hpp"

namespace armstudy::report {

/// The number at a value path of `results` (cases/source_spec.hpp: dotted keys, [N],
/// [k=v,...], or key:NAME for a key figure); nullopt when the path leads nowhere or to no
/// finite number.
std::optional<double> value_at(const nlohmann::json& results, const std::string& path);

/// Each printed item with armstudy's values and its verdict.
SourceRecord compare_with_source(const cases::SourceSpec& spec, const nlohmann::json& results);

/// The check that every difference from the source has its reason: passed when each row
/// that differs or is contradicted names a docs/defects.md entry and says why.
CheckRecord source_explained_check(const SourceRecord& source);

/// Page 1's line: how many printed figures armstudy agrees with and how many claims it
/// confirms.
std::string source_summary(const SourceRecord& source);

/// Page 2's part "Source and armstudy": the table of every row.
Section source_section(const SourceRecord& source);

}  // namespace armstudy::report
