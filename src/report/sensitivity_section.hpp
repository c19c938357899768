// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The sensitivity part of a case report (results["sensitivity"], report/sensitivity_record.hpp):
/// a tornado chart of the headline figure's change per key on page 1, largest influence
/// first, and the table of every key and step on page 2 or later.

#include <filesystem>
#include <string>

#include "report/page.hpp"
#include "report/sensitivity_record.hpp"

namespace armstudy::report {

/// Writes the tornado chart (sensitivity_tornado.svg) into `dir` and returns its file name
/// ("" when no step has a value); `caption` receives its caption.
std::string write_tornado(const std::filesystem::path& dir, const SensitivityRecord& s,
                          std::string* caption);

/// The keys by influence: the largest |change| at either step first (keys without a value
/// last, in the case's order).
std::vector<const SensitivityKeyRecord*> by_influence(const SensitivityRecord& s);

/// The page's section "Sensitivity": what was varied and the table of every key.
Section sensitivity_section(const SensitivityRecord& s);

}  // namespace armstudy::report
