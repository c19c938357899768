// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The motions of a case as CSV files beside results.json, for a reader's own tools: one
/// file per solver or optimiser, one row per sample, a header row naming every column with
/// its unit in brackets ("t [s]", "q1 [rad]", "qd1 [rad/s]", "qdd1 [rad/s^2]", "tau1 [N m]",
/// "voltage1 [V]", "current1 [A]"), numbers in the shortest form that reads back to the same
/// double (C locale; an empty field where a value is not finite).

#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/types.hpp"

namespace armstudy::report {

struct CsvColumn {
  std::string name;  ///< e.g. "q1"
  std::string unit;  ///< e.g. "rad" ("" for none)
  std::vector<double> values;
  /// "q1 [rad]" (or "q1" without a unit)
  std::string header() const { return unit.empty() ? name : name + " [" + unit + "]"; }
};

/// One motion's table: every column the same length.
struct MotionCsv {
  std::string file;  ///< e.g. "motion_exact.csv"
  std::string what;  ///< which motion, for results.json "exports"
  std::vector<CsvColumn> columns;

  /// Appends one column.
  void add(std::string name, std::string unit, std::vector<double> values);
  /// Appends one column per joint, `name`1 ... `name`N, from samples of joint vectors (or
  /// 2-vectors): values[k][j].
  void add_joints(const std::string& name, const std::string& unit,
                  const std::vector<core::JointVector>& values);
  void add_joints(const std::string& name, const std::string& unit,
                  const std::vector<Eigen::Vector2d>& values);
  /// Appends one column per row of `m` (joints x samples), `name`1 ... `name`N.
  void add_rows(const std::string& name, const std::string& unit, const Eigen::MatrixXd& m);
  /// Header names, e.g. {"t [s]", "q1 [rad]"}.
  std::vector<std::string> headers() const;
  /// Rows (the common column length). @throws std::invalid_argument if columns differ.
  size_t rows() const;
};

/// The CSV text of `table`. @throws std::invalid_argument for columns of different lengths.
std::string motion_csv_text(const MotionCsv& table);

/// Writes `dir`/table.file atomically; returns the file name.
std::string write_motion_csv(const std::filesystem::path& dir, const MotionCsv& table);

}  // namespace armstudy::report
