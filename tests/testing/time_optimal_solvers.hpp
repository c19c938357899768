// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
// The time-optimal tests' look-up of one solver's answer in a result.

#include <stdexcept>
#include <string>

#include "studies/time_optimal/solve.hpp"

namespace armstudy::testing {

/// The answer of the solver named `name` ("exact", "dp", ...); throws if the result has none.
inline const studies::time_optimal::SolverResult& solver(const studies::time_optimal::Result& r,
                                                         const std::string& name) {
  for (const auto& s : r.solvers)
    if (s.name == name) return s;
  throw std::runtime_error("no solver " + name);
}

}  // namespace armstudy::testing
