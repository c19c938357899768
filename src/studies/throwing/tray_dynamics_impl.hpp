// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The one-pass tray-arm dynamics of tray_dynamics.hpp as templates over the scalar type:
/// TrayDynamics::mixed is their double instantiation (the same expressions in the same
/// order as before, so its results are unchanged bit for bit), and the exact derivatives of
/// the throw (throw_gradient.hpp) instantiate them with Eigen's AutoDiffScalar to obtain
/// the local Jacobians of the same physics. Written for both: the cosines, sines and square
/// roots are called unqualified (std:: for double, Eigen's for AutoDiffScalar), comparisons
/// read the value, and the shortcuts that skip a division by a right-hand side that is
/// exactly 0 (which Eigen's triangular solve takes) are taken only for double, where they
/// give the same value; a derivative type always divides so that its derivative stays exact.

#include <cmath>
#include <type_traits>

#include "core/planar_chain.hpp"

namespace armstudy::studies::tray_detail {

inline constexpr int kTrayJoints = 4;

/// one body of the chain: its link, centre of mass in the link's frame, mass and inertia
struct Body {
  int link = 0;
  double x = 0, y = 0, mass = 0, inertia = 0;
};

/// is b exactly 0, for the skipped divisions (double only; see the file comment)
template <typename T>
bool skips(const T& b) {
  if constexpr (std::is_same_v<T, double>)
    return b == 0.0;
  else
    return false;
}

// Mpp.llt().solve(rhs) of Eigen for the n x n lower triangle of A (n <= 4), in place:
// llt_inplace's unblocked loop (it stops at a pivot <= 0, leaving the rest as it is), then
// the column-major forward and the row-major backward substitution of
// triangular_solve_vector, which skip a division where the right-hand side is exactly 0
template <typename T>
void solve_spd(T A[kTrayJoints][kTrayJoints], int n, T b[kTrayJoints]) {
  using std::sqrt;
  if (n == 2 && A[0][0] > 0.0) {
    // the same operations for the tray arm's two passive joints, in straight code
    const T l00 = sqrt(A[0][0]);
    const T l10 = A[1][0] / l00;
    const T x = A[1][1] - l10 * l10;
    if (x > 0.0) {
      const T l11 = sqrt(x);
      T b0 = b[0], b1 = b[1];
      if (!skips(b0)) {
        b0 /= l00;
        b1 -= b0 * l10;
      }
      if (!skips(b1)) b1 /= l11;  // forward: y1
      if (!skips(b1)) b1 /= l11;  // backward: x1
      b0 -= l10 * b1;
      if (!skips(b0)) b0 /= l00;
      b[0] = b0;
      b[1] = b1;
      return;
    }
  }
  for (int k = 0; k < n; ++k) {
    T x = A[k][k];
    if (k > 0) {
      T sq = A[k][0] * A[k][0];
      for (int j = 1; j < k; ++j) sq += A[k][j] * A[k][j];
      x -= sq;
    }
    if (x <= 0.0) break;
    A[k][k] = x = sqrt(x);
    for (int i = k + 1; i < n; ++i) {
      if (k > 0) {
        T dot = A[i][0] * A[k][0];
        for (int j = 1; j < k; ++j) dot += A[i][j] * A[k][j];
        A[i][k] -= dot;
      }
      A[i][k] /= x;
    }
  }
  for (int i = 0; i < n; ++i) {
    if (!skips(b[i])) {
      b[i] /= A[i][i];
      for (int r = i + 1; r < n; ++r) b[r] -= b[i] * A[r][i];
    }
  }
  for (int i = n - 1; i >= 0; --i) {
    if (i < n - 1) {
      T dot = A[i + 1][i] * b[i + 1];
      for (int j = i + 2; j < n; ++j) dot += A[j][i] * b[j];
      b[i] -= dot;
    }
    if (!skips(b[i])) b[i] /= A[i][i];
  }
}

// the link frames and joint rates of one state (mixed's forward kinematics)
template <typename T>
struct Kinematics {
  T c[kTrayJoints], s[kTrayJoints], px[kTrayJoints + 1], py[kTrayJoints + 1];  // cos, sin; joints
  T sx[kTrayJoints], sy[kTrayJoints];  // perp(p_j - p_j-1), j >= 1
  T w[kTrayJoints];                    // joint rates
  double gravity;
};

// one body's m J^T J and I into M, m J^T (Jdot qd + g ey) into h (core/dynamics.cpp and
// core/kinematics.cpp's point_position, point_jacobian, point_jacobian_dot)
template <int Link, typename T>
void add_body(const Body& body, const Kinematics<T>& k, T M[kTrayJoints][kTrayJoints],
              T h[kTrayJoints]) {
  if (body.mass != 0.0) {
    const T bx = k.px[Link] + (k.c[Link] * body.x - k.s[Link] * body.y);
    const T by = k.py[Link] + (k.s[Link] * body.x + k.c[Link] * body.y);
    T J0[Link + 1], J1[Link + 1], D0[Link + 1], D1[Link + 1];
    for (int j = 0; j <= Link; ++j) {
      J0[j] = -(by - k.py[j]);
      J1[j] = bx - k.px[j];
    }
    T vx = J0[0] * k.w[0], vy = J1[0] * k.w[0];
    for (int j = 1; j <= Link; ++j) {
      vx += J0[j] * k.w[j];
      vy += J1[j] * k.w[j];
    }
    T vjx = T(0.0), vjy = T(0.0), omega = T(0.0);
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
    T mJ0[Link + 1], mJ1[Link + 1];
    for (int i = 0; i <= Link; ++i) {
      mJ0[i] = m * J0[i];
      mJ1[i] = m * J1[i];
    }
    for (int i = 0; i <= Link; ++i)
      for (int j = 0; j <= Link; ++j) M[i][j] += mJ0[i] * J0[j] + mJ1[i] * J1[j];
    T ax = D0[0] * k.w[0], ay = D1[0] * k.w[0];
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

// forward kinematics once: each link's cosine and sine (the generic chain's angles)
template <typename T>
void forward_kinematics(const core::PlanarChain& chain, const T q[kTrayJoints],
                        const T qd[kTrayJoints], Kinematics<T>& k) {
  using std::cos;
  using std::sin;
  k.px[0] = T(chain.base.x());
  k.py[0] = T(chain.base.y());
  T a = T(chain.base_angle);
  for (int i = 0; i < kTrayJoints; ++i) {
    a += q[i];
    k.c[i] = cos(a);
    k.s[i] = sin(a);
    const double L = chain.links[i].length;
    k.px[i + 1] = k.px[i] + L * k.c[i];
    k.py[i + 1] = k.py[i] + L * k.s[i];
  }
  // link vectors of point_jacobian_dot's joint velocities, perp(p_j - p_j-1)
  k.sx[0] = k.sy[0] = T(0.0);
  for (int j = 1; j < kTrayJoints; ++j) {
    k.sx[j] = -(k.py[j] - k.py[j - 1]);
    k.sy[j] = k.px[j] - k.px[j - 1];
  }
  for (int i = 0; i < kTrayJoints; ++i) k.w[i] = qd[i];
  k.gravity = chain.gravity;
}

// M and h of the chain's bodies and spinners (core/dynamics.cpp's sums)
template <typename T>
void mass_matrix_and_bias(const core::PlanarChain& chain, const Body* bodies, int n_bodies,
                          const Kinematics<T>& k, T M[kTrayJoints][kTrayJoints], T h[kTrayJoints]) {
  // the links' bodies come first, in order; the link as a compile-time bound unrolls the
  // loops into straight code
  add_body<0>(bodies[0], k, M, h);
  add_body<1>(bodies[1], k, M, h);
  add_body<2>(bodies[2], k, M, h);
  add_body<3>(bodies[3], k, M, h);
  for (int b = kTrayJoints; b < n_bodies; ++b) {
    const Body& body = bodies[b];
    switch (body.link) {
      case 0: add_body<0>(body, k, M, h); break;
      case 1: add_body<1>(body, k, M, h); break;
      case 2: add_body<2>(body, k, M, h); break;
      default: add_body<3>(body, k, M, h); break;
    }
  }
  for (const core::SpinningInertia& sp : chain.spinners) {
    double L[kTrayJoints], C[kTrayJoints];
    for (int i = 0; i < kTrayJoints; ++i) {
      C[i] = sp.coeffs[i];
      L[i] = sp.inertia * C[i];
    }
    for (int i = 0; i < kTrayJoints; ++i)
      for (int j = 0; j < kTrayJoints; ++j)
        if (C[i] != 0.0 && C[j] != 0.0) M[i][j] += C[j] * L[i];
  }
}

/// TrayDynamics::mixed on arrays: the passive accelerations (qdd gets qdd_active's active
/// entries and the solved passive ones), the active joints' torques (tau, passive entries
/// untouched) and the ball's contact forces {N, F_t}.
template <typename T>
void mixed(const core::PlanarChain& chain, const Body* bodies, int n_bodies, const T q[kTrayJoints],
           const T qd[kTrayJoints], const T qdd_active[kTrayJoints], double ball_mass,
           T qdd[kTrayJoints], T tau[kTrayJoints], T force[2]) {
  constexpr int kNj = kTrayJoints;
  Kinematics<T> k;
  forward_kinematics(chain, q, qd, k);
  T M[kNj][kNj], h[kNj];
  for (int i = 0; i < kNj; ++i) {
    h[i] = T(0.0);
    for (int j = 0; j < kNj; ++j) M[i][j] = T(0.0);
  }
  mass_matrix_and_bias(chain, bodies, n_bodies, k, M, h);

  // core::passive_forward_dynamics with zero passive torques, Eigen's LLT solve written out
  int ia[kNj], ip[kNj];
  int na = 0, np = 0;
  for (int i = 0; i < kNj; ++i) (chain.links[i].active ? ia[na++] : ip[np++]) = i;
  for (int i = 0; i < kNj; ++i) qdd[i] = qdd_active[i];
  if (np > 0) {
    T Mpp[kNj][kNj], rhs[kNj];
    for (int r = 0; r < np; ++r) {
      rhs[r] = 0.0 - h[ip[r]];
      for (int ka = 0; ka < na; ++ka) rhs[r] -= M[ip[r]][ia[ka]] * qdd_active[ia[ka]];
      for (int kp = 0; kp < np; ++kp) Mpp[r][kp] = M[ip[r]][ip[kp]];
    }
    solve_spd(Mpp, np, rhs);
    for (int r = 0; r < np; ++r) qdd[ip[r]] = rhs[r];
  }
  for (int ka = 0; ka < na; ++ka) {
    const int i = ia[ka];
    T sum = M[i][0] * qdd[0];
    for (int j = 1; j < kNj; ++j) sum += M[i][j] * qdd[j];
    tau[i] = sum + h[i];
  }

  // ball_contact_forces (simulate.cpp) with the same angles
  T w = T(0.0), al = T(0.0), ax = T(0.0), ay = T(0.0);
  for (int i = 0; i < kNj; ++i) {
    w += k.w[i];
    al += qdd[i];
    const double L = chain.links[i].length;
    const T ww = w * w;
    ax += L * (al * -k.s[i] - ww * k.c[i]);
    ay += L * (al * k.c[i] - ww * k.s[i]);
  }
  const T nx = k.c[kNj - 1], ny = k.s[kNj - 1], tx = -k.s[kNj - 1], ty = k.c[kNj - 1];
  const double gx = 0.0, gy = -chain.gravity;
  force[0] = ball_mass * ((gx - ax) * nx + (gy - ay) * ny);
  force[1] = ball_mass * ((ax - gx) * tx + (ay - gy) * ty);
}

}  // namespace armstudy::studies::tray_detail
