// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The second derivatives of a natural cubic spline through points at given knots, shared by
/// the tip path (path.cpp, 2-vectors) and the joint-space path (joint_path.cpp, one angle per
/// joint).

#include <vector>

namespace armstudy::studies::time_optimal {

/// Fills m[1..n-2] with the spline's second derivatives at the knots (m[0] = m[n-1] = 0, as
/// `m` holds them on entry): the tridiagonal system solved by the Thomas algorithm, every
/// coordinate at once. Requires n = knots.size() = pts.size() = m.size() > 2.
template <class V>
void natural_spline_second_derivatives(const std::vector<double>& knots, const std::vector<V>& pts,
                                       std::vector<V>& m) {
  const int k = static_cast<int>(pts.size()) - 2;
  std::vector<double> diag(k), up(k), low(k);
  std::vector<V> rhs(k);
  for (int j = 0; j < k; ++j) {
    const int i = j + 1;
    const double h0 = knots[i] - knots[i - 1], h1 = knots[i + 1] - knots[i];
    low[j] = h0;
    diag[j] = 2.0 * (h0 + h1);
    up[j] = h1;
    rhs[j] = 6.0 * ((pts[i + 1] - pts[i]) / h1 - (pts[i] - pts[i - 1]) / h0);
  }
  for (int j = 1; j < k; ++j) {
    const double w = low[j] / diag[j - 1];
    diag[j] -= w * up[j - 1];
    rhs[j] -= w * rhs[j - 1];
  }
  m[k] = rhs[k - 1] / diag[k - 1];
  for (int j = k - 2; j >= 0; --j) m[j + 1] = (rhs[j] - up[j] * m[j + 2]) / diag[j];
}

}  // namespace armstudy::studies::time_optimal
