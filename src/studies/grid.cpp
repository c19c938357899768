// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/grid.hpp"

#include "core/check.hpp"

namespace armstudy::studies {

std::vector<double> linspace(double a, double b, int n) {
  ARM_THROW_UNLESS(n >= 1, "linspace count " << n << " should be >= 1");
  std::vector<double> v(n);
  if (n == 1) {
    v[0] = a;
    return v;
  }
  for (int i = 0; i < n; ++i) v[i] = a + (b - a) * i / (n - 1);
  v[n - 1] = b;
  return v;
}

}  // namespace armstudy::studies
