// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
// The bundled vertical 3-link time-optimal case (reports/cases/time-optimal-3link.yaml),
// loaded with its own loader, with settings small enough for a unit test.

#include <gtest/gtest.h>

#include <string>

#include "cases/time_optimal_case.hpp"
#include "cases/yaml_reader.hpp"
#include "testing/case_keys.hpp"

namespace armstudy::testing {

inline std::string three_link_case_path() {
  return std::string(ARMSTUDY_SOURCE_DIR) + "/reports/cases/time-optimal-3link.yaml";
}

/// The case's spec (its arm, joint-space spline, ranges and limits) on a 400-point exact
/// grid, DP on 10 segments with 100 levels, no convergence table.
inline studies::time_optimal::Spec three_link_spec() {
  const std::string path = three_link_case_path();
  cases::Diagnostics d(path);
  std::string text;
  const auto node = cases::parse_file(path, d, &text);
  EXPECT_TRUE(node) << path;
  cases::Map root(*node, d, "");
  mark_cli_keys(root);
  studies::time_optimal::Spec spec = cases::load_time_optimal(root);
  root.finish();
  EXPECT_TRUE(d.empty()) << path;
  spec.exact.grid_points = 400;
  spec.dp.segments = 10;
  spec.dp.levels = 100;
  spec.dp.convergence_segments = {};
  spec.complex.max_iterations = 5000;
  return spec;
}

}  // namespace armstudy::testing
