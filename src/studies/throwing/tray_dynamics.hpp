// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Fast path of the planning model's dynamics for the tray arm (a chain of exactly four
/// joints): mixed forward dynamics (given active accelerations, solve the passive ones and
/// the active torques) and the ball's contact forces, in one pass over the chain.
///
/// It computes exactly the sums of core/dynamics.cpp (Kane's method: M += m J^T J + I w^T w
/// per body, h += m J^T (Jdot qd + g ey), M += I c c^T per spinner) and of
/// ball_contact_forces (simulate.hpp), in the same order and with the same Eigen
/// expressions, so its results equal the generic chain's to the last bit in practice (the
/// tests require 1e-12 relative). What it saves: the generic chain evaluates the cosine and
/// sine of every link angle about 29 times per state (forward kinematics in the mass matrix,
/// in the bias forces and in every point Jacobian, and again for the contact forces) and
/// every body's Jacobian three times; here each link's cosine and sine are evaluated once and
/// each Jacobian once. No allocation (fixed-capacity types). The generic chain stays the
/// reference (ThrowSetup::generic_dynamics selects it).

#include <Eigen/Dense>

#include "core/dynamics.hpp"
#include "core/planar_chain.hpp"
#include "core/types.hpp"
#include "studies/throwing/tray_dynamics_impl.hpp"

namespace armstudy::studies {

/// Precomputed body list of a 4-joint chain and its one-pass dynamics.
class TrayDynamics {
 public:
  /// @throws std::invalid_argument unless `chain` has 4 joints.
  explicit TrayDynamics(const core::PlanarChain& chain);

  /// core::passive_forward_dynamics(chain, q, qd, qdd_active, 0) (passive torques zero)
  /// and, in `force`, ball_contact_forces(chain, ball_mass, q, qd, qdd): {N, F_t}.
  core::MixedDynamics mixed(const core::JointVector& q, const core::JointVector& qd,
                            const core::JointVector& qdd_active, double ball_mass,
                            Eigen::Vector2d& force) const;

  /// the chain's bodies in the generic chain's order (links, then point masses), for
  /// tray_detail::mixed's other instances (throw_gradient.hpp)
  const tray_detail::Body* bodies() const { return bodies_; }
  int body_count() const { return n_bodies_; }
  const core::PlanarChain& chain() const { return chain_; }

 private:
  using Body = tray_detail::Body;
  const core::PlanarChain& chain_;
  Body bodies_[core::kMaxLinks * 2];
  int n_bodies_ = 0;
};

}  // namespace armstudy::studies
