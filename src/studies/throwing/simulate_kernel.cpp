// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/throwing/simulate_kernel.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/check.hpp"
#include "core/integrators.hpp"
#include "studies/throwing/lanes.hpp"

namespace armstudy::studies {
namespace {

constexpr int kN = 4;

struct Body {
  int link = 0;
  double x = 0, y = 0, mass = 0, inertia = 0;
};

// the setup's constants as the Planner, TrayDynamics and core::motor_sample read them
struct Model {
  double base_x = 0, base_y = 0, base_angle = 0, gravity = 0;
  double L[kN] = {};
  Body bodies[core::kMaxLinks * 2];
  int n_bodies = 0;
  // the spinners' constants C_j (I C_i) added to M[i][j] where both coefficients are
  // nonzero, in the spinners' order: n_spin[i][j] of them, spin[i][j][0 ..] (kernel_applies:
  // at most kMaxSpin spinners)
  static constexpr int kMaxSpin = 4;
  int n_spin[kN][kN] = {};
  double spin[kN][kN][kMaxSpin] = {};
  double ball_mass = 0;
  double B[2][kN] = {};  // motor_matrix
  double b_mount = 0;    // motor_torques' B(1, 0)
  // eq. 5-6 per motor: e = c_qd qd + c_qdd qdd + b3 tau + c_f sign(qd), i = (e - kv qd) / Ra
  double c_qd[2] = {}, c_qdd[2] = {}, b3[2] = {}, c_f[2] = {}, kv[2] = {}, Ra[2] = {};
  double band[2] = {};  // coulomb_band (0: the exact sign)
  bool regeneration = true;
  double mu = 0;
  // stage_constraint_values
  double margin = 0, weight = 0, half_width = 0, vmax = 0, imax = 0, pmax = 0;

  explicit Model(const ThrowSetup& s) {
    const core::PlanarChain& chain = s.chain;
    base_x = chain.base.x();
    base_y = chain.base.y();
    base_angle = chain.base_angle;
    gravity = chain.gravity;
    for (int i = 0; i < kN; ++i) {
      const core::Link& l = chain.links[i];
      L[i] = l.length;
      bodies[n_bodies++] = {i, l.com, l.com_lateral, l.mass, l.inertia};
    }
    for (const core::PointMass& p : chain.point_masses)
      bodies[n_bodies++] = {p.link, p.x, p.y, p.mass, 0.0};
    for (const core::SpinningInertia& sp : chain.spinners) {
      double Li[kN], C[kN];
      for (int i = 0; i < kN; ++i) {
        C[i] = sp.coeffs[i];
        Li[i] = sp.inertia * C[i];
      }
      for (int i = 0; i < kN; ++i)
        for (int j = 0; j < kN; ++j)
          if (C[i] != 0.0 && C[j] != 0.0) spin[i][j][n_spin[i][j]++] = C[j] * Li[i];
    }
    ball_mass = s.ball_mass;
    const Eigen::Matrix<double, 2, 4> Bm = motor_matrix(s.mount);
    for (int m = 0; m < 2; ++m)
      for (int j = 0; j < kN; ++j) B[m][j] = Bm(m, j);
    b_mount = s.mount == Motor2Mount::kOnBase ? 1.0 : 0.0;
    for (int m = 0; m < 2; ++m) {
      const core::DcMotor& mo = s.motor[m];
      const double b = mo.Ra / mo.kt;
      c_qd[m] = mo.kv + b * mo.Dm;
      c_qdd[m] = b * mo.Im;
      b3[m] = b;
      c_f[m] = b * mo.tau_f;
      band[m] = mo.coulomb_band;
      kv[m] = mo.kv;
      Ra[m] = mo.Ra;
    }
    regeneration = s.count_regeneration;
    mu = s.friction_coefficient;
    margin = s.contact_margin;
    weight = s.ball_mass * s.chain.gravity;
    half_width = s.half_width;
    vmax = s.voltage_max;
    imax = s.current_max;
    pmax = s.power_max;
  }
};

// a profile's node rates and stage-start angles (the Planner's q_start_), per lane
template <typename T>
struct LaneProfile {
  std::vector<T> v0, v1;  // joints 1, 2 at nodes 0 .. P
  std::vector<T> q0, q1;  // at stage starts 0 .. P
};

void profile_nodes(const VelocityProfile& p, std::vector<double> v[2], std::vector<double> q[2]) {
  const int P = p.stages();
  const double h = p.stage_length();
  std::vector<Eigen::Vector2d> qs(P + 1);
  qs[0] = p.q0;
  for (int k = 0; k < P; ++k) qs[k + 1] = qs[k] + 0.5 * h * (p.v.col(k) + p.v.col(k + 1));
  for (int i = 0; i < 2; ++i) {
    v[i].resize(P + 1);
    q[i].resize(P + 1);
    for (int k = 0; k <= P; ++k) {
      v[i][k] = p.v(i, k);
      q[i][k] = qs[k][i];
    }
  }
}

LaneProfile<double> lanes_of(const VelocityProfile& p) {
  std::vector<double> v[2], q[2];
  profile_nodes(p, v, q);
  return {v[0], v[1], q[0], q[1]};
}

// one body's m J^T J and I into M, m J^T (Jdot qd + g ey) into h: tray_dynamics.cpp's
// add_body, the same operations on T
template <int Link, typename T>
void add_body(const Body& body, const T* px, const T* py, const T* c, const T* s, const T* sx,
              const T* sy, const T* w, double gravity, T M[kN][kN], T h[kN]) {
  if (body.mass != 0.0) {
    const T bx = px[Link] + (c[Link] * body.x - s[Link] * body.y);
    const T by = py[Link] + (s[Link] * body.x + c[Link] * body.y);
    T J0[Link + 1], J1[Link + 1], D0[Link + 1], D1[Link + 1];
    for (int j = 0; j <= Link; ++j) {
      J0[j] = -(by - py[j]);
      J1[j] = bx - px[j];
    }
    T vx = J0[0] * w[0], vy = J1[0] * w[0];
    for (int j = 1; j <= Link; ++j) {
      vx += J0[j] * w[j];
      vy += J1[j] * w[j];
    }
    T vjx = 0.0, vjy = 0.0, omega = 0.0;
    for (int j = 0; j <= Link; ++j) {
      if (j > 0) {
        vjx += omega * sx[j];
        vjy += omega * sy[j];
      }
      omega += w[j];
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
    T ax = D0[0] * w[0], ay = D1[0] * w[0];
    for (int j = 1; j <= Link; ++j) {
      ax += D0[j] * w[j];
      ay += D1[j] * w[j];
    }
    ax = ax + 0.0;
    ay = ay + gravity;
    for (int i = 0; i <= Link; ++i) h[i] += mJ0[i] * ax + mJ1[i] * ay;
  }
  if (body.inertia != 0.0)
    for (int i = 0; i <= Link; ++i)
      for (int j = 0; j <= Link; ++j) M[i][j] += body.inertia;
}

// tray_dynamics.cpp's solve_spd for the two passive joints (A lower triangle, b in place)
void solve2(double A00, double A10, double A11, double& b0, double& b1) {
  if (A00 > 0.0) {
    const double l00 = std::sqrt(A00);
    const double l10 = A10 / l00;
    const double x = A11 - l10 * l10;
    if (x > 0.0) {
      const double l11 = std::sqrt(x);
      if (b0 != 0.0) {
        b0 /= l00;
        b1 -= b0 * l10;
      }
      if (b1 != 0.0) b1 /= l11;
      if (b1 != 0.0) b1 /= l11;
      b0 -= l10 * b1;
      if (b0 != 0.0) b0 /= l00;
      return;
    }
  }
  // the general loop (a pivot <= 0 stops the factorisation there)
  double A[2][2] = {{A00, 0.0}, {A10, A11}};
  for (int k = 0; k < 2; ++k) {
    double x = A[k][k];
    if (k > 0) {
      const double sq = A[k][0] * A[k][0];
      x -= sq;
    }
    if (x <= 0.0) break;
    A[k][k] = x = std::sqrt(x);
    for (int i = k + 1; i < 2; ++i) A[i][k] /= x;
  }
  if (b0 != 0.0) {
    b0 /= A[0][0];
    b1 -= b0 * A[1][0];
  }
  if (b1 != 0.0) b1 /= A[1][1];
  if (b1 != 0.0) b1 /= A[1][1];
  const double dot = A[1][0] * b1;
  b0 -= dot;
  if (b0 != 0.0) b0 /= A[0][0];
}

// the same for 2 or 4 lanes: the straight code with the branches on b taken lane by lane
// where every lane's pivots are > 0, else each lane by the scalar code
template <typename T>
void solve2(const T& A00, const T& A10, const T& A11, T& b0, T& b1) {
  constexpr int all = (1 << lane_count<T>)-1;
  if (lanes_set(A00 > 0.0) == all) {
    const T l00 = lane_sqrt(A00);
    const T l10 = A10 / l00;
    const T x = A11 - l10 * l10;
    if (lanes_set(x > 0.0) == all) {
      const T l11 = lane_sqrt(x);
      const auto nz = b0 != 0.0;
      const T y0 = b0 / l00;
      b1 = select(nz, b1 - y0 * l10, b1);
      b0 = select(nz, y0, b0);
      b1 = select(b1 != 0.0, b1 / l11, b1);
      b1 = select(b1 != 0.0, b1 / l11, b1);
      b0 = b0 - l10 * b1;
      b0 = select(b0 != 0.0, b0 / l00, b0);
      return;
    }
  }
  constexpr int n = lane_count<T>;
  double r0[n], r1[n], v[n];
  for (int i = 0; i < n; ++i) {
    r0[i] = lane_of(b0, i);
    r1[i] = lane_of(b1, i);
    solve2(lane_of(A00, i), lane_of(A10, i), lane_of(A11, i), r0[i], r1[i]);
  }
  for (int i = 0; i < n; ++i) v[i] = r0[i];
  b0 = pack_lanes<T>(v);
  for (int i = 0; i < n; ++i) v[i] = r1[i];
  b1 = pack_lanes<T>(v);
}

// the active joints' part of an evaluation: a function of (stage, tau) only
template <typename T>
struct Frames {
  T qa[2], qda[2], acc[2];
  T a1;                        // base angle + q1 + q2
  T c[2], s[2], px[3], py[3];  // links 1, 2; joint positions 0 .. 2
  T sx[3], sy[3];              // perp(p_j - p_j-1), j = 1, 2
  T M[2][2], h[2];             // after the bodies of links 1 and 2
  T w, al, ax, ay;             // the ball's acceleration sums over links 1 and 2
};

// the five states (theta3, theta4, their rates, the energy) of every lane, with the
// operations core::rk4_step needs: each the lanes' operation component by component
template <typename T>
struct LaneState {
  T v[5];
  T& operator[](int i) { return v[i]; }
  const T& operator[](int i) const { return v[i]; }
  friend LaneState operator+(const LaneState& a, const LaneState& b) {
    LaneState r;
    for (int i = 0; i < 5; ++i) r.v[i] = a.v[i] + b.v[i];
    return r;
  }
  friend LaneState operator*(double c, const LaneState& a) {
    LaneState r;
    for (int i = 0; i < 5; ++i) r.v[i] = c * a.v[i];
    return r;
  }
};

// one point's outputs: the state derivative and what the constraints track
template <typename T>
struct Point {
  LaneState<T> dx;
  T voltage[2], current[2], power[2];
  T normal, tangential;
};

template <typename T>
class Kernel {
 public:
  Kernel(const Model& m, const LaneProfile<T>& p, double h) : m_(m), p_(p), h_(h) {}

  // the Planner's eval(stage, t, x) for what the simulation uses (over 60 lines, kept whole:
  // the innermost step of every lane's rk4, one pass through the equations with no calls)
  void eval(int stage, double t, const LaneState<T>& x, Point<T>& out) {
    const double tau = t - stage * h_;
    const uint64_t bits = std::bit_cast<uint64_t>(tau);
    if (!cached_ || stage != stage_ || bits != tau_bits_) {
      frames(stage, tau);
      cached_ = true;
      stage_ = stage;
      tau_bits_ = bits;
    }
    const Frames<T>& f = f_;
    const Model& m = m_;
    // the passive links' frames
    T c[kN], s[kN], px[kN + 1], py[kN + 1], sx[kN], sy[kN], w[kN];
    for (int i = 0; i < 2; ++i) {
      c[i] = f.c[i];
      s[i] = f.s[i];
    }
    for (int i = 0; i < 3; ++i) {
      px[i] = f.px[i];
      py[i] = f.py[i];
      sx[i] = f.sx[i];
      sy[i] = f.sy[i];
    }
    const T a2 = f.a1 + x[0];
    lane_cos_sin(a2, c[2], s[2]);
    px[3] = px[2] + m.L[2] * c[2];
    py[3] = py[2] + m.L[2] * s[2];
    const T a3 = a2 + x[1];
    lane_cos_sin(a3, c[3], s[3]);
    px[4] = px[3] + m.L[3] * c[3];
    py[4] = py[3] + m.L[3] * s[3];
    sx[3] = -(py[3] - py[2]);
    sy[3] = px[3] - px[2];
    w[0] = f.qda[0];
    w[1] = f.qda[1];
    w[2] = x[2];
    w[3] = x[3];
    T M[kN][kN], h[kN];
    for (int i = 0; i < kN; ++i) {
      h[i] = 0.0;
      for (int j = 0; j < kN; ++j) M[i][j] = 0.0;
    }
    for (int i = 0; i < 2; ++i) {
      h[i] = f.h[i];
      for (int j = 0; j < 2; ++j) M[i][j] = f.M[i][j];
    }
    add_body<2>(m.bodies[2], px, py, c, s, sx, sy, w, m.gravity, M, h);
    add_body<3>(m.bodies[3], px, py, c, s, sx, sy, w, m.gravity, M, h);
    for (int b = kN; b < m.n_bodies; ++b) {
      const Body& body = m.bodies[b];
      switch (body.link) {
        case 0: add_body<0>(body, px, py, c, s, sx, sy, w, m.gravity, M, h); break;
        case 1: add_body<1>(body, px, py, c, s, sx, sy, w, m.gravity, M, h); break;
        case 2: add_body<2>(body, px, py, c, s, sx, sy, w, m.gravity, M, h); break;
        default: add_body<3>(body, px, py, c, s, sx, sy, w, m.gravity, M, h); break;
      }
    }
    for (int i = 0; i < kN; ++i)
      for (int j = 0; j < kN; ++j)
        for (int q = 0; q < m.n_spin[i][j]; ++q) M[i][j] += m.spin[i][j][q];
    // passive accelerations (zero passive torques), then the active torques
    T b0 = 0.0 - h[2], b1 = 0.0 - h[3];
    b0 -= M[2][0] * f.acc[0];
    b0 -= M[2][1] * f.acc[1];
    b1 -= M[3][0] * f.acc[0];
    b1 -= M[3][1] * f.acc[1];
    solve2(M[2][2], M[3][2], M[3][3], b0, b1);
    const T qdd[kN] = {f.acc[0], f.acc[1], b0, b1};
    T Q[2];
    for (int i = 0; i < 2; ++i) {
      T sum = M[i][0] * qdd[0];
      for (int j = 1; j < kN; ++j) sum += M[i][j] * qdd[j];
      Q[i] = sum + h[i];
    }
    // ball_contact_forces, the active links' terms from the frames
    T wsum = f.w, al = f.al, ax = f.ax, ay = f.ay;
    for (int i = 2; i < kN; ++i) {
      wsum += w[i];
      al += qdd[i];
      const T ww = wsum * wsum;
      ax += m.L[i] * (al * -s[i] - ww * c[i]);
      ay += m.L[i] * (al * c[i] - ww * s[i]);
    }
    const T nx = c[kN - 1], ny = s[kN - 1], tx = -s[kN - 1], ty = c[kN - 1];
    const double gx = 0.0, gy = -m.gravity;
    out.normal = m.ball_mass * ((gx - ax) * nx + (gy - ay) * ny);
    out.tangential = m.ball_mass * ((ax - gx) * tx + (ay - gy) * ty);
    // motor torques, rates and accelerations (motor_torques, B qd, B qdd), eq. 5-6
    const T tau_m[2] = {Q[0] - m.b_mount * Q[1], Q[1]};
    T power = 0.0;
    for (int k = 0; k < 2; ++k) {
      T rate = m.B[k][0] * w[0];
      T acc_m = m.B[k][0] * qdd[0];
      for (int j = 1; j < kN; ++j) {
        rate += m.B[k][j] * w[j];
        acc_m += m.B[k][j] * qdd[j];
      }
      // core::coulomb_sign's operations: a smooth step within the band, else the exact sign
      T sg;
      if (m.band[k] > 0) {
        const T r = rate / m.band[k];
        sg = select(r > 1.0, T(1.0), select(r < -1.0, T(-1.0), 0.5 * r * (3.0 - r * r)));
      } else {
        sg = select(rate > 0.0, T(1.0), select(rate < 0.0, T(-1.0), T(0.0)));
      }
      const T e = m.c_qd[k] * rate + m.c_qdd[k] * acc_m + m.b3[k] * tau_m[k] + m.c_f[k] * sg;
      const T i = (e - m.kv[k] * rate) / m.Ra[k];
      const T p = e * i;
      out.voltage[k] = e;
      out.current[k] = i;
      out.power[k] = p;
      power += m.regeneration ? p : lane_max(T(0.0), p);
    }
    out.dx[0] = x[2];
    out.dx[1] = x[3];
    out.dx[2] = qdd[2];
    out.dx[3] = qdd[3];
    out.dx[4] = power;
  }

 private:
  void frames(int stage, double tau) {
    Frames<T>& f = f_;
    const Model& m = m_;
    const T v0[2] = {p_.v0[stage], p_.v1[stage]};
    const T v1[2] = {p_.v0[stage + 1], p_.v1[stage + 1]};
    const T q0[2] = {p_.q0[stage], p_.q1[stage]};
    for (int i = 0; i < 2; ++i) {
      f.acc[i] = (v1[i] - v0[i]) / h_;
      f.qa[i] = q0[i] + v0[i] * tau + 0.5 * f.acc[i] * tau * tau;
      f.qda[i] = v0[i] + f.acc[i] * tau;
    }
    f.px[0] = m.base_x;
    f.py[0] = m.base_y;
    T a = m.base_angle;
    for (int i = 0; i < 2; ++i) {
      a += f.qa[i];
      lane_cos_sin(a, f.c[i], f.s[i]);
      f.px[i + 1] = f.px[i] + m.L[i] * f.c[i];
      f.py[i + 1] = f.py[i] + m.L[i] * f.s[i];
    }
    f.a1 = a;
    f.sx[0] = f.sy[0] = 0.0;
    for (int j = 1; j < 3; ++j) {
      f.sx[j] = -(f.py[j] - f.py[j - 1]);
      f.sy[j] = f.px[j] - f.px[j - 1];
    }
    T M[kN][kN], h[kN];
    for (int i = 0; i < kN; ++i) {
      h[i] = 0.0;
      for (int j = 0; j < kN; ++j) M[i][j] = 0.0;
    }
    add_body<0>(m.bodies[0], f.px, f.py, f.c, f.s, f.sx, f.sy, f.qda, m.gravity, M, h);
    add_body<1>(m.bodies[1], f.px, f.py, f.c, f.s, f.sx, f.sy, f.qda, m.gravity, M, h);
    for (int i = 0; i < 2; ++i) {
      f.h[i] = h[i];
      for (int j = 0; j < 2; ++j) f.M[i][j] = M[i][j];
    }
    T w = 0.0, al = 0.0, ax = 0.0, ay = 0.0;
    for (int i = 0; i < 2; ++i) {
      w += f.qda[i];
      al += f.acc[i];
      const T ww = w * w;
      ax += m.L[i] * (al * -f.s[i] - ww * f.c[i]);
      ay += m.L[i] * (al * f.c[i] - ww * f.s[i]);
    }
    f.w = w;
    f.al = al;
    f.ax = ax;
    f.ay = ay;
  }

  const Model& m_;
  const LaneProfile<T>& p_;
  double h_;
  Frames<T> f_;
  bool cached_ = false;
  int stage_ = 0;
  uint64_t tau_bits_ = 0;
};

// the stage-wise maxima of the simulation (ProfileEvaluation's stage_* and
// max_friction_ratio), per lane
template <typename T>
struct Track {
  std::vector<T> theta4, voltage, current, power, normal, friction;
  T ratio;
};

template <typename T>
void track(const Model& m, const LaneState<T>& x, const Point<T>& p, int k, Track<T>& tr) {
  tr.theta4[k] = lane_max(tr.theta4[k], lane_abs(x[1]));
  for (int i = 0; i < 2; ++i) {
    tr.voltage[k] = lane_max(tr.voltage[k], lane_abs(p.voltage[i]));
    tr.current[k] = lane_max(tr.current[k], lane_abs(p.current[i]));
    tr.power[k] = lane_max(tr.power[k], lane_abs(p.power[i]));
  }
  const T N = p.normal, Ft = lane_abs(p.tangential);
  tr.normal[k] = lane_min(tr.normal[k], N);
  tr.friction[k] = lane_max(tr.friction[k], Ft - m.mu * N);
  tr.ratio = lane_max(tr.ratio, select(N > 0.0, Ft / N, T(INFINITY)));
}

// simulate.cpp's stage_constraint_values(.., k, backoff) > 0 for some constraint
template <typename T>
auto violated(const Model& m, const Track<T>& tr, int k, double backoff) {
  const T g0 = (m.margin - tr.normal[k]) / m.weight + backoff;
  const T g1 = tr.friction[k] / m.weight + backoff;
  const T g2 = (tr.theta4[k] - m.half_width) / m.half_width + backoff;
  const T g3 = (tr.voltage[k] - m.vmax) / m.vmax + backoff;
  const T g4 = (tr.current[k] - m.imax) / m.imax + backoff;
  const T g5 = (tr.power[k] - m.pmax) / m.pmax + backoff;
  return lane_or(lane_or(lane_or(g0 > 0.0, g1 > 0.0), lane_or(g2 > 0.0, g3 > 0.0)),
                 lane_or(g4 > 0.0, g5 > 0.0));
}

enum class End { kNone, kStopped, kNotFinite };

struct Run {
  int P = 0, n = 1;
  double h = 0, dt = 0, backoff = 0;
  SimulationCheckpoints* save = nullptr;  // one lane only
};

// the simulation loop of simulate.cpp from stage k, step j (j == n: the stage's end point)
// until every stage is done or a lane ends; returns the lanes that ended (bit i: lane i) and
// why, with (k, j) where the other lanes go on; the lanes of `stop` (bit i: lane i) stop at
// a certain violation
template <typename T>
int run(const Run& r, Kernel<T>& K, const Model& m, LaneState<T>& x, Track<T>& tr, int& k, int& j,
        int stop, End& why) {
  Point<T> k1, kj;  // an RK4 step's first stage (tracked), its later ones
  const double dt = r.dt;
  // the right-hand side inside stage k
  auto stage_rhs = [&](double t, const LaneState<T>& y) {
    K.eval(k, t, y, kj);
    return kj.dx;
  };
  for (; k < r.P; ++k, j = 0) {
    if (j == 0 && r.save) {
      core::OdeState s(5);
      for (int i = 0; i < 5; ++i) s[i] = lane_of(x[i], 0);
      r.save->x.push_back(s);
      r.save->friction_ratio.push_back(lane_of(tr.ratio, 0));
    }
    for (; j < r.n; ++j) {
      const double t = k * r.h + j * dt;
      K.eval(k, t, x, k1);
      track(m, x, k1, k, tr);
      if (stop) {
        const int v = lanes_set(violated(m, tr, k, r.backoff)) & stop;
        if (v) {
          why = End::kStopped;
          return v;
        }
      }
      x = core::rk4_step(stage_rhs, t, x, k1.dx, dt);
      auto bad = lane_not(lane_finite(x[0]));
      for (int i = 1; i < 5; ++i) bad = lane_or(bad, lane_not(lane_finite(x[i])));
      bad = lane_or(bad, lane_or(lane_abs(x[2]) > 1e4, lane_abs(x[3]) > 1e4));
      if (const int v = lanes_set(bad)) {
        why = End::kNotFinite;
        ++j;
        return v;
      }
    }
    // the end of the stage with this stage's accelerations
    K.eval(k, (k + 1) * r.h, x, k1);
    track(m, x, k1, k, tr);
    if (stop) {
      const int v = lanes_set(violated(m, tr, k, r.backoff)) & stop;
      if (v) {
        why = End::kStopped;
        return v;
      }
    }
  }
  why = End::kNone;
  return 0;
}

template <typename T>
Track<T> start_track(int P, const SimulationCheckpoints* from, int first) {
  Track<T> tr;
  tr.theta4.assign(P, T(0.0));
  tr.voltage.assign(P, T(0.0));
  tr.current.assign(P, T(0.0));
  tr.power.assign(P, T(0.0));
  tr.normal.assign(P, T(INFINITY));
  tr.friction.assign(P, T(-INFINITY));
  tr.ratio = 0.0;
  if (from) {
    tr.ratio = from->friction_ratio[first];
    const ProfileEvaluation& b = from->evaluation;
    for (int k = 0; k < first; ++k) {
      tr.theta4[k] = b.stage_theta4[k];
      tr.voltage[k] = b.stage_voltage[k];
      tr.current[k] = b.stage_current[k];
      tr.power[k] = b.stage_power[k];
      tr.normal[k] = b.stage_normal[k];
      tr.friction[k] = b.stage_friction[k];
    }
  }
  return tr;
}

template <typename T>
void start_state(const ThrowSetup& setup, const SimulationCheckpoints* from, int first, T x[5]) {
  if (from) {
    for (int i = 0; i < 5; ++i) x[i] = from->x[first][i];
  } else {
    x[0] = setup.theta3_0;
    x[1] = setup.theta4_0;
    x[2] = x[3] = x[4] = 0.0;
  }
}

// simulate.cpp's end of a simulation
ProfileEvaluation finish(const ThrowSetup& setup, const double x[5], Track<double>& tr, End why,
                         double backoff) {
  ProfileEvaluation ev;
  ev.stage_theta4 = std::move(tr.theta4);
  ev.stage_voltage = std::move(tr.voltage);
  ev.stage_current = std::move(tr.current);
  ev.stage_power = std::move(tr.power);
  ev.stage_normal = std::move(tr.normal);
  ev.stage_friction = std::move(tr.friction);
  ev.max_friction_ratio = tr.ratio;
  if (why == End::kStopped) {
    ev.stopped = true;
    ev.energy = std::numeric_limits<double>::max() / 4;
    ev.violation = INFINITY;
    ev.feasible = false;
    return ev;
  }
  if (why == End::kNotFinite) {
    ev.finite = false;
    ev.energy = std::numeric_limits<double>::max() / 4;
    ev.max_friction_ratio = INFINITY;
    classify(setup, ev, backoff);
    return ev;
  }
  finish_finite(setup, x, backoff, ev);
  return ev;
}

Run run_settings(const ThrowSetup& setup, const VelocityProfile& p, double backoff) {
  Run r;
  r.P = p.stages();
  r.h = p.stage_length();
  r.n = std::max(1, setup.steps_per_stage);
  r.dt = r.h / r.n;
  r.backoff = backoff;
  return r;
}

// one profile's simulation, between the runs of its lanes
struct Job {
  LaneProfile<double> nodes;
  double x[5];
  Track<double> tr;
  bool stop = false;  // stop at a certain violation
  ProfileEvaluation* out;
};

// the jobs (the first lane_count<T>; fewer are padded with a copy of the first, whose lanes are
// ignored) from (k, j) in T's lanes until one ends; their states written back, returns the
// jobs that ended
template <typename T>
int run_lanes(const Model& m, const Run& r, Job* const* jobs, int n, int& k, int& j, End& why) {
  constexpr int W = lane_count<T>;
  Job* lane[W];
  for (int i = 0; i < W; ++i) lane[i] = jobs[i < n ? i : 0];
  double v[W];
  auto packed = [&](auto&& value) {
    for (int i = 0; i < W; ++i) v[i] = value(*lane[i]);
    return pack_lanes<T>(v);
  };
  const int P = r.P;
  LaneProfile<T> lp;
  for (int q = 0; q <= P; ++q) {
    lp.v0.push_back(packed([q](const Job& b) { return b.nodes.v0[q]; }));
    lp.v1.push_back(packed([q](const Job& b) { return b.nodes.v1[q]; }));
    lp.q0.push_back(packed([q](const Job& b) { return b.nodes.q0[q]; }));
    lp.q1.push_back(packed([q](const Job& b) { return b.nodes.q1[q]; }));
  }
  LaneState<T> x;
  for (int c = 0; c < 5; ++c) x[c] = packed([c](const Job& b) { return b.x[c]; });
  Track<T> tr;
  auto track_of = [&](std::vector<double> Track<double>::*f) {
    std::vector<T> out(P);
    for (int q = 0; q < P; ++q) out[q] = packed([&](const Job& b) { return (b.tr.*f)[q]; });
    return out;
  };
  tr.theta4 = track_of(&Track<double>::theta4);
  tr.voltage = track_of(&Track<double>::voltage);
  tr.current = track_of(&Track<double>::current);
  tr.power = track_of(&Track<double>::power);
  tr.normal = track_of(&Track<double>::normal);
  tr.friction = track_of(&Track<double>::friction);
  tr.ratio = packed([](const Job& b) { return b.tr.ratio; });
  int stop = 0;
  for (int i = 0; i < W; ++i) stop |= lane[i]->stop ? 1 << i : 0;
  Kernel<T> K(m, lp, r.h);
  const int ended = run(r, K, m, x, tr, k, j, stop, why);
  for (int i = 0; i < n && i < W; ++i) {
    Job& b = *lane[i];
    for (int c = 0; c < 5; ++c) b.x[c] = lane_of(x[c], i);
    for (int q = 0; q < P; ++q) {
      b.tr.theta4[q] = lane_of(tr.theta4[q], i);
      b.tr.voltage[q] = lane_of(tr.voltage[q], i);
      b.tr.current[q] = lane_of(tr.current[q], i);
      b.tr.power[q] = lane_of(tr.power[q], i);
      b.tr.normal[q] = lane_of(tr.normal[q], i);
      b.tr.friction[q] = lane_of(tr.friction[q], i);
    }
    b.tr.ratio = lane_of(tr.ratio, i);
  }
  return ended & ((1 << std::min(n, W)) - 1);
}

// the jobs (1 to 5, all at stage k, step j) to their ends: their lanes run until one ends,
// which is finished; the others go on from where it ended, in as many lanes
void drive(const ThrowSetup& setup, const Model& m, const Run& r, std::vector<Job*> live, int k,
           int j) {
  while (!live.empty()) {
    const int n = static_cast<int>(live.size());
    End why = End::kNone;
    int ended = 0;
    switch (n) {
      case 1: ended = run_lanes<double>(m, r, live.data(), n, k, j, why); break;
      case 2: ended = run_lanes<D2>(m, r, live.data(), n, k, j, why); break;
      case 3: ended = run_lanes<D3>(m, r, live.data(), n, k, j, why); break;
      case 4: ended = run_lanes<D4>(m, r, live.data(), n, k, j, why); break;
      default: ended = run_lanes<D5>(m, r, live.data(), n, k, j, why); break;
    }
    std::vector<Job*> next;
    for (int i = 0; i < n; ++i) {
      Job& b = *live[i];
      if (ended == 0 || (ended >> i & 1))
        *b.out = finish(setup, b.x, b.tr, ended == 0 ? End::kNone : why, r.backoff);
      else
        next.push_back(&b);
    }
    live = std::move(next);
  }
}

}  // namespace

bool kernel_applies(const ThrowSetup& s) {
  const core::PlanarChain& c = s.chain;
  return !s.generic_dynamics && c.num_links() == kN && c.links[0].active && c.links[1].active &&
         !c.links[2].active && !c.links[3].active &&
         c.num_links() + static_cast<int>(c.point_masses.size()) <= core::kMaxLinks * 2 &&
         static_cast<int>(c.spinners.size()) <= Model::kMaxSpin;
}

namespace {

// profiles[0 .. n) (n <= 5, the same stages and final time) from t = 0 or from `from`'s stage
// `first`, at once; stop[i]: profile i stops at a certain violation
void simulate_group(const ThrowSetup& setup, const Model& m, const VelocityProfile* const* profiles,
                    int n, double backoff, const bool* stop, ProfileEvaluation* out,
                    const SimulationCheckpoints* from, int first, SimulationCheckpoints* save) {
  Run r = run_settings(setup, *profiles[0], backoff);
  r.save = save;
  const int k0 = from ? first : 0;
  std::vector<Job> jobs(n);
  std::vector<Job*> live;
  for (int i = 0; i < n; ++i) {
    Job& b = jobs[i];
    b.nodes = lanes_of(*profiles[i]);
    start_state(setup, from, k0, b.x);
    b.tr = start_track<double>(r.P, from, k0);
    b.stop = stop[i];
    b.out = &out[i];
    live.push_back(&b);
  }
  drive(setup, m, r, std::move(live), k0, 0);
}

}  // namespace

ProfileEvaluation simulate_kernel(const ThrowSetup& setup, const VelocityProfile& profile,
                                  double backoff, bool stop_when_infeasible,
                                  const SimulationCheckpoints* from, int first,
                                  SimulationCheckpoints* save) {
  ARM_THROW_UNLESS(kernel_applies(setup), "the simulation kernel needs the tray arm's joints");
  const Model m(setup);
  if (save) {
    save->profile = profile;
    save->x.clear();
    save->friction_ratio.clear();
  }
  const VelocityProfile* p = &profile;
  ProfileEvaluation out;
  simulate_group(setup, m, &p, 1, backoff, &stop_when_infeasible, &out, from, first, save);
  return out;
}

void simulate_kernel_lanes(const ThrowSetup& setup,
                           const std::vector<const VelocityProfile*>& profiles, int width,
                           double backoff, bool stop_when_infeasible, ProfileEvaluation* out,
                           const SimulationCheckpoints* from, int first, const bool* stop_each) {
  ARM_THROW_UNLESS(kernel_applies(setup), "the simulation kernel needs the tray arm's joints");
  width = std::clamp(width, 1, 5);
  const Model m(setup);
  const int n = static_cast<int>(profiles.size());
  std::vector<char> stops(n);  // std::vector<bool> has no data()
  for (int i = 0; i < n; ++i) stops[i] = stop_each ? stop_each[i] : stop_when_infeasible;
  for (int i = 0; i < n;) {
    int g = 1;
    while (g < width && i + g < n && profiles[i + g]->stages() == profiles[i]->stages() &&
           profiles[i + g]->tf == profiles[i]->tf)
      ++g;
    bool st[5];
    for (int q = 0; q < g; ++q) st[q] = stops[i + q];
    simulate_group(setup, m, &profiles[i], g, backoff, st, &out[i], from, first, nullptr);
    i += g;
  }
}

}  // namespace armstudy::studies
