// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "core/energy.hpp"

#include "core/check.hpp"

namespace armstudy::core {

double integrate_trapezoid(std::span<const double> t, std::span<const double> y) {
  ARM_THROW_UNLESS(t.size() == y.size(),
                   "integrate: " << t.size() << " times but " << y.size() << " samples");
  double sum = 0.0;
  for (size_t k = 1; k < t.size(); ++k) sum += 0.5 * (t[k] - t[k - 1]) * (y[k] + y[k - 1]);
  return sum;
}

double integrate_simpson(std::span<const double> y, double h) {
  const size_t n = y.size();
  if (n < 2) return 0.0;
  if (n % 2 == 0) {
    double sum = 0.0;
    for (size_t k = 1; k < n; ++k) sum += 0.5 * h * (y[k] + y[k - 1]);
    return sum;
  }
  double sum = y[0] + y[n - 1];
  for (size_t k = 1; k + 1 < n; ++k) sum += (k % 2 ? 4.0 : 2.0) * y[k];
  return sum * h / 3.0;
}

}  // namespace armstudy::core
