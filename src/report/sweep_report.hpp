// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The sweep report: DIR/sweep/index.html, the key figures of every sweep case plotted over
/// the sweep's axes (e.g. the least energy over the link-length ratio, one curve per line
/// length), drawn from the sweep table that cli::sweep_table builds.

#include <filesystem>
#include <string>

#include "report/sweep_table.hpp"

namespace armstudy::report {

/// Writes `dir`/index.html, report.css and one SVG per key figure from `table`. The x axis is the
/// first parameter whose values are all numbers; each combination of the other parameters is one
/// curve. Cases whose status is not "ok" are left out of the plots and counted in a note. Returns
/// the number of plots.
/// @throws std::runtime_error when a file cannot be written.
int write_sweep_report(const std::filesystem::path& dir, const SweepTable& table,
                       const std::string& title);

}  // namespace armstudy::report
