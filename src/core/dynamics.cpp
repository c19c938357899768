// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "core/dynamics.hpp"

#include "core/check.hpp"
#include "core/kinematics.hpp"

namespace armstudy::core {
namespace {

// calls f(link, p_L, mass, inertia) for every rigid body of the chain
template <typename F>
void for_each_body(const PlanarChain& chain, F&& f) {
  for (int i = 0; i < chain.num_links(); ++i) {
    const Link& l = chain.links[i];
    f(i, Eigen::Vector2d(l.com, l.com_lateral), l.mass, l.inertia);
  }
  for (const PointMass& p : chain.point_masses) f(p.link, Eigen::Vector2d(p.x, p.y), p.mass, 0.0);
}

void check_sizes(const PlanarChain& chain, const JointVector& a, const char* name) {
  ARM_THROW_UNLESS(a.size() == chain.num_links(), name << " has " << a.size()
                                                       << " entries; chain has "
                                                       << chain.num_links() << " joints");
}

// M(q) (when M is given) and h(q, qd) (when qd and h are) from one pose, each body's
// Jacobian taken once for both
void mass_and_bias(const PlanarChain& chain, const JointVector& q, const JointVector* qd,
                   JointMatrix* M, JointVector* h) {
  const int n = chain.num_links();
  const ChainPose pose = forward_kinematics(chain, q);
  if (M) *M = JointMatrix::Zero(n, n);
  if (qd) *h = JointVector::Zero(n);
  for_each_body(chain, [&](int link, const Eigen::Vector2d& p_L, double m, double I) {
    if (m != 0.0) {
      const PointJacobian J = point_jacobian(pose, link, p_L);
      if (M) M->noalias() += m * J.transpose() * J;
      if (qd) {
        const PointJacobian Jd = point_jacobian_dot(pose, J, *qd, link);
        const Eigen::Vector2d a = Jd * *qd + Eigen::Vector2d(0.0, chain.gravity);
        h->noalias() += m * J.transpose() * a;
      }
    }
    // angular Jacobian: ones for joints 0..link
    if (M && I != 0.0) M->topLeftCorner(link + 1, link + 1).array() += I;
  });
  if (!M) return;
  for (const SpinningInertia& s : chain.spinners)
    M->noalias() += s.inertia * s.coeffs * s.coeffs.transpose();
}

}  // namespace

JointMatrix mass_matrix(const PlanarChain& chain, const JointVector& q) {
  check_sizes(chain, q, "q");
  JointMatrix M;
  mass_and_bias(chain, q, nullptr, &M, nullptr);
  return M;
}

JointVector bias_forces(const PlanarChain& chain, const JointVector& q, const JointVector& qd) {
  check_sizes(chain, q, "q");
  check_sizes(chain, qd, "qd");
  JointVector h;
  mass_and_bias(chain, q, &qd, nullptr, &h);
  return h;
}

JointVector inverse_dynamics(const PlanarChain& chain, const JointVector& q, const JointVector& qd,
                             const JointVector& qdd) {
  check_sizes(chain, q, "q");
  check_sizes(chain, qd, "qd");
  check_sizes(chain, qdd, "qdd");
  JointMatrix M;
  JointVector h;
  mass_and_bias(chain, q, &qd, &M, &h);
  return M * qdd + h;
}

JointVector forward_dynamics(const PlanarChain& chain, const JointVector& q, const JointVector& qd,
                             const JointVector& tau) {
  check_sizes(chain, q, "q");
  check_sizes(chain, qd, "qd");
  check_sizes(chain, tau, "tau");
  JointMatrix M;
  JointVector h;
  mass_and_bias(chain, q, &qd, &M, &h);
  const JointVector rhs = tau - h;
  return M.llt().solve(rhs);
}

MixedDynamics passive_forward_dynamics(const PlanarChain& chain, const JointVector& q,
                                       const JointVector& qd, const JointVector& qdd_active,
                                       const JointVector& tau_passive) {
  check_sizes(chain, qdd_active, "qdd_active");
  check_sizes(chain, tau_passive, "tau_passive");
  check_sizes(chain, q, "q");
  check_sizes(chain, qd, "qd");
  const int n = chain.num_links();
  JointMatrix M;
  JointVector h;
  mass_and_bias(chain, q, &qd, &M, &h);
  // index sets of active (A) and passive (P) joints
  int ia[kMaxLinks], ip[kMaxLinks];
  int na = 0, np = 0;
  for (int i = 0; i < n; ++i) (chain.links[i].active ? ia[na++] : ip[np++]) = i;
  MixedDynamics out;
  out.qdd = qdd_active;
  out.tau = tau_passive;
  if (np > 0) {
    // M_PP qdd_P = tau_P - h_P - M_PA qdd_A
    JointMatrix Mpp(np, np);
    JointVector rhs(np);
    for (int r = 0; r < np; ++r) {
      rhs[r] = tau_passive[ip[r]] - h[ip[r]];
      for (int c = 0; c < na; ++c) rhs[r] -= M(ip[r], ia[c]) * qdd_active[ia[c]];
      for (int c = 0; c < np; ++c) Mpp(r, c) = M(ip[r], ip[c]);
    }
    const JointVector qdd_p = Mpp.llt().solve(rhs);
    for (int r = 0; r < np; ++r) out.qdd[ip[r]] = qdd_p[r];
  }
  // active torques from the full acceleration
  const JointVector tau_full = M * out.qdd + h;
  for (int c = 0; c < na; ++c) out.tau[ia[c]] = tau_full[ia[c]];
  return out;
}

double kinetic_energy(const PlanarChain& chain, const JointVector& q, const JointVector& qd) {
  check_sizes(chain, qd, "qd");
  return 0.5 * qd.dot(mass_matrix(chain, q) * qd);
}

double potential_energy(const PlanarChain& chain, const JointVector& q) {
  check_sizes(chain, q, "q");
  if (chain.gravity == 0.0) return 0.0;
  const ChainPose pose = forward_kinematics(chain, q);
  double u = 0.0;
  for_each_body(chain, [&](int link, const Eigen::Vector2d& p_L, double m, double) {
    u += m * chain.gravity * point_position(pose, link, p_L).y();
  });
  return u;
}

}  // namespace armstudy::core
