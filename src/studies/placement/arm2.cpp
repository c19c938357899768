// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/placement/arm2.hpp"

#include <algorithm>
#include <limits>

#include "core/check.hpp"
#include "studies/placement/arm2_block.hpp"

namespace armstudy::studies::placement {

Arm2 make_arm2(const core::PlanarChain& chain) {
  ARM_THROW_UNLESS(chain.num_links() == 2,
                   "the placement evaluator needs 2 links, the arm has " << chain.num_links());
  ARM_THROW_UNLESS(chain.links[0].active && chain.links[1].active,
                   "the placement evaluator needs both joints active");
  ARM_THROW_UNLESS(chain.gravity == 0.0,
                   "the placement evaluator needs gravity 0 (horizontal "
                   "plane), the arm has "
                       << chain.gravity << " m/s^2");
  Arm2 a;
  a.L1 = chain.links[0].length;
  a.L2 = chain.links[1].length;
  // inertia about each joint, mass and first moment of link 2's bodies
  double J1 = 0, J2 = 0, m2 = 0, mx2 = 0, my2 = 0;
  const auto add = [&](int link, double m, double x, double y, double I) {
    if (link == 0) {
      J1 += I + m * (x * x + y * y);
    } else {
      J2 += I + m * (x * x + y * y);
      m2 += m;
      mx2 += m * x;
      my2 += m * y;
    }
  };
  for (int i = 0; i < 2; ++i) {
    const core::Link& l = chain.links[i];
    add(i, l.mass, l.com, l.com_lateral, l.inertia);
  }
  for (const core::PointMass& p : chain.point_masses) add(p.link, p.mass, p.x, p.y, 0.0);
  a.a11 = J1 + m2 * a.L1 * a.L1 + J2;
  a.a12 = J2;
  a.a22 = J2;
  a.A = a.L1 * mx2;
  a.B = a.L1 * my2;
  // spinning inertias add the constant I c c^T
  for (const core::SpinningInertia& s : chain.spinners) {
    a.a11 += s.inertia * s.coeffs[0] * s.coeffs[0];
    a.a12 += s.inertia * s.coeffs[0] * s.coeffs[1];
    a.a22 += s.inertia * s.coeffs[1] * s.coeffs[1];
  }
  return a;
}

ProgramTable make_program_table(core::MotionProgram program, double duration, double length,
                                int samples) {
  ARM_THROW_UNLESS(samples >= 3, "samples per trajectory " << samples << " should be >= 3");
  ARM_THROW_UNLESS(duration > 0, "duration " << duration << " s should be > 0");
  ARM_THROW_UNLESS(length > 0, "line length " << length << " m should be > 0");
  ProgramTable t;
  t.program = program;
  t.duration = duration;
  t.length = length;
  t.dt = duration / (samples - 1);
  t.s.resize(samples);
  t.sd.resize(samples);
  t.sdd.resize(samples);
  for (int k = 0; k < samples; ++k) {
    const auto p = core::evaluate_program(program, k * t.dt, duration, length);
    t.s[k] = p.s;
    t.sd[k] = p.sd;
    t.sdd[k] = p.sdd;
  }
  return t;
}

namespace {
// Gregory's end-corrected trapezoidal rule: end weights exact for polynomials of degree 5
// near each end (from the Euler-Maclaurin end terms); interior weights 1
constexpr int kGregory = 6;
constexpr double kGregoryWeight[kGregory] = {19087.0 / 60480, 84199.0 / 60480, 18869.0 / 30240,
                                             37621.0 / 30240, 55031.0 / 60480, 61343.0 / 60480};
}  // namespace

namespace {
// samples per block of the structure-of-arrays loop (on the stack: 5 x 2 kB)
constexpr int kBlock = 256;
}  // namespace

LineMetrics evaluate_line(const Arm2& arm, const ProgramTable& table, const Line& line,
                          int configuration) {
  const double sign = configuration == 1 ? 1.0 : -1.0;
  const double sx = line.start.x(), sy = line.start.y();
  const double ux = line.dir.x(), uy = line.dir.y();
  const int n = table.size();
  double e_sum = 0, w_sum = 0, e_end = 0, w_end = 0;
  double pt1 = 0, pt2 = 0, pp1 = 0, pp2 = 0, min_sin = 1;
  double w_head[kGregory] = {}, w_tail[kGregory] = {};
  double coarse = 0, e_even = 0;  // trapezoid on the even samples (and the last)
  double P1[kBlock], P2[kBlock], T1[kBlock], T2[kBlock], S2[kBlock];
  for (int k0 = 0; k0 < n; k0 += kBlock) {
    const int m = std::min(kBlock, n - k0);
    sample_block(arm, table.s.data() + k0, table.sd.data() + k0, table.sdd.data() + k0, m, sx, sy,
                 ux, uy, sign, P1, P2, T1, T2, S2);
    // the sums and peaks in evaluate_line_scalar's order (the same figures, bit for bit)
    for (int i = 0; i < m; ++i) {
      const int k = k0 + i;
      const double p1 = P1[i], p2 = P2[i];
      const double e = std::abs(p1) + std::abs(p2), w = p1 + p2;
      e_sum += e;
      w_sum += w;
      if (k % 2 == 0) {
        if (k > 0) coarse += e_even + e;
        e_even = e;
      } else if (k == n - 1) {
        coarse += 0.5 * (e_even + e);
      }
      if (k == 0 || k == n - 1) {
        e_end += e;
        w_end += w;
      }
      if (k < kGregory) w_head[k] = w;
      if (k >= n - kGregory) w_tail[n - 1 - k] = w;
      pt1 = std::max(pt1, T1[i]);
      pt2 = std::max(pt2, T2[i]);
      pp1 = std::max(pp1, std::abs(p1));
      pp2 = std::max(pp2, std::abs(p2));
      min_sin = std::min(min_sin, S2[i]);
    }
  }
  LineMetrics m;
  m.energy = table.dt * (e_sum - 0.5 * e_end);
  m.energy_coarse = table.dt * coarse;
  if (n >= 2 * kGregory) {
    for (int k = 0; k < kGregory; ++k) w_sum += (kGregoryWeight[k] - 1.0) * (w_head[k] + w_tail[k]);
    m.signed_work = table.dt * w_sum;
  } else {
    m.signed_work = table.dt * (w_sum - 0.5 * w_end);
  }
  m.peak_torque[0] = pt1;
  m.peak_torque[1] = pt2;
  m.peak_power[0] = pp1;
  m.peak_power[1] = pp2;
  m.min_abs_sin = min_sin;
  if (!std::isfinite(m.energy) || !std::isfinite(pt1) || !std::isfinite(pt2) || min_sin == 0.0) {
    m.energy = std::numeric_limits<double>::infinity();
  }
  return m;
}

LineMetrics evaluate_line_scalar(const Arm2& arm, const ProgramTable& table, const Line& line,
                                 int configuration) {
  const double sign = configuration == 1 ? 1.0 : -1.0;
  const double sx = line.start.x(), sy = line.start.y();
  const double ux = line.dir.x(), uy = line.dir.y();
  const int n = table.size();
  const double* s = table.s.data();
  const double* sd = table.sd.data();
  const double* sdd = table.sdd.data();
  double e_sum = 0, w_sum = 0, e_end = 0, w_end = 0;
  double pt1 = 0, pt2 = 0, pp1 = 0, pp2 = 0, min_sin = 1;
  double w_head[kGregory] = {}, w_tail[kGregory] = {};
  double coarse = 0, e_even = 0;  // trapezoid on the even samples (and the last)
  for (int k = 0; k < n; ++k) {
    const Arm2Sample o = arm2_sample(arm, sx + s[k] * ux, sy + s[k] * uy, sd[k] * ux, sd[k] * uy,
                                     sdd[k] * ux, sdd[k] * uy, sign);
    const double p1 = o.tau1 * o.qd1, p2 = o.tau2 * o.qd2;
    const double e = std::abs(p1) + std::abs(p2), w = p1 + p2;
    e_sum += e;
    w_sum += w;
    if (k % 2 == 0) {
      if (k > 0) coarse += e_even + e;  // (e_a + e_b) / 2 over 2 dt, times dt below
      e_even = e;
    } else if (k == n - 1) {
      coarse += 0.5 * (e_even + e);  // the last, single interval
    }
    if (k == 0 || k == n - 1) {
      e_end += e;
      w_end += w;
    }
    if (k < kGregory) w_head[k] = w;
    if (k >= n - kGregory) w_tail[n - 1 - k] = w;
    pt1 = std::max(pt1, std::abs(o.tau1));
    pt2 = std::max(pt2, std::abs(o.tau2));
    pp1 = std::max(pp1, std::abs(p1));
    pp2 = std::max(pp2, std::abs(p2));
    min_sin = std::min(min_sin, std::abs(o.s2));
  }
  // trapezoidal rule on the uniform grid: h (sum - (y0 + yn) / 2)
  LineMetrics m;
  m.energy = table.dt * (e_sum - 0.5 * e_end);
  m.energy_coarse = table.dt * coarse;
  // the signed power is smooth (it is dK/dt): Gregory's rule makes its integral O(h^6);
  // |power| has kinks where a joint's power changes sign, so the energy keeps the trapezoid
  if (n >= 2 * kGregory) {
    for (int k = 0; k < kGregory; ++k) w_sum += (kGregoryWeight[k] - 1.0) * (w_head[k] + w_tail[k]);
    m.signed_work = table.dt * w_sum;
  } else {
    m.signed_work = table.dt * (w_sum - 0.5 * w_end);
  }
  m.peak_torque[0] = pt1;
  m.peak_torque[1] = pt2;
  m.peak_power[0] = pp1;
  m.peak_power[1] = pp2;
  m.min_abs_sin = min_sin;
  if (!std::isfinite(m.energy) || !std::isfinite(pt1) || !std::isfinite(pt2) || min_sin == 0.0) {
    m.energy = std::numeric_limits<double>::infinity();
  }
  return m;
}

TimeSeries sample_series(const Arm2& arm, const ProgramTable& table, const Line& line,
                         int configuration) {
  const double sign = configuration == 1 ? 1.0 : -1.0;
  const int n = table.size();
  TimeSeries ts;
  ts.t.resize(n);
  ts.tip.resize(n);
  ts.q.resize(n);
  ts.qd.resize(n);
  ts.qdd.resize(n);
  ts.tau.resize(n);
  ts.power.resize(n);
  ts.energy.resize(n);
  double prev_q1 = 0, prev_abs = 0;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d p = line.start + table.s[k] * line.dir;
    const Eigen::Vector2d v = table.sd[k] * line.dir, a = table.sdd[k] * line.dir;
    const Arm2Sample o = arm2_sample(arm, p.x(), p.y(), v.x(), v.y(), a.x(), a.y(), sign);
    double q1 = std::atan2(o.s1, o.c1);
    // unwrap link 1's angle so that the series is continuous
    if (k > 0) q1 += 2.0 * core::kPi * std::round((prev_q1 - q1) / (2.0 * core::kPi));
    prev_q1 = q1;
    ts.t[k] = k * table.dt;
    ts.tip[k] = p;
    ts.q[k] = {q1, std::atan2(o.s2, o.c2)};
    ts.qd[k] = {o.qd1, o.qd2};
    ts.qdd[k] = {o.qdd1, o.qdd2};
    ts.tau[k] = {o.tau1, o.tau2};
    ts.power[k] = {o.tau1 * o.qd1, o.tau2 * o.qd2};
    const double abs_p = std::abs(ts.power[k][0]) + std::abs(ts.power[k][1]);
    ts.energy[k] = k == 0 ? 0.0 : ts.energy[k - 1] + 0.5 * table.dt * (abs_p + prev_abs);
    prev_abs = abs_p;
  }
  return ts;
}

}  // namespace armstudy::studies::placement
