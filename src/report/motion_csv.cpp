// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/motion_csv.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

#include "sys/atomic_file.hpp"

namespace armstudy::report {

void MotionCsv::add(std::string name, std::string unit, std::vector<double> values) {
  columns.push_back({std::move(name), std::move(unit), std::move(values)});
}

void MotionCsv::add_joints(const std::string& name, const std::string& unit,
                           const std::vector<core::JointVector>& values) {
  const int n = values.empty() ? 0 : static_cast<int>(values.front().size());
  for (int j = 0; j < n; ++j) {
    std::vector<double> col;
    col.reserve(values.size());
    for (const auto& v : values) col.push_back(j < v.size() ? v[j] : NAN);
    add(name + std::to_string(j + 1), unit, std::move(col));
  }
}

void MotionCsv::add_joints(const std::string& name, const std::string& unit,
                           const std::vector<Eigen::Vector2d>& values) {
  std::vector<core::JointVector> v;
  v.reserve(values.size());
  for (const auto& x : values) v.emplace_back(x);
  add_joints(name, unit, v);
}

void MotionCsv::add_rows(const std::string& name, const std::string& unit,
                         const Eigen::MatrixXd& m) {
  for (int j = 0; j < m.rows(); ++j) {
    std::vector<double> col(m.cols());
    for (int k = 0; k < m.cols(); ++k) col[k] = m(j, k);
    add(name + std::to_string(j + 1), unit, std::move(col));
  }
}

std::vector<std::string> MotionCsv::headers() const {
  std::vector<std::string> h;
  for (const auto& c : columns) h.push_back(c.header());
  return h;
}

size_t MotionCsv::rows() const {
  if (columns.empty()) return 0;
  const size_t n = columns.front().values.size();
  for (const auto& c : columns)
    if (c.values.size() != n)
      throw std::invalid_argument(file + ": column '" + c.header() + "' has " +
                                  std::to_string(c.values.size()) + " values; column '" +
                                  columns.front().header() + "' has " + std::to_string(n));
  return n;
}

std::string motion_csv_text(const MotionCsv& t) {
  const size_t n = t.rows();
  std::string out;
  for (size_t c = 0; c < t.columns.size(); ++c) out += (c ? "," : "") + t.columns[c].header();
  out += "\n";
  char buf[40];
  for (size_t k = 0; k < n; ++k) {
    for (size_t c = 0; c < t.columns.size(); ++c) {
      if (c) out += ',';
      const double v = t.columns[c].values[k];
      if (!std::isfinite(v)) continue;
      const auto r = std::to_chars(buf, buf + sizeof buf, v);  // shortest round trip
      out.append(buf, r.ptr);
    }
    out += '\n';
  }
  return out;
}

std::string write_motion_csv(const std::filesystem::path& dir, const MotionCsv& table) {
  sys::write_file_atomic(dir / table.file, motion_csv_text(table));
  return table.file;
}

}  // namespace armstudy::report
