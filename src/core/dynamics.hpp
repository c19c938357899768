// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Rigid-body dynamics of a PlanarChain: M(q) qdd + h(q, qd) = tau, with tau on the
/// relative joint angles and gravity along -y.
///
/// Derivation (Kane's method, exact for planar chains): every body b (link, point mass)
/// with translational Jacobian J_b (2 x N) of its centre of mass and angular Jacobian
/// w_b (1 x N, ones up to its link) contributes
///   M += m_b J_b^T J_b + I_b w_b^T w_b,
///   h += m_b J_b^T (Jdot_b qd + g ey)   (planar: no gyroscopic term, w_b is constant);
/// a SpinningInertia adds I c c^T to M. Units: M in kg m^2, h and tau in N m.

#include "core/planar_chain.hpp"
#include "core/types.hpp"

namespace armstudy::core {

/// Mass matrix (N x N), symmetric positive definite, kg m^2.
JointMatrix mass_matrix(const PlanarChain& chain, const JointVector& q);

/// Bias forces h = C(q, qd) qd + g(q) (N), N m.
JointVector bias_forces(const PlanarChain& chain, const JointVector& q, const JointVector& qd);

/// Inverse dynamics tau = M qdd + h (N), N m.
JointVector inverse_dynamics(const PlanarChain& chain, const JointVector& q, const JointVector& qd,
                             const JointVector& qdd);

/// Forward dynamics qdd = M^-1 (tau - h) (N), rad/s^2.
JointVector forward_dynamics(const PlanarChain& chain, const JointVector& q, const JointVector& qd,
                             const JointVector& tau);

/// Result of mixed forward dynamics: full accelerations and the torques that produce them.
struct MixedDynamics {
  JointVector qdd;  ///< (N) rad/s^2: the given active ones and the solved passive ones
  JointVector tau;  ///< (N) N m: active torques solved, passive torques as given
};

/// Forward dynamics with passive joints: given the accelerations of the ACTIVE joints
/// (entries of `qdd_active` at passive joints are ignored) and the torques of the passive
/// joints (`tau_passive`, entries at active joints ignored; usually zero), solves the
/// passive accelerations and the active torques.
MixedDynamics passive_forward_dynamics(const PlanarChain& chain, const JointVector& q,
                                       const JointVector& qd, const JointVector& qdd_active,
                                       const JointVector& tau_passive);

/// Kinetic energy 1/2 qd^T M qd, J.
double kinetic_energy(const PlanarChain& chain, const JointVector& q, const JointVector& qd);

/// Potential energy sum m g y of every mass (zero at y = 0), J.
double potential_energy(const PlanarChain& chain, const JointVector& q);

}  // namespace armstudy::core
