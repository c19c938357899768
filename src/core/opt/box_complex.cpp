// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "core/opt/box_complex.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/check.hpp"

namespace armstudy::core::opt {

// (over 60 lines, kept whole: Box's (1965) iteration as one loop, reflect, contract and
// check the spread, in the paper's order)
ComplexResult box_complex(const std::function<double(const Eigen::VectorXd&)>& f,
                          const std::function<bool(const Eigen::VectorXd&)>& feasible,
                          const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                          const Eigen::VectorXd& x0, const ComplexOptions& options) {
  const int n = static_cast<int>(x0.size());
  ARM_THROW_UNLESS(n >= 1, "Complex method needs >= 1 variable; got " << n);
  ARM_THROW_UNLESS(lo.size() == n && hi.size() == n, "Complex bounds have sizes "
                                                         << lo.size() << ", " << hi.size()
                                                         << "; expected " << n);
  ARM_THROW_UNLESS((lo.array() <= hi.array()).all(), "Complex bounds should have lo <= hi");
  ARM_THROW_UNLESS((x0.array() >= lo.array()).all() && (x0.array() <= hi.array()).all(),
                   "Complex start point should lie within the bounds");
  ARM_THROW_UNLESS(feasible(x0), "Complex start point should be feasible");
  const int k = options.points > 0 ? options.points : 2 * n;
  ARM_THROW_UNLESS(k >= n + 1, "Complex size " << k << " should be >= n + 1 = " << n + 1);
  ARM_THROW_UNLESS(options.alpha > 1.0, "Complex alpha " << options.alpha << " should be > 1");

  ComplexResult res;
  const auto eval = [&](const Eigen::VectorXd& x) {
    ++res.evaluations;
    return f(x);
  };
  std::mt19937 rng(options.seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<Eigen::VectorXd> pts{x0};
  std::vector<double> val{eval(x0)};

  // initial complex: random points in the box, pulled halfway towards the centroid of the
  // accepted ones until feasible (Box 1965, step 1)
  while (static_cast<int>(pts.size()) < k) {
    Eigen::VectorXd x(n);
    for (int i = 0; i < n; ++i) x[i] = lo[i] + uni(rng) * (hi[i] - lo[i]);
    Eigen::VectorXd c = Eigen::VectorXd::Zero(n);
    for (const auto& p : pts) c += p;
    c /= static_cast<double>(pts.size());
    int tries = 0;
    while (!feasible(x) && tries++ < options.max_retractions) x = 0.5 * (x + c);
    if (!feasible(x)) x = c;  // the centroid of feasible points of a convex-ish set
    if (!feasible(x)) x = pts[pts.size() - 1];
    pts.push_back(x);
    val.push_back(eval(x));
  }

  const auto spread_ok = [&] {
    const auto [mn, mx] = std::minmax_element(val.begin(), val.end());
    return *mx - *mn <= options.tolerance * std::max(1.0, std::abs(*mn));
  };
  for (res.iterations = 0; res.iterations < options.max_iterations; ++res.iterations) {
    if (spread_ok()) {
      res.converged = true;
      break;
    }
    const int worst = static_cast<int>(std::max_element(val.begin(), val.end()) - val.begin());
    Eigen::VectorXd c = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < k; ++i)
      if (i != worst) c += pts[i];
    c /= static_cast<double>(k - 1);
    // over-reflection through the centroid, clipped to the box (step 2-3)
    Eigen::VectorXd x = c + options.alpha * (c - pts[worst]);
    x = x.cwiseMax(lo).cwiseMin(hi);
    double fx = std::numeric_limits<double>::infinity();
    int tries = 0;
    for (; tries < options.max_retractions; ++tries) {
      if (feasible(x)) {
        fx = eval(x);
        // still the worst: keep retracting (step 4)
        bool still_worst = true;
        for (int i = 0; i < k; ++i)
          if (i != worst && val[i] > fx) still_worst = false;
        if (!still_worst) break;
      }
      x = 0.5 * (x + c);
    }
    if (tries == options.max_retractions) {
      // the complex has collapsed onto the centroid side: shrink it towards the best point
      const int best = static_cast<int>(std::min_element(val.begin(), val.end()) - val.begin());
      for (int i = 0; i < k; ++i) {
        if (i == best) continue;
        Eigen::VectorXd y = 0.5 * (pts[i] + pts[best]);
        if (feasible(y)) {
          pts[i] = y;
          val[i] = eval(y);
        }
      }
      continue;
    }
    pts[worst] = x;
    val[worst] = fx;
  }
  const int best = static_cast<int>(std::min_element(val.begin(), val.end()) - val.begin());
  res.x = pts[best];
  res.f = val[best];
  return res;
}

}  // namespace armstudy::core::opt
