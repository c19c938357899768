// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "core/ik2.hpp"

#include <algorithm>
#include <cmath>

#include "core/check.hpp"

namespace armstudy::core {

Reach reach_2link(double L1, double L2, const Eigen::Vector2d& p) {
  Reach r;
  r.radius = p.norm();
  r.inner = std::abs(L1 - L2);
  r.outer = L1 + L2;
  r.margin = std::min(r.radius - r.inner, r.outer - r.radius);
  return r;
}

std::optional<Eigen::Vector2d> ik_2link(double L1, double L2, const Eigen::Vector2d& p,
                                        int configuration) {
  ARM_THROW_UNLESS(configuration == 1 || configuration == 2,
                   "configuration " << configuration << " should be 1 or 2");
  const double r2 = p.squaredNorm();
  double c2 = (r2 - L1 * L1 - L2 * L2) / (2.0 * L1 * L2);
  if (c2 > 1.0 + 1e-12 || c2 < -1.0 - 1e-12) return std::nullopt;
  c2 = std::clamp(c2, -1.0, 1.0);
  double q2 = std::acos(c2);
  if (configuration == 2) q2 = -q2;
  const double q1 = std::atan2(p.y(), p.x()) - std::atan2(L2 * std::sin(q2), L1 + L2 * c2);
  return Eigen::Vector2d(q1, q2);
}

std::optional<Ik2State> ik_2link_motion(double L1, double L2, const Eigen::Vector2d& p,
                                        const Eigen::Vector2d& v, const Eigen::Vector2d& a,
                                        int configuration) {
  const auto q = ik_2link(L1, L2, p, configuration);
  if (!q) return std::nullopt;
  Ik2State st;
  st.q = *q;
  const double t1 = (*q)[0], t12 = (*q)[0] + (*q)[1];
  const double s1 = std::sin(t1), c1 = std::cos(t1), s12 = std::sin(t12), c12 = std::cos(t12);
  st.sin_q2 = std::sin((*q)[1]);
  // J = [[-L1 s1 - L2 s12, -L2 s12], [L1 c1 + L2 c12, L2 c12]], det J = L1 L2 sin q2
  const double det = L1 * L2 * st.sin_q2;
  const double j11 = -L1 * s1 - L2 * s12, j12 = -L2 * s12;
  const double j21 = L1 * c1 + L2 * c12, j22 = L2 * c12;
  const auto solve = [&](const Eigen::Vector2d& b) {
    return Eigen::Vector2d((j22 * b.x() - j12 * b.y()) / det, (-j21 * b.x() + j11 * b.y()) / det);
  };
  st.qd = solve(v);
  // Jdot qd: the centripetal acceleration of the tip at zero joint acceleration
  const double w1 = st.qd[0], w12 = st.qd[0] + st.qd[1];
  const Eigen::Vector2d jd_qd(-L1 * c1 * w1 * w1 - L2 * c12 * w12 * w12,
                              -L1 * s1 * w1 * w1 - L2 * s12 * w12 * w12);
  st.qdd = solve(a - jd_qd);
  return st;
}

}  // namespace armstudy::core
