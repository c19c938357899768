// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Uniform grids shared by the studies.

#include <vector>

namespace armstudy::studies {

/// n >= 2 evenly spaced values from a to b inclusive (n == 1 gives {a}).
std::vector<double> linspace(double a, double b, int n);

}  // namespace armstudy::studies
