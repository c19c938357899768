// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// What results.json stores of a long series (a solver's nodes, a grid's curve, a sampled
/// motion): at most kMaxStoredPoints points, every stride-th and the last, so that a case
/// at its largest allowed grid writes a results.json armstudy reads back (docs/budgets.md:
/// 16 MiB). The study keeps every point for its own checks; the stride is written beside
/// the series, so a reader knows a subsample from the whole.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace armstudy::app {

/// The most points of one series results.json stores.
inline constexpr std::size_t kMaxStoredPoints = 2001;

/// The stride that keeps a series of `n` points within kMaxStoredPoints (every stride-th
/// and the last): 1 when it fits whole.
inline int stored_stride(std::size_t n) {
  if (n <= kMaxStoredPoints) return 1;
  // points 0, st, 2 st, ... <= n - 1 and the last: (n - 2) / st + 2 <= kMaxStoredPoints
  return static_cast<int>((n - 2) / (kMaxStoredPoints - 2) + 1);
}

/// The indices stored of a series of `n` points at `stride`: 0, stride, 2 stride, ... and
/// n - 1.
inline std::vector<std::size_t> stored_indices(std::size_t n, int stride) {
  std::vector<std::size_t> out;
  const std::size_t st = static_cast<std::size_t>(std::max(1, stride));
  for (std::size_t k = 0; k < n; k += st) out.push_back(k);
  if (n > 0 && out.back() != n - 1) out.push_back(n - 1);
  return out;
}

/// The entries of `v` at stored_indices(v.size(), stride).
template <class T>
std::vector<T> stored(const std::vector<T>& v, int stride) {
  if (stride <= 1) return v;
  std::vector<T> out;
  for (std::size_t k : stored_indices(v.size(), stride)) out.push_back(v[k]);
  return out;
}

}  // namespace armstudy::app
