// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/throwing/tray_dynamics.hpp"

#include <cmath>

#include "core/check.hpp"
#include "studies/throwing/tray_dynamics_impl.hpp"

namespace armstudy::studies {
namespace {
constexpr int kN = tray_detail::kTrayJoints;
}  // namespace

TrayDynamics::TrayDynamics(const core::PlanarChain& chain) : chain_(chain) {
  ARM_THROW_UNLESS(chain.num_links() == kN,
                   "the tray-arm dynamics need 4 joints, the chain has " << chain.num_links());
  ARM_THROW_UNLESS(chain.num_links() + int(chain.point_masses.size()) <= int(std::size(bodies_)),
                   "the tray-arm dynamics take at most " << std::size(bodies_) << " bodies");
  // the bodies in the generic chain's order: links, then point masses
  for (int i = 0; i < kN; ++i) {
    const core::Link& l = chain.links[i];
    bodies_[n_bodies_++] = {i, l.com, l.com_lateral, l.mass, l.inertia};
  }
  for (const core::PointMass& p : chain.point_masses)
    bodies_[n_bodies_++] = {p.link, p.x, p.y, p.mass, 0.0};
}

core::MixedDynamics TrayDynamics::mixed(const core::JointVector& q, const core::JointVector& qd,
                                        const core::JointVector& qdd_active, double ball_mass,
                                        Eigen::Vector2d& force) const {
  // Plain scalars and 4 x 4 arrays in place of core::JointMatrix and Eigen temporaries (the
  // run-time sizes and the stores and reloads of small vectors cost more than the
  // arithmetic), each value the same expression as the generic chain's Eigen code: Eigen's
  // coefficient-based products sum their inner index in order from 0, (m J^T) J and
  // (m J^T) a scale J^T first, a spinner's outer product adds c_j (I c_i), a point
  // Jacobian's columns beyond its link and a spinner's zero coefficients add exact zeros
  // there (finite terms times 0; the entries they would add to are never -0), so they are
  // left out; 2-vectors work lane by lane (tray_dynamics_impl.hpp, its double instance).
  double qa[kN], qda[kN], acc[kN], qdd[kN], tau[kN] = {}, f[2];
  for (int i = 0; i < kN; ++i) {
    qa[i] = q[i];
    qda[i] = qd[i];
    acc[i] = qdd_active[i];
  }
  tray_detail::mixed(chain_, bodies_, n_bodies_, qa, qda, acc, ball_mass, qdd, tau, f);
  core::MixedDynamics out;
  out.qdd.resize(kN);
  out.tau = core::JointVector::Zero(kN);
  for (int i = 0; i < kN; ++i) {
    out.qdd[i] = qdd[i];
    out.tau[i] = tau[i];
  }
  force = {f[0], f[1]};
  return out;
}

}  // namespace armstudy::studies
