// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Box's Complex method (M. J. Box, "A new method of constrained optimization and a
/// comparison with other methods", Computer Journal 8, 1965): derivative-free minimisation
/// of f(x) subject to bounds lo <= x <= hi and implicit constraints given as a feasibility
/// predicate. Arm agnostic; used by the time-optimal study as the source's nonlinear
/// programming comparison (Ozkipcak 1994).
///
/// A complex of k >= n+1 feasible points (default 2n) is evolved: the worst point is
/// reflected through the centroid of the others by alpha (default 1.3); a reflection that
/// leaves the bounds is clipped to them, one that is infeasible or still the worst is moved
/// halfway towards the centroid until it is neither. Random points come from a local
/// std::mt19937 with a fixed seed, so a run is reproducible.

#include <functional>

#include <Eigen/Dense>

namespace armstudy::core::opt {

struct ComplexOptions {
  int points = 0;              ///< complex size k (0: 2 n); >= n + 1
  double alpha = 1.3;          ///< reflection factor, > 1 (Box)
  int max_iterations = 20000;  ///< reflections
  int max_retractions = 60;    ///< halvings towards the centroid per reflection
  /// converged when max f - min f over the complex <= tolerance * max(1, |min f|)
  double tolerance = 1e-10;
  unsigned seed = 1;
};

struct ComplexResult {
  Eigen::VectorXd x;       ///< best point found (n)
  double f = 0;            ///< f(x)
  int iterations = 0;      ///< reflections made
  long evaluations = 0;    ///< calls of f
  bool converged = false;  ///< the spread criterion was met (else max_iterations ran out)
};

/// Minimises f over the feasible box points, starting from the feasible point x0 (n).
/// `feasible` judges implicit constraints (bounds are enforced by the method itself); f is
/// only evaluated at feasible points.
/// @throws std::invalid_argument if sizes differ, lo > hi, x0 is outside the bounds or
/// infeasible, or options are out of range.
ComplexResult box_complex(const std::function<double(const Eigen::VectorXd&)>& f,
                          const std::function<bool(const Eigen::VectorXd&)>& feasible,
                          const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                          const Eigen::VectorXd& x0, const ComplexOptions& options = {});

}  // namespace armstudy::core::opt
