// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/placement/peaks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "studies/placement/quadrature.hpp"

namespace armstudy::studies::placement {
namespace {

// quantity q of a sample: 0, 1 |tau_j|; 2, 3 |tau_j qd_j|
double quantity(const Arm2Sample& o, int q) {
  switch (q) {
    case 0: return std::abs(o.tau1);
    case 1: return std::abs(o.tau2);
    case 2: return std::abs(o.tau1 * o.qd1);
    default: return std::abs(o.tau2 * o.qd2);
  }
}

struct Refined {
  double value = 0;
  double spread = 0;  // the last bracket's values' spread
};

// the maximum of quantity q on [a, b] by golden section, to 1e-10 of T
Refined golden_max(const LinePower& power, int q, double a, double b, double T) {
  const auto f = [&](double t) { return quantity(power.sample(t), q); };
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - r * (b - a), e = a + r * (b - a);
  double fc = f(c), fe = f(e);
  Refined out;
  // the ends count too: a maximum at an end of the motion (t = 0 or T)
  out.value = std::max({f(a), f(b), fc, fe});
  for (int i = 0; i < 200 && b - a > 1e-10 * T; ++i) {
    if (fc >= fe) {
      b = e;
      e = c;
      fe = fc;
      c = b - r * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = e;
      fc = fe;
      e = a + r * (b - a);
      fe = f(e);
    }
    out.value = std::max({out.value, fc, fe});
  }
  out.spread = std::abs(fc - fe);
  return out;
}

}  // namespace

MotionPeaks continuous_peaks(const Arm2& arm, core::MotionProgram program, double duration,
                             double length, const Line& line, int configuration, int samples) {
  MotionPeaks out;
  const LinePower power(arm, program, duration, length, line, configuration);
  const int n = std::max(samples, 3);
  const double dt = duration / (n - 1);
  std::vector<Arm2Sample> s(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    s[size_t(k)] = power.sample(k == n - 1 ? duration : k * dt);
    if (!std::isfinite(s[size_t(k)].tau1) || !std::isfinite(s[size_t(k)].tau2) ||
        !std::isfinite(s[size_t(k)].qd1) || !std::isfinite(s[size_t(k)].qd2)) {
      out.finite = false;
      return out;
    }
  }
  constexpr double kUlp = std::numeric_limits<double>::epsilon();
  for (int q = 0; q < 4; ++q) {
    double sampled = 0;
    for (const Arm2Sample& o : s) sampled = std::max(sampled, quantity(o, q));
    double peak = sampled, spread = 0;
    for (int k = 0; k < n; ++k) {
      const double v = quantity(s[size_t(k)], q);
      const bool local = (k == 0 || v >= quantity(s[size_t(k - 1)], q)) &&
                         (k == n - 1 || v >= quantity(s[size_t(k) + 1], q));
      if (!local || v < 0.99 * sampled || !(v > 0)) continue;
      const double a = std::max(0.0, (k - 1) * dt), b = std::min(duration, (k + 1) * dt);
      const Refined r = golden_max(power, q, a, b, duration);
      if (r.value > peak) {
        peak = r.value;
        spread = r.spread;
      }
    }
    if (q < 2)
      out.torque[q] = peak;
    else
      out.power[q - 2] = peak;
    if (peak > 0) out.resolution = std::max(out.resolution, spread / peak + 8 * kUlp);
  }
  return out;
}

}  // namespace armstudy::studies::placement
