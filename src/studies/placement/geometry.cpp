// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/placement/geometry.hpp"

#include <algorithm>
#include <cmath>

namespace armstudy::studies::placement {
namespace {
double acos_clamped(double x) { return std::acos(std::clamp(x, -1.0, 1.0)); }
double asin_clamped(double x) { return std::asin(std::clamp(x, -1.0, 1.0)); }
bool is_lmax(const Annulus& a, double L) { return std::abs(L - a.lmax) <= 1e-12 * a.lmax; }
}  // namespace

Annulus annulus(double L1, double L2) {
  return {L1, L2, std::abs(L1 - L2), L1 + L2, 4.0 * std::sqrt(L1 * L2)};
}

double longest_line(const Annulus& a, double margin) {
  const double R = a.outer - margin, r = a.inner + margin;
  if (R <= r) return 0.0;
  // chord of radius R tangent to radius r, as in (4.6)
  return 2.0 * std::sqrt(R * R - r * r);
}

XsInterval thesis_xs_interval(const Annulus& a, double L) {
  const double R = a.outer, r = a.inner;
  XsInterval xs;
  xs.init = R;
  if (is_lmax(a, L)) {
    // (4.7)
    xs.fin = R;
    xs.thesis_case = 1;
  } else if (L > a.lmax / 2) {
    // (4.8b)
    xs.fin = std::sqrt(R * R + L * L - 2.0 * R * L * std::cos(asin_clamped(r / R)));
    xs.thesis_case = 2;
  } else {
    // (4.9b)
    xs.fin = r;
    xs.thesis_case = 3;
  }
  return xs;
}

PhiInterval thesis_phi_interval(const Annulus& a, double L, double x_s) {
  const double R = a.outer, r = a.inner, pi = core::kPi;
  // end point on the outer circle: (4.11a), (4.12a), (4.13d)
  const double phi_outer = pi - acos_clamped((L * L + x_s * x_s - R * R) / (2.0 * L * x_s));
  // end point on the inner circle: (4.12d), (4.13c), (4.13f)
  const double phi_inner = pi - acos_clamped((L * L + x_s * x_s - r * r) / (2.0 * L * x_s));
  PhiInterval p;
  if (is_lmax(a, L)) {
    // (4.10)
    p.init = p.fin = pi - asin_clamped(r / R);
    p.thesis_case = 1;
  } else if (L >= a.lmax / 2) {
    // (4.11): from the outer circle to the tangent of the inner circle
    p.init = phi_outer;
    p.fin = pi - asin_clamped(r / x_s);
    p.thesis_case = 2;
  } else {
    if (L > 2.0 * a.L2) {
      // (4.12): tangent of the inner circle if the line reaches it, else end on it
      p.init = phi_outer;
      const double alpha = acos_clamped(r / x_s);
      p.fin = x_s * std::sin(alpha) <= L ? pi - (pi / 2 - alpha) : phi_inner;
      p.thesis_case = 3;
    } else {
      // (4.13): subcase 4.1 (R - x_s >= L) starts at 0, subcase 4.2 on the outer circle
      p.init = R - x_s >= L ? 0.0 : phi_outer;
      // (4.13b), lost in the text, taken as pi like (4.13e); (4.13c), (4.13f)
      p.fin = x_s - r >= L ? pi : phi_inner;
      p.thesis_case = 4;
    }
  }
  return p;
}

LineCheck check_line(double L1, double L2, const Line& line, double L) {
  const Annulus a = annulus(L1, L2);
  LineCheck c;
  // closest point of the segment to the root
  const double s_star = std::clamp(-line.start.dot(line.dir), 0.0, L);
  c.r_min = (line.start + s_star * line.dir).norm();
  c.r_max = std::max(line.start.norm(), (line.start + L * line.dir).norm());
  c.boundary_distance = std::min(c.r_min - a.inner, a.outer - c.r_max);
  const auto abs_sin = [&](double r) {
    const double c2 = std::clamp((r * r - L1 * L1 - L2 * L2) / (2.0 * L1 * L2), -1.0, 1.0);
    return std::sqrt(1.0 - c2 * c2);
  };
  c.min_abs_sin = std::min(abs_sin(c.r_min), abs_sin(c.r_max));
  return c;
}

}  // namespace armstudy::studies::placement
