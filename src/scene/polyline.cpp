// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/polyline.hpp"

#include <algorithm>
#include <utility>

namespace armstudy::scene {
namespace {

// distance of p from the segment a-b
double distance_to_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                           const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double u = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + u * ab)).norm();
}

}  // namespace

std::vector<size_t> simplify_polyline(std::span<const Eigen::Vector2d> points, double tolerance) {
  const size_t n = points.size();
  std::vector<size_t> out;
  if (n == 0) return out;
  if (n <= 2 || !(tolerance > 0)) {
    for (size_t k = 0; k < n; ++k) out.push_back(k);
    return out;
  }
  std::vector<char> keep(n, 0);
  keep[0] = keep[n - 1] = 1;
  // an explicit stack of spans [lo, hi] whose ends are kept (no recursion depth limit)
  std::vector<std::pair<size_t, size_t>> todo{{0, n - 1}};
  while (!todo.empty()) {
    const auto [lo, hi] = todo.back();
    todo.pop_back();
    double worst = -1;
    size_t at = lo;
    for (size_t k = lo + 1; k < hi; ++k) {
      const double d = distance_to_segment(points[k], points[lo], points[hi]);
      if (d > worst) {
        worst = d;
        at = k;
      }
    }
    if (worst > tolerance) {
      keep[at] = 1;
      todo.emplace_back(lo, at);
      todo.emplace_back(at, hi);
    }
  }
  for (size_t k = 0; k < n; ++k)
    if (keep[k]) out.push_back(k);
  return out;
}

double subpixel_tolerance(double span_x, double span_y, int width, int height) {
  const double per_px = std::min(span_x / std::max(1, width), span_y / std::max(1, height));
  return 0.1 * per_px;
}

}  // namespace armstudy::scene
