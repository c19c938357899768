// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The integrators of the tray-arm simulations: DOPRI5 meets its tolerance on a problem
// with a known solution, hits the requested times exactly, and RK4 converges at 4th order.
#include "core/integrators.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace armstudy::core {
namespace {

// harmonic oscillator x'' = -w^2 x: x = cos(w t), v = -w sin(w t)
OdeState oscillator(double w, const OdeState& x) {
  OdeState d(2);
  d << x[1], -w * w * x[0];
  return d;
}

TEST(Integrators, Dopri5MeetsItsToleranceOnTheHarmonicOscillator) {
  const double w = 7.0;
  OdeState x0(2);
  x0 << 1.0, 0.0;
  std::vector<double> times;
  for (int k = 1; k <= 20; ++k) times.push_back(0.1 * k);
  for (double tol : {1e-6, 1e-9, 1e-12}) {
    Dopri5Options opt;
    opt.rtol = opt.atol = tol;
    Dopri5Stats st;
    const auto xs = integrate_dopri5([&](double, const OdeState& x) { return oscillator(w, x); },
                                     0.0, x0, times, opt, &st);
    ASSERT_EQ(xs.size(), times.size());
    double err = 0;
    for (size_t k = 0; k < times.size(); ++k)
      err = std::max(err, std::abs(xs[k][0] - std::cos(w * times[k])));
    // global error stays within a modest multiple of the per-step tolerance
    EXPECT_LT(err, 200 * tol) << "tol " << tol;
    EXPECT_GT(st.accepted, 0);
  }
}

TEST(Integrators, Rk4ErrorShrinksSixteenfoldWhenTheStepHalves) {
  const double w = 3.0, T = 2.0;
  auto run = [&](int n) {
    OdeState x(2);
    x << 1.0, 0.0;
    const double h = T / n;
    for (int k = 0; k < n; ++k)
      x = rk4_step([&](double, const OdeState& s) { return oscillator(w, s); }, k * h, x, h);
    return std::abs(x[0] - std::cos(w * T));
  };
  const double e1 = run(200), e2 = run(400);
  EXPECT_NEAR(std::log2(e1 / e2), 4.0, 0.1);
}

TEST(Integrators, Dopri5ReportsAStepUnderflowInsteadOfLooping) {
  // x' = 1/(1 - t) blows up at t = 1
  OdeState x0(1);
  x0 << 0.0;
  Dopri5Options opt;
  opt.h_min = 1e-9;
  EXPECT_THROW(integrate_dopri5(
                   [](double t, const OdeState&) {
                     OdeState d(1);
                     d << 1.0 / ((1.0 - t) * (1.0 - t));
                     return d;
                   },
                   0.0, x0, {2.0}, opt),
               std::runtime_error);
}

}  // namespace
}  // namespace armstudy::core
