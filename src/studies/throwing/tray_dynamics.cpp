#include "studies/throwing/tray_dynamics.hpp"

#include <cmath>

#include "core/check.hpp"

namespace armstudy::studies {
namespace {
constexpr int kN = 4;
Eigen::Vector2d perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }
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
  const core::PlanarChain& chain = chain_;
  // forward kinematics once: each link's cosine and sine (the generic chain's angles)
  double c[kN], s[kN];
  Eigen::Vector2d p_WJ[kN + 1];
  p_WJ[0] = chain.base;
  double a = chain.base_angle;
  for (int i = 0; i < kN; ++i) {
    a += q[i];
    c[i] = std::cos(a);
    s[i] = std::sin(a);
    p_WJ[i + 1] = p_WJ[i] + chain.links[i].length * Eigen::Vector2d(c[i], s[i]);
  }
  // link vectors of point_jacobian_dot's joint velocities
  Eigen::Vector2d seg_perp[kN];
  for (int j = 1; j < kN; ++j) seg_perp[j] = perp(p_WJ[j] - p_WJ[j - 1]);

  core::JointMatrix M = core::JointMatrix::Zero(kN, kN);
  core::JointVector h = core::JointVector::Zero(kN);
  const Eigen::Vector2d g_up(0.0, chain.gravity);
  for (int b = 0; b < n_bodies_; ++b) {
    const Body& body = bodies_[b];
    const int link = body.link;
    if (body.mass != 0.0) {
      // point_position, point_jacobian, point_jacobian_dot of core/kinematics.cpp
      const Eigen::Vector2d p = p_WJ[link] + Eigen::Vector2d(c[link] * body.x - s[link] * body.y,
                                                             s[link] * body.x + c[link] * body.y);
      core::PointJacobian J = core::PointJacobian::Zero(2, kN);
      for (int j = 0; j <= link; ++j) J.col(j) = perp(p - p_WJ[j]);
      const Eigen::Vector2d v = J * qd;
      core::PointJacobian Jd = core::PointJacobian::Zero(2, kN);
      Eigen::Vector2d v_j = Eigen::Vector2d::Zero();
      double omega = 0.0;
      for (int j = 0; j <= link; ++j) {
        if (j > 0) v_j += omega * seg_perp[j];
        omega += qd[j];
        Jd.col(j) = perp(v - v_j);
      }
      M.noalias() += body.mass * J.transpose() * J;
      const Eigen::Vector2d acc = Jd * qd + g_up;
      h.noalias() += body.mass * J.transpose() * acc;
    }
    if (body.inertia != 0.0) M.topLeftCorner(link + 1, link + 1).array() += body.inertia;
  }
  for (const core::SpinningInertia& sp : chain.spinners)
    M.noalias() += sp.inertia * sp.coeffs * sp.coeffs.transpose();

  // core::passive_forward_dynamics with zero passive torques
  int ia[kN], ip[kN];
  int na = 0, np = 0;
  for (int i = 0; i < kN; ++i) (chain.links[i].active ? ia[na++] : ip[np++]) = i;
  core::MixedDynamics out;
  out.qdd = qdd_active;
  out.tau = core::JointVector::Zero(kN);
  if (np > 0) {
    core::JointMatrix Mpp(np, np);
    core::JointVector rhs(np);
    for (int r = 0; r < np; ++r) {
      rhs[r] = 0.0 - h[ip[r]];
      for (int k = 0; k < na; ++k) rhs[r] -= M(ip[r], ia[k]) * qdd_active[ia[k]];
      for (int k = 0; k < np; ++k) Mpp(r, k) = M(ip[r], ip[k]);
    }
    const core::JointVector qdd_p = Mpp.llt().solve(rhs);
    for (int r = 0; r < np; ++r) out.qdd[ip[r]] = qdd_p[r];
  }
  const core::JointVector tau_full = M * out.qdd + h;
  for (int k = 0; k < na; ++k) out.tau[ia[k]] = tau_full[ia[k]];

  // ball_contact_forces (simulate.cpp) with the same angles
  double w = 0.0, al = 0.0;
  Eigen::Vector2d acc = Eigen::Vector2d::Zero();
  for (int i = 0; i < kN; ++i) {
    w += qd[i];
    al += out.qdd[i];
    const Eigen::Vector2d e(c[i], s[i]), ep(-s[i], c[i]);
    acc += chain.links[i].length * (al * ep - w * w * e);
  }
  const Eigen::Vector2d nn(c[kN - 1], s[kN - 1]), tt(-s[kN - 1], c[kN - 1]);
  const Eigen::Vector2d g(0.0, -chain.gravity);
  force = {ball_mass * (g - acc).dot(nn), ball_mass * (acc - g).dot(tt)};
  return out;
}

}  // namespace armstudy::studies
