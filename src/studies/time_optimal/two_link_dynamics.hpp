// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Closed-form dynamics of a 2-link planar chain for the path-projected torques of the
/// time-optimal solvers: tau = a s'' + b s'^2 + c with a = M q', b = M q'' + C(q, q') q',
/// c = g(q) (Pham and Pham 2018's a, b, c). The fast path of joint_point (path.hpp) for tip
/// paths; core/dynamics.hpp (the generic chain) stays the reference, and the tests require
/// the two to agree to 1e-12 relative.
///
/// Model (relative angles q1, q2, absolute theta1 = base_angle + q1, theta12 = theta1 + q2;
/// every body of link i, links and point masses, at (x, y) in link i's frame):
///   M = [[a11 + 2 g, a12 + g], [a12 + g, a22]],  g = A cos q2 - B sin q2,
///   a11 = J1 + m2 L1^2 + J2, a12 = a22 = J2 (J_i: inertia of link i's bodies about joint i,
///   m2: their mass on link 2), A = L1 sum(m x), B = L1 sum(m y) over link 2's bodies,
///   plus I c c^T of every spinner;
///   C(q, q') q' = (g' (2 q1' q2' + q2'^2), -g' q1'^2),  g' = -A sin q2 - B cos q2;
///   gravity (G along -y): c2 = G (cos theta12 X2 - sin theta12 Y2),
///   c1 = G (cos theta1 (X1 + L1 m2) - sin theta1 Y1) + c2, with (X_i, Y_i) = sum(m x, m y)
///   over link i's bodies.

#include "core/planar_chain.hpp"
#include "core/types.hpp"

namespace armstudy::studies::time_optimal {

/// The constant parameters of the model above (SI).
struct TwoLinkDynamics {
  double L1 = 0;
  double a11 = 0, a12 = 0, a22 = 0, A = 0, B = 0;
  double X1 = 0, Y1 = 0, X2 = 0, Y2 = 0, m2 = 0;
  double gravity = 0, base_angle = 0;
};

/// @throws std::invalid_argument unless `chain` has 2 links.
TwoLinkDynamics make_two_link_dynamics(const core::PlanarChain& chain);

/// a = M(q) dq, b = M(q) ddq + C(q, dq) dq, c = g(q) (2 entries each; N m per unit s'', s'^2).
void path_dynamics(const TwoLinkDynamics& d, const core::JointVector& q,
                   const core::JointVector& dq, const core::JointVector& ddq, core::JointVector* a,
                   core::JointVector* b, core::JointVector* c);

/// path_dynamics with cos q2 and sin q2 given (c2, s2: std::cos and std::sin of q[1], which
/// the caller has computed already): the same numbers.
void path_dynamics_cs(const TwoLinkDynamics& d, double c2, double s2, const core::JointVector& q,
                      const core::JointVector& dq, const core::JointVector& ddq,
                      core::JointVector* a, core::JointVector* b, core::JointVector* c);

/// path_dynamics from the cosines and sines of q2 (c2, s2), of link 1's absolute angle
/// (base_angle + q1: ct1, st1) and of link 2's (ct12, st12) instead of q: the same
/// operations after the angles' functions, so the same numbers for the same cosines and
/// sines (path_dynamics_cs takes them with std::cos and std::sin).
void path_dynamics_abs(const TwoLinkDynamics& d, double c2, double s2, double ct1, double st1,
                       double ct12, double st12, const double dq[2], const double ddq[2],
                       core::JointVector* a, core::JointVector* b, core::JointVector* c);

/// tau = M(q) qdd + C(q, qd) qd + g(q) of the model above (2 entries, N m): the inverse
/// dynamics of the dense re-check, equal to core::inverse_dynamics to 1e-12 relative.
void inverse_dynamics(const TwoLinkDynamics& d, const core::JointVector& q,
                      const core::JointVector& qd, const core::JointVector& qdd,
                      core::JointVector* tau);

/// inverse_dynamics from the cosines and sines of link 1's absolute angle (base_angle + q1:
/// c1, s1) and of q2 (c2, s2) instead of q: the same model, no trigonometric functions.
/// kGravity false: the chain's gravity is 0 (no branch, for loops the compiler vectorises).
template <bool kGravity>
inline void inverse_dynamics_cs_fixed(const TwoLinkDynamics& d, double c1, double s1, double c2,
                                      double s2, const double qd[2], const double qdd[2],
                                      double tau[2]) {
  const double g = d.A * c2 - d.B * s2;
  const double gp = -d.A * s2 - d.B * c2;
  const double m11 = d.a11 + 2.0 * g, m12 = d.a12 + g, m22 = d.a22;
  tau[0] = m11 * qdd[0] + m12 * qdd[1] + gp * (2.0 * qd[0] * qd[1] + qd[1] * qd[1]);
  tau[1] = m12 * qdd[0] + m22 * qdd[1] - gp * qd[0] * qd[0];
  if constexpr (kGravity) {
    const double c12 = c1 * c2 - s1 * s2, s12 = s1 * c2 + c1 * s2;
    const double g2 = d.gravity * (c12 * d.X2 - s12 * d.Y2);
    tau[1] += g2;
    tau[0] += d.gravity * (c1 * (d.X1 + d.L1 * d.m2) - s1 * d.Y1) + g2;
  }
}

inline void inverse_dynamics_cs(const TwoLinkDynamics& d, double c1, double s1, double c2,
                                double s2, const double qd[2], const double qdd[2], double tau[2]) {
  if (d.gravity == 0.0)
    inverse_dynamics_cs_fixed<false>(d, c1, s1, c2, s2, qd, qdd, tau);
  else
    inverse_dynamics_cs_fixed<true>(d, c1, s1, c2, s2, qd, qdd, tau);
}

}  // namespace armstudy::studies::time_optimal
