// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/throwing/profile.hpp"

#include <algorithm>
#include <cmath>

#include "core/check.hpp"
#include "core/types.hpp"

namespace armstudy::studies {

ActiveState evaluate_profile(const VelocityProfile& p, int stage, double t) {
  const double h = p.stage_length();
  // angle at the stage start: trapezoids of the earlier stages
  Eigen::Vector2d q = p.q0;
  for (int k = 0; k < stage; ++k) q += 0.5 * h * (p.v.col(k) + p.v.col(k + 1));
  const double tau = t - stage * h;
  ActiveState s;
  s.qdd = (p.v.col(stage + 1) - p.v.col(stage)) / h;
  s.qd = p.v.col(stage) + s.qdd * tau;
  s.q = q + p.v.col(stage) * tau + 0.5 * s.qdd * tau * tau;
  return s;
}

ActiveState evaluate_profile(const VelocityProfile& p, double t) {
  const int P = p.stages();
  const int stage = std::clamp(static_cast<int>(std::floor(t / p.stage_length())), 0, P - 1);
  return evaluate_profile(p, stage, t);
}

Eigen::Vector2d displacement(const VelocityProfile& p) {
  const double h = p.stage_length();
  Eigen::Vector2d d = Eigen::Vector2d::Zero();
  for (int k = 0; k < p.stages(); ++k) d += 0.5 * h * (p.v.col(k) + p.v.col(k + 1));
  return d;
}

void project_displacement(VelocityProfile& p, const Eigen::Vector2d& delta) {
  const int P = p.stages();
  ARM_THROW_UNLESS(P >= 2, "velocity profile has " << P << " stages; should have >= 2");
  const double h = p.stage_length();
  // displacement of the shape sin(pi t_k / tf) at the interior nodes (trapezoid rule)
  double shape = 0.0;
  for (int k = 1; k < P; ++k) shape += h * std::sin(core::kPi * k / P);
  const Eigen::Vector2d c = (delta - displacement(p)) / shape;
  for (int k = 1; k < P; ++k) p.v.col(k) += c * std::sin(core::kPi * k / P);
}

VelocityProfile prolong_profile(const VelocityProfile& p, int factor) {
  ARM_THROW_UNLESS(factor >= 1, "prolongation factor " << factor << " should be >= 1");
  VelocityProfile q = p;
  const int P = p.stages();
  q.v.resize(2, P * factor + 1);
  for (int k = 0; k < P; ++k)
    for (int m = 0; m < factor; ++m) {
      const double s = double(m) / factor;
      q.v.col(Eigen::Index(k) * factor + m) = (1 - s) * p.v.col(k) + s * p.v.col(k + 1);
    }
  q.v.col(Eigen::Index(P) * factor) = p.v.col(P);
  return q;
}

Eigen::Vector2d eq8_rate(const Eigen::Vector2d& q_i, const Eigen::Vector2d& qd_i,
                         const Eigen::Vector2d& q_f, const Eigen::Vector2d& qd_f, double tf,
                         double t) {
  // eq. 8 of 003 as corrected in docs/defects.md: meets both end rates, integrates to q_f - q_i
  return qd_i + (qd_f - qd_i) * (t / tf) +
         (core::kPi / 2) * ((q_f - q_i) / tf - (qd_i + qd_f) / 2) * std::sin(core::kPi * t / tf);
}

VelocityProfile eq8_profile(const Eigen::Vector2d& q_i, const Eigen::Vector2d& qd_i,
                            const Eigen::Vector2d& q_f, const Eigen::Vector2d& qd_f, double tf,
                            int stages) {
  ARM_THROW_UNLESS(stages >= 2, "IDP stages " << stages << " should be >= 2");
  ARM_THROW_UNLESS(tf > 0, "final time " << tf << " s should be > 0");
  VelocityProfile p;
  p.tf = tf;
  p.q0 = q_i;
  p.v.resize(2, stages + 1);
  for (int k = 0; k <= stages; ++k)
    p.v.col(k) = eq8_rate(q_i, qd_i, q_f, qd_f, tf, tf * k / stages);
  p.v.col(0) = qd_i;
  p.v.col(stages) = qd_f;
  project_displacement(p, q_f - q_i);
  return p;
}

}  // namespace armstudy::studies
