// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/time_optimal/path.hpp"
#include "studies/time_optimal/two_link_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/check.hpp"
#include "core/dynamics.hpp"
#include "core/ik2.hpp"
#include "studies/time_optimal/natural_spline.hpp"

namespace armstudy::studies::time_optimal {
namespace {
constexpr int kTable = 32;  // arc-length table entries per spline piece
// 5-point Gauss-Legendre nodes and weights on [-1, 1]
constexpr double kGlX[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                            0.9061798459386640};
constexpr double kGlW[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                            0.4786286704993665, 0.2369268850561891};

std::string fmt(double v, int digits = 3) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(digits);
  os << v;
  return os.str();
}
}  // namespace

PathGeometry::PathGeometry(const PathSpec& spec) : kind_(spec.kind), pts_(spec.points) {
  const int n = static_cast<int>(pts_.size());
  ARM_THROW_UNLESS(n >= 2, "path has " << n << " points; should have >= 2");
  ARM_THROW_UNLESS(kind_ != PathKind::kLine || n == 2,
                   "a line path has " << n << " points; should have 2");
  for (int i = 0; i + 1 < n; ++i)
    ARM_THROW_UNLESS((pts_[i + 1] - pts_[i]).norm() > 1e-9,
                     "path points " << i + 1 << " and " << i + 2 << " coincide");
  if (kind_ != PathKind::kSpline || n == 2) {
    if (kind_ == PathKind::kSpline) kind_ = PathKind::kPolyline;  // a 2-point spline is a line
    piece_s_.push_back(0.0);
    for (int i = 0; i + 1 < n; ++i)
      piece_s_.push_back(piece_s_.back() + (pts_[i + 1] - pts_[i]).norm());
    length_ = piece_s_.back();
    for (int i = 0; i + 1 < n; ++i) dir_.push_back((pts_[i + 1] - pts_[i]).normalized());
    for (int i = 1; i + 1 < n; ++i) {
      // a corner only where the direction changes
      const Eigen::Vector2d d0 = (pts_[i] - pts_[i - 1]).normalized();
      const Eigen::Vector2d d1 = (pts_[i + 1] - pts_[i]).normalized();
      if ((d1 - d0).norm() > 1e-12) stops_.push_back(piece_s_[i]);
    }
    return;
  }
  // natural cubic spline with chord-length knots: tridiagonal system for the second
  // derivatives m_i, m_0 = m_n-1 = 0 (natural_spline.hpp)
  tau_.assign(n, 0.0);
  for (int i = 1; i < n; ++i) tau_[i] = tau_[i - 1] + (pts_[i] - pts_[i - 1]).norm();
  m_.assign(n, Eigen::Vector2d::Zero());
  if (n > 2) natural_spline_second_derivatives(tau_, pts_, m_);
  // arc-length tables
  piece_s_.push_back(0.0);
  tab_tau_.resize(n - 1);
  tab_s_.resize(n - 1);
  for (int i = 0; i + 1 < n; ++i) {
    double s = piece_s_.back();
    for (int j = 0; j <= kTable; ++j) {
      const double t = tau_[i] + (tau_[i + 1] - tau_[i]) * j / kTable;
      if (j > 0) s += spline_arc(i, tab_tau_[i].back(), t);
      tab_tau_[i].push_back(t);
      tab_s_[i].push_back(s);
    }
    piece_s_.push_back(s);
  }
  length_ = piece_s_.back();
}

Eigen::Vector2d PathGeometry::spline_d(int i, double t, int order) const {
  // cubic spline piece i and its derivatives (Numerical Recipes 3.3.3 form)
  const double h = tau_[i + 1] - tau_[i];
  const double A = (tau_[i + 1] - t) / h, B = (t - tau_[i]) / h;
  if (order == 0)
    return A * pts_[i] + B * pts_[i + 1] +
           ((A * A * A - A) * m_[i] + (B * B * B - B) * m_[i + 1]) * h * h / 6.0;
  if (order == 1)
    return (pts_[i + 1] - pts_[i]) / h - (3 * A * A - 1) / 6.0 * h * m_[i] +
           (3 * B * B - 1) / 6.0 * h * m_[i + 1];
  return A * m_[i] + B * m_[i + 1];
}

double PathGeometry::spline_arc(int i, double t0, double t1) const {
  const double mid = 0.5 * (t0 + t1), half = 0.5 * (t1 - t0);
  double s = 0;
  for (int g = 0; g < 5; ++g) s += kGlW[g] * spline_d(i, mid + half * kGlX[g], 1).norm();
  return s * half;
}

bool PathGeometry::joins_pieces(double s) const {
  return piece_s_.size() > 2 && std::binary_search(piece_s_.begin() + 1, piece_s_.end() - 1, s);
}

PathPoint PathGeometry::at(double s, bool from_left) const {
  s = std::clamp(s, 0.0, length_);
  const int pieces = static_cast<int>(piece_s_.size()) - 1;
  // piece containing s: [piece_s_[i], piece_s_[i+1]) or (.., ..] from the left
  int i;
  if (from_left) {
    i = static_cast<int>(std::lower_bound(piece_s_.begin(), piece_s_.end(), s) - piece_s_.begin()) -
        1;
  } else {
    i = static_cast<int>(std::upper_bound(piece_s_.begin(), piece_s_.end(), s) - piece_s_.begin()) -
        1;
  }
  return at_piece(s, std::clamp(i, 0, pieces - 1));
}

void PathGeometry::at_increasing(const double* s, size_t n, PathPoint* out) const {
  const int pieces = static_cast<int>(piece_s_.size()) - 1;
  // upper_bound - 1: the last piece start <= s, which only grows with s
  int after = 0;  // the number of piece starts <= the clamped s so far
  const int starts = static_cast<int>(piece_s_.size());
  double last = 0;
  for (size_t k = 0; k < n; ++k) {
    const double c = std::clamp(s[k], 0.0, length_);
    if (c < last) after = 0;  // (not increasing after all: from the start again)
    last = c;
    while (after < starts && piece_s_[after] <= c) ++after;
    const int i = std::clamp(after - 1, 0, pieces - 1);
    if (kind_ == PathKind::kSpline) {
      out[k] = at_piece(c, i);
      continue;
    }
    // (at_piece's straight piece, inline)
    const Eigen::Vector2d& d = dir_[i];
    out[k].p = pts_[i] + d * (c - piece_s_[i]);
    out[k].dp = d;
    out[k].ddp.setZero();
  }
}

PathPoint PathGeometry::at_piece(double s, int i) const {
  PathPoint out;
  if (kind_ != PathKind::kSpline) {
    const Eigen::Vector2d& d = dir_[i];
    out.p = pts_[i] + d * (s - piece_s_[i]);
    out.dp = d;
    out.ddp.setZero();
    return out;
  }
  // invert the arc length: table bracket, then Newton on s(tau) - s = 0
  const auto& ts = tab_s_[i];
  int j = static_cast<int>(std::upper_bound(ts.begin(), ts.end(), s) - ts.begin()) - 1;
  j = std::clamp(j, 0, kTable - 1);
  const double w = ts[j + 1] > ts[j] ? (s - ts[j]) / (ts[j + 1] - ts[j]) : 0.0;
  double t = tab_tau_[i][j] + w * (tab_tau_[i][j + 1] - tab_tau_[i][j]);
  for (int it = 0; it < 8; ++it) {
    const double err = ts[j] + spline_arc(i, tab_tau_[i][j], t) - s;
    const double speed = spline_d(i, t, 1).norm();
    t -= err / speed;
    t = std::clamp(t, tab_tau_[i][j], tab_tau_[i][j + 1]);
    if (std::abs(err) < 1e-15 * std::max(1.0, length_)) break;
  }
  const Eigen::Vector2d P = spline_d(i, t, 0), P1 = spline_d(i, t, 1), P2 = spline_d(i, t, 2);
  const double v = P1.norm();
  out.p = P;
  out.dp = P1 / v;
  // chain rule with ds/dtau = |P1|: p'' = (P2 - (P2 . T) T) / |P1|^2
  out.ddp = (P2 - P2.dot(out.dp) * out.dp) / (v * v);
  return out;
}

namespace {
// the path point at s in the chain's base frame, and the rotation into it
Eigen::Vector2d in_base_frame(const core::PlanarChain& chain, const Eigen::Vector2d& p) {
  const double cb = std::cos(chain.base_angle), sb = std::sin(chain.base_angle);
  Eigen::Matrix2d Rt;
  Rt << cb, sb, -sb, cb;
  return Rt * (p - chain.base);
}
}  // namespace

double workspace_margin(const core::PlanarChain& chain, const PathGeometry& path, double s) {
  ARM_THROW_UNLESS(chain.num_links() == 2,
                   "time-optimal arm has " << chain.num_links() << " links; should have 2");
  const Eigen::Vector2d p = in_base_frame(chain, path.at(s).p);
  return core::reach_2link(chain.links[0].length, chain.links[1].length, p).margin;
}

std::string length_text(double m) {
  std::ostringstream os;
  os.precision(3);
  os << m << " m (" << 1e3 * m << " mm)";
  return os.str();
}

TipPointEvaluator::TipPointEvaluator(const core::PlanarChain& chain, const PathGeometry& path,
                                     int configuration)
    : path_(&path), base_(chain.base), configuration_(configuration) {
  ARM_THROW_UNLESS(chain.num_links() == 2,
                   "time-optimal arm has " << chain.num_links() << " links; should have 2");
  ARM_THROW_UNLESS(configuration == 1 || configuration == 2,
                   "configuration " << configuration << " should be 1 or 2");
  L1_ = chain.links[0].length;
  L2_ = chain.links[1].length;
  const double cb = std::cos(chain.base_angle), sb = std::sin(chain.base_angle);
  rt_ << cb, sb, -sb, cb;
  dyn_ = make_two_link_dynamics(chain);
}

bool TipPointEvaluator::at(double s, bool from_left, JointPoint* jp) const {
  const PathPoint pp = path_->at(s, from_left);
  // path in the base frame: rotate by -base_angle about the base
  const Eigen::Vector2d p = rt_ * (pp.p - base_);
  if (!core::reach_2link(L1_, L2_, p).reachable()) return false;
  // core::ik_2link_motion's operations in its order (and ik_2link's), with sin q2 taken
  // once: ik_2link, ik_2link_motion and path_dynamics each take std::sin of the same q2
  const double L1 = L1_, L2 = L2_;
  double c2 = (p.squaredNorm() - L1 * L1 - L2 * L2) / (2.0 * L1 * L2);
  if (c2 > 1.0 + 1e-12 || c2 < -1.0 - 1e-12) return false;
  c2 = std::clamp(c2, -1.0, 1.0);
  double q2 = std::acos(c2);
  if (configuration_ == 2) q2 = -q2;
  const double sin_q2 = std::sin(q2), cos_q2 = std::cos(q2);
  const double q1 = std::atan2(p.y(), p.x()) - std::atan2(L2 * sin_q2, L1 + L2 * c2);
  if (std::abs(sin_q2) < 1e-9) return false;
  const double t1 = q1, t12 = q1 + q2;
  const double s1 = std::sin(t1), c1 = std::cos(t1), s12 = std::sin(t12), c12 = std::cos(t12);
  const double det = L1 * L2 * sin_q2;
  const double j11 = -L1 * s1 - L2 * s12, j12 = -L2 * s12;
  const double j21 = L1 * c1 + L2 * c12, j22 = L2 * c12;
  const auto solve = [&](const Eigen::Vector2d& b) {
    return Eigen::Vector2d((j22 * b.x() - j12 * b.y()) / det, (-j21 * b.x() + j11 * b.y()) / det);
  };
  const Eigen::Vector2d qd = solve(rt_ * pp.dp);
  const double w1 = qd[0], w12 = qd[0] + qd[1];
  const Eigen::Vector2d jd_qd(-L1 * c1 * w1 * w1 - L2 * c12 * w12 * w12,
                              -L1 * s1 * w1 * w1 - L2 * s12 * w12 * w12);
  const Eigen::Vector2d acc = rt_ * pp.ddp;
  const Eigen::Vector2d qdd = solve(acc - jd_qd);
  jp->s = s;
  jp->p = pp.p;
  jp->q = Eigen::Vector2d(q1, q2);
  jp->dq = qd;
  jp->ddq = qdd;
  jp->sin_q2 = sin_q2;
  // tau = M (q' s'' + q'' s'^2) + C(q, q' s') q' s' + g = a s'' + b s'^2 + c, in closed form
  // (two_link_dynamics.hpp; equal to core's generic chain to 1e-12, the tests' oracle)
  path_dynamics_cs(dyn_, cos_q2, sin_q2, jp->q, jp->dq, jp->ddq, &jp->a, &jp->b, &jp->c);
  return true;
}

TipRateEvaluator::TipRateEvaluator(const core::PlanarChain& chain, const PathGeometry& path,
                                   int configuration)
    : path_(&path), base_(chain.base), configuration_(configuration) {
  ARM_THROW_UNLESS(chain.num_links() == 2,
                   "time-optimal arm has " << chain.num_links() << " links; should have 2");
  ARM_THROW_UNLESS(configuration == 1 || configuration == 2,
                   "configuration " << configuration << " should be 1 or 2");
  L1_ = chain.links[0].length;
  L2_ = chain.links[1].length;
  c2_shift_ = L1_ * L1_ + L2_ * L2_;
  c2_scale_ = 1.0 / (2.0 * L1_ * L2_);
  inv_l1l2_ = 1.0 / (L1_ * L2_);
  cb_ = std::cos(chain.base_angle);
  sb_ = std::sin(chain.base_angle);
  rt_ << cb_, sb_, -sb_, cb_;
}

void TipRateArrays::resize(size_t n) {
  for (std::vector<double>* v :
       {&px, &py, &vx, &vy, &ax, &ay, &dq0, &dq1, &ddq0, &ddq1, &c1, &s1, &c2, &s2})
    v->resize(n);
  ok.resize(n);
}

// an AVX build of the loop beside the baseline one, picked at load time where the CPU has
// AVX (4 lanes instead of 2; still no FMA, so the same roundings)
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
__attribute__((target_clones("avx", "default")))
#endif
void TipRateEvaluator::at_points(size_t n, TipRateArrays* a) const {
  // at_point's operations term by term (Eigen's 2x2 products are r00 x + r01 y)
  const double r00 = rt_(0, 0), r01 = rt_(0, 1), r10 = rt_(1, 0), r11 = rt_(1, 1);
  const double bx = base_.x(), by = base_.y();
  const double L1 = L1_, L2 = L2_, shift = c2_shift_, scale = c2_scale_, inv = inv_l1l2_;
  const double cb = cb_, sb = sb_, sign = configuration_ == 1 ? 1.0 : -1.0;
  const double* __restrict px = a->px.data();
  const double* __restrict py = a->py.data();
  const double* __restrict vx = a->vx.data();
  const double* __restrict vy = a->vy.data();
  const double* __restrict ax = a->ax.data();
  const double* __restrict ay = a->ay.data();
  double* __restrict dq0 = a->dq0.data();
  double* __restrict dq1 = a->dq1.data();
  double* __restrict ddq0 = a->ddq0.data();
  double* __restrict ddq1 = a->ddq1.data();
  double* __restrict oc1 = a->c1.data();
  double* __restrict os1 = a->s1.data();
  double* __restrict oc2 = a->c2.data();
  double* __restrict os2 = a->s2.data();
  char* __restrict ok = a->ok.data();
  // (GCC honours __restrict only on parameters: the arrays are distinct vectors)
#pragma GCC ivdep
  for (size_t i = 0; i < n; ++i) {
    const double dx = px[i] - bx, dy = py[i] - by;
    const double p0 = r00 * dx + r01 * dy, p1 = r10 * dx + r11 * dy;
    const double v0 = r00 * vx[i] + r01 * vy[i], v1 = r10 * vx[i] + r11 * vy[i];
    const double a0 = r00 * ax[i] + r01 * ay[i], a1 = r10 * ax[i] + r11 * ay[i];
    const double r2 = p0 * p0 + p1 * p1;
    const double c2 = (r2 - shift) * scale;
    const double w = (1.0 - c2) * (1.0 + c2);
    const double ir2 = 1.0 / r2;
    const double root = std::sqrt(w > 1e-16 ? w : 1.0);  // (ok[i] = 0 where w is replaced)
    const double s2 = sign * root;
    const double k1 = L1 + L2 * c2, k2 = L2 * s2;
    const double c1 = (p0 * k1 + p1 * k2) * ir2, s1 = (p1 * k1 - p0 * k2) * ir2;
    const double c12 = c1 * c2 - s1 * s2, s12 = s1 * c2 + c1 * s2;
    const double idet = inv / s2;
    const double j11 = -L1 * s1 - L2 * s12, j12 = -L2 * s12;
    const double j21 = L1 * c1 + L2 * c12, j22 = L2 * c12;
    const double qd1 = (j22 * v0 - j12 * v1) * idet, qd2 = (-j21 * v0 + j11 * v1) * idet;
    const double w1 = qd1, w12 = qd1 + qd2;
    const double ex = a0 + L1 * c1 * w1 * w1 + L2 * c12 * w12 * w12;
    const double ey = a1 + L1 * s1 * w1 * w1 + L2 * s12 * w12 * w12;
    dq0[i] = qd1;
    dq1[i] = qd2;
    ddq0[i] = (j22 * ex - j12 * ey) * idet;
    ddq1[i] = (-j21 * ex + j11 * ey) * idet;
    oc1[i] = cb * c1 - sb * s1;
    os1[i] = sb * c1 + cb * s1;
    oc2[i] = c2;
    os2[i] = s2;
  }
  // (apart: a byte store or a bool in the loop above keeps it from vectorising)
  for (size_t i = 0; i < n; ++i) ok[i] = (1.0 - oc2[i]) * (1.0 + oc2[i]) > 1e-16;
}

std::optional<JointPoint> joint_point(const core::PlanarChain& chain, const PathGeometry& path,
                                      int configuration, double s, bool from_left,
                                      PathTrouble* trouble) {
  const TipPointEvaluator eval(chain, path, configuration);
  JointPoint jp;
  if (eval.at(s, from_left, &jp)) return jp;
  if (!trouble) return std::nullopt;
  // why not: the same steps again, with the words
  const PathPoint pp = path.at(s, from_left);
  const double L1 = chain.links[0].length, L2 = chain.links[1].length;
  const Eigen::Vector2d p = in_base_frame(chain, pp.p);
  const auto where = [&] {
    return "at s = " + fmt(s) + " m, (x, y) = (" + fmt(pp.p.x()) + ", " + fmt(pp.p.y()) + ") m";
  };
  const core::Reach reach = core::reach_2link(L1, L2, p);
  if (!reach.reachable()) {
    trouble->message = "the path leaves the workspace " + where() + ": it is " +
                       length_text(-reach.margin) + " outside the reachable annulus [" +
                       fmt(reach.inner, 2) + ", " + fmt(reach.outer, 2) + "] m";
    return std::nullopt;
  }
  const double cb = std::cos(chain.base_angle), sb = std::sin(chain.base_angle);
  Eigen::Matrix2d Rt;
  Rt << cb, sb, -sb, cb;
  const auto st = core::ik_2link_motion(L1, L2, p, Rt * pp.dp, Rt * pp.ddp, configuration);
  trouble->message = "the path passes through a singular pose " + where() + ": the elbow is " +
                     (std::cos(st ? st->q[1] : 0.0) > 0 ? "straight" : "folded") +
                     " (sin q2 = 0), where no finite joint speed follows the path";
  return std::nullopt;
}

}  // namespace armstudy::studies::time_optimal
