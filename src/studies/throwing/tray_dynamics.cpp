// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/throwing/tray_dynamics.hpp"

#include <cmath>

#include "core/check.hpp"

namespace armstudy::studies {
namespace {
constexpr int kN = 4;

// Mpp.llt().solve(rhs) of Eigen for the n x n lower triangle of A (n <= 4), in place:
// llt_inplace's unblocked loop (it stops at a pivot <= 0, leaving the rest as it is), then
// the column-major forward and the row-major backward substitution of
// triangular_solve_vector, which skip a division where the right-hand side is exactly 0
void solve_spd(double A[kN][kN], int n, double b[kN]) {
  if (n == 2 && A[0][0] > 0.0) {
    // the same operations for the tray arm's two passive joints, in straight code
    const double l00 = std::sqrt(A[0][0]);
    const double l10 = A[1][0] / l00;
    const double x = A[1][1] - l10 * l10;
    if (x > 0.0) {
      const double l11 = std::sqrt(x);
      double b0 = b[0], b1 = b[1];
      if (b0 != 0.0) {
        b0 /= l00;
        b1 -= b0 * l10;
      }
      if (b1 != 0.0) b1 /= l11;  // forward: y1
      if (b1 != 0.0) b1 /= l11;  // backward: x1
      b0 -= l10 * b1;
      if (b0 != 0.0) b0 /= l00;
      b[0] = b0;
      b[1] = b1;
      return;
    }
  }
  for (int k = 0; k < n; ++k) {
    double x = A[k][k];
    if (k > 0) {
      double sq = A[k][0] * A[k][0];
      for (int j = 1; j < k; ++j) sq += A[k][j] * A[k][j];
      x -= sq;
    }
    if (x <= 0.0) break;
    A[k][k] = x = std::sqrt(x);
    for (int i = k + 1; i < n; ++i) {
      if (k > 0) {
        double dot = A[i][0] * A[k][0];
        for (int j = 1; j < k; ++j) dot += A[i][j] * A[k][j];
        A[i][k] -= dot;
      }
      A[i][k] /= x;
    }
  }
  for (int i = 0; i < n; ++i) {
    if (b[i] != 0.0) {
      b[i] /= A[i][i];
      for (int r = i + 1; r < n; ++r) b[r] -= b[i] * A[r][i];
    }
  }
  for (int i = n - 1; i >= 0; --i) {
    if (i < n - 1) {
      double dot = A[i + 1][i] * b[i + 1];
      for (int j = i + 2; j < n; ++j) dot += A[j][i] * b[j];
      b[i] -= dot;
    }
    if (b[i] != 0.0) b[i] /= A[i][i];
  }
}
// the link frames and joint rates of one state (mixed's forward kinematics)
struct Kinematics {
  double c[kN], s[kN], px[kN + 1], py[kN + 1];  // cos, sin of each link; joint positions
  double sx[kN], sy[kN];                        // perp(p_j - p_j-1), j >= 1
  double w[kN];                                 // joint rates
  double gravity;
};

// one body's m J^T J and I into M, m J^T (Jdot qd + g ey) into h (core/dynamics.cpp and
// core/kinematics.cpp's point_position, point_jacobian, point_jacobian_dot)
template <int Link, typename Body>
void add_body(const Body& body, const Kinematics& k, double M[kN][kN], double h[kN]) {
  if (body.mass != 0.0) {
    const double bx = k.px[Link] + (k.c[Link] * body.x - k.s[Link] * body.y);
    const double by = k.py[Link] + (k.s[Link] * body.x + k.c[Link] * body.y);
    double J0[Link + 1], J1[Link + 1], D0[Link + 1], D1[Link + 1];
    for (int j = 0; j <= Link; ++j) {
      J0[j] = -(by - k.py[j]);
      J1[j] = bx - k.px[j];
    }
    double vx = J0[0] * k.w[0], vy = J1[0] * k.w[0];
    for (int j = 1; j <= Link; ++j) {
      vx += J0[j] * k.w[j];
      vy += J1[j] * k.w[j];
    }
    double vjx = 0.0, vjy = 0.0, omega = 0.0;
    for (int j = 0; j <= Link; ++j) {
      if (j > 0) {
        vjx += omega * k.sx[j];
        vjy += omega * k.sy[j];
      }
      omega += k.w[j];
      D0[j] = -(vy - vjy);
      D1[j] = vx - vjx;
    }
    const double m = body.mass;
    double mJ0[Link + 1], mJ1[Link + 1];
    for (int i = 0; i <= Link; ++i) {
      mJ0[i] = m * J0[i];
      mJ1[i] = m * J1[i];
    }
    for (int i = 0; i <= Link; ++i)
      for (int j = 0; j <= Link; ++j) M[i][j] += mJ0[i] * J0[j] + mJ1[i] * J1[j];
    double ax = D0[0] * k.w[0], ay = D1[0] * k.w[0];
    for (int j = 1; j <= Link; ++j) {
      ax += D0[j] * k.w[j];
      ay += D1[j] * k.w[j];
    }
    ax = ax + 0.0;
    ay = ay + k.gravity;
    for (int i = 0; i <= Link; ++i) h[i] += mJ0[i] * ax + mJ1[i] * ay;
  }
  if (body.inertia != 0.0)
    for (int i = 0; i <= Link; ++i)
      for (int j = 0; j <= Link; ++j) M[i][j] += body.inertia;
}

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

// (over 60 lines, kept whole: the hot mixed forward/inverse dynamics of every simulation
// step, written as one pass through the equations; throwing_bench measures it)
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
  // left out; 2-vectors work lane by lane.
  const core::PlanarChain& chain = chain_;
  // forward kinematics once: each link's cosine and sine (the generic chain's angles)
  Kinematics k;
  double* c = k.c;
  double* s = k.s;
  double* px = k.px;
  double* py = k.py;
  px[0] = chain.base.x();
  py[0] = chain.base.y();
  double a = chain.base_angle;
  for (int i = 0; i < kN; ++i) {
    a += q[i];
    c[i] = std::cos(a);
    s[i] = std::sin(a);
    const double L = chain.links[i].length;
    px[i + 1] = px[i] + L * c[i];
    py[i + 1] = py[i] + L * s[i];
  }
  // link vectors of point_jacobian_dot's joint velocities, perp(p_j - p_j-1)
  k.sx[0] = k.sy[0] = 0.0;
  for (int j = 1; j < kN; ++j) {
    k.sx[j] = -(py[j] - py[j - 1]);
    k.sy[j] = px[j] - px[j - 1];
  }
  for (int i = 0; i < kN; ++i) k.w[i] = qd[i];
  k.gravity = chain.gravity;
  const double* w_ = k.w;

  double M[kN][kN] = {}, h[kN] = {};
  // the links' bodies come first, in order; the link as a compile-time bound unrolls the
  // loops into straight code
  add_body<0>(bodies_[0], k, M, h);
  add_body<1>(bodies_[1], k, M, h);
  add_body<2>(bodies_[2], k, M, h);
  add_body<3>(bodies_[3], k, M, h);
  for (int b = kN; b < n_bodies_; ++b) {
    const Body& body = bodies_[b];
    switch (body.link) {
      case 0: add_body<0>(body, k, M, h); break;
      case 1: add_body<1>(body, k, M, h); break;
      case 2: add_body<2>(body, k, M, h); break;
      default: add_body<3>(body, k, M, h); break;
    }
  }
  for (const core::SpinningInertia& sp : chain.spinners) {
    double L[kN], C[kN];
    for (int i = 0; i < kN; ++i) {
      C[i] = sp.coeffs[i];
      L[i] = sp.inertia * C[i];
    }
    for (int i = 0; i < kN; ++i)
      for (int j = 0; j < kN; ++j)
        if (C[i] != 0.0 && C[j] != 0.0) M[i][j] += C[j] * L[i];
  }

  // core::passive_forward_dynamics with zero passive torques, Eigen's LLT solve written out
  int ia[kN], ip[kN];
  int na = 0, np = 0;
  for (int i = 0; i < kN; ++i) (chain.links[i].active ? ia[na++] : ip[np++]) = i;
  double qdd[kN];
  for (int i = 0; i < kN; ++i) qdd[i] = qdd_active[i];
  if (np > 0) {
    double Mpp[kN][kN], rhs[kN];
    for (int r = 0; r < np; ++r) {
      rhs[r] = 0.0 - h[ip[r]];
      for (int ka = 0; ka < na; ++ka) rhs[r] -= M[ip[r]][ia[ka]] * qdd_active[ia[ka]];
      for (int kp = 0; kp < np; ++kp) Mpp[r][kp] = M[ip[r]][ip[kp]];
    }
    solve_spd(Mpp, np, rhs);
    for (int r = 0; r < np; ++r) qdd[ip[r]] = rhs[r];
  }
  core::MixedDynamics out;
  out.qdd.resize(kN);
  out.tau = core::JointVector::Zero(kN);
  for (int i = 0; i < kN; ++i) out.qdd[i] = qdd[i];
  for (int ka = 0; ka < na; ++ka) {
    const int i = ia[ka];
    double sum = M[i][0] * qdd[0];
    for (int j = 1; j < kN; ++j) sum += M[i][j] * qdd[j];
    out.tau[i] = sum + h[i];
  }

  // ball_contact_forces (simulate.cpp) with the same angles
  double w = 0.0, al = 0.0, ax = 0.0, ay = 0.0;
  for (int i = 0; i < kN; ++i) {
    w += w_[i];
    al += qdd[i];
    const double L = chain.links[i].length, ww = w * w;
    ax += L * (al * -s[i] - ww * c[i]);
    ay += L * (al * c[i] - ww * s[i]);
  }
  const double nx = c[kN - 1], ny = s[kN - 1], tx = -s[kN - 1], ty = c[kN - 1];
  const double gx = 0.0, gy = -chain.gravity;
  force = {ball_mass * ((gx - ax) * nx + (gy - ay) * ny),
           ball_mass * ((ax - gx) * tx + (ay - gy) * ty)};
  return out;
}

}  // namespace armstudy::studies
