// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/time_optimal/two_link_dynamics.hpp"

#include <cmath>

#include "core/check.hpp"

namespace armstudy::studies::time_optimal {

TwoLinkDynamics make_two_link_dynamics(const core::PlanarChain& chain) {
  ARM_THROW_UNLESS(chain.num_links() == 2,
                   "the 2-link dynamics need 2 links, the chain has " << chain.num_links());
  TwoLinkDynamics d;
  d.L1 = chain.links[0].length;
  d.gravity = chain.gravity;
  d.base_angle = chain.base_angle;
  double J1 = 0, J2 = 0;
  const auto add = [&](int link, double m, double x, double y, double I) {
    if (link == 0) {
      J1 += I + m * (x * x + y * y);
      d.X1 += m * x;
      d.Y1 += m * y;
    } else {
      J2 += I + m * (x * x + y * y);
      d.m2 += m;
      d.X2 += m * x;
      d.Y2 += m * y;
    }
  };
  for (int i = 0; i < 2; ++i) {
    const core::Link& l = chain.links[i];
    add(i, l.mass, l.com, l.com_lateral, l.inertia);
  }
  for (const core::PointMass& p : chain.point_masses) add(p.link, p.mass, p.x, p.y, 0.0);
  d.a11 = J1 + d.m2 * d.L1 * d.L1 + J2;
  d.a12 = J2;
  d.a22 = J2;
  d.A = d.L1 * d.X2;
  d.B = d.L1 * d.Y2;
  for (const core::SpinningInertia& s : chain.spinners) {
    d.a11 += s.inertia * s.coeffs[0] * s.coeffs[0];
    d.a12 += s.inertia * s.coeffs[0] * s.coeffs[1];
    d.a22 += s.inertia * s.coeffs[1] * s.coeffs[1];
  }
  return d;
}

void path_dynamics(const TwoLinkDynamics& d, const core::JointVector& q,
                   const core::JointVector& dq, const core::JointVector& ddq, core::JointVector* a,
                   core::JointVector* b, core::JointVector* c) {
  path_dynamics_cs(d, std::cos(q[1]), std::sin(q[1]), q, dq, ddq, a, b, c);
}

void path_dynamics_cs(const TwoLinkDynamics& d, double c2, double s2, const core::JointVector& q,
                      const core::JointVector& dq, const core::JointVector& ddq,
                      core::JointVector* a, core::JointVector* b, core::JointVector* c) {
  const double rates[2][2] = {{dq[0], dq[1]}, {ddq[0], ddq[1]}};
  if (d.gravity == 0.0) {
    path_dynamics_abs(d, c2, s2, 0.0, 0.0, 0.0, 0.0, rates[0], rates[1], a, b, c);
    return;
  }
  const double t1 = d.base_angle + q[0], t12 = t1 + q[1];
  path_dynamics_abs(d, c2, s2, std::cos(t1), std::sin(t1), std::cos(t12), std::sin(t12), rates[0],
                    rates[1], a, b, c);
}

void path_dynamics_abs(const TwoLinkDynamics& d, double c2, double s2, double ct1, double st1,
                       double ct12, double st12, const double dq[2], const double ddq[2],
                       core::JointVector* a, core::JointVector* b, core::JointVector* c) {
  const double g = d.A * c2 - d.B * s2;
  const double gp = -d.A * s2 - d.B * c2;
  const double m11 = d.a11 + 2.0 * g, m12 = d.a12 + g, m22 = d.a22;
  a->resize(2);
  b->resize(2);
  c->resize(2);
  (*a)[0] = m11 * dq[0] + m12 * dq[1];
  (*a)[1] = m12 * dq[0] + m22 * dq[1];
  (*b)[0] = m11 * ddq[0] + m12 * ddq[1] + gp * (2.0 * dq[0] * dq[1] + dq[1] * dq[1]);
  (*b)[1] = m12 * ddq[0] + m22 * ddq[1] - gp * dq[0] * dq[0];
  if (d.gravity == 0.0) {
    (*c)[0] = 0.0;
    (*c)[1] = 0.0;
    return;
  }
  (*c)[1] = d.gravity * (ct12 * d.X2 - st12 * d.Y2);
  (*c)[0] = d.gravity * (ct1 * (d.X1 + d.L1 * d.m2) - st1 * d.Y1) + (*c)[1];
}

void inverse_dynamics(const TwoLinkDynamics& d, const core::JointVector& q,
                      const core::JointVector& qd, const core::JointVector& qdd,
                      core::JointVector* tau) {
  const double c2 = std::cos(q[1]), s2 = std::sin(q[1]);
  const double g = d.A * c2 - d.B * s2;
  const double gp = -d.A * s2 - d.B * c2;
  const double m11 = d.a11 + 2.0 * g, m12 = d.a12 + g, m22 = d.a22;
  tau->resize(2);
  (*tau)[0] = m11 * qdd[0] + m12 * qdd[1] + gp * (2.0 * qd[0] * qd[1] + qd[1] * qd[1]);
  (*tau)[1] = m12 * qdd[0] + m22 * qdd[1] - gp * qd[0] * qd[0];
  if (d.gravity == 0.0) return;
  const double t1 = d.base_angle + q[0], t12 = t1 + q[1];
  const double ct1 = std::cos(t1), st1 = std::sin(t1), ct12 = std::cos(t12), st12 = std::sin(t12);
  const double g2 = d.gravity * (ct12 * d.X2 - st12 * d.Y2);
  (*tau)[1] += g2;
  (*tau)[0] += d.gravity * (ct1 * (d.X1 + d.L1 * d.m2) - st1 * d.Y1) + g2;
}

}  // namespace armstudy::studies::time_optimal
