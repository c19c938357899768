// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/placement/quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <vector>

#include "core/check.hpp"
#include "core/types.hpp"

namespace armstudy::studies::placement {
namespace {

// Gauss-Kronrod 7-15 nodes on [-1, 1] (the non-negative half, 0 last) and weights (QUADPACK
// qk15); the Gauss nodes are the odd-indexed Kronrod nodes
constexpr double kGkNode[8] = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
constexpr double kGkWeight[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double kGaussWeight[4] = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};
constexpr double kEps = std::numeric_limits<double>::epsilon();

// (a - b)(a + b) >= 0, no cancellation in a - b; a point within roundoff of a circle (|a - b|
// within 64 ulp of a) is on it: an end meant on a boundary (x_s = L1 + L2) integrates as the
// exactly touching line, the limit of lines inside (the energy is continuous there, but a
// start 1e-16 m inside would move the stretched elbow's first microseconds)
double diff_sq(double a, double b) {
  if (std::abs(a - b) <= 64.0 * kEps * std::max(std::abs(a), std::abs(b))) return 0.0;
  return std::max(0.0, (a - b) * (a + b));
}

// The program at tau <= T / 2 (the quadrature's half nearer to an end), accurate to its last
// bits where the tip is nearly at rest: core's cycloidal 1 - cos(2 pi u) and u - sin(2 pi u) /
// (2 pi) cancel (at u = 1e-8 they keep 2 and 0 digits); here 2 sin^2(pi u) and a series.
// The polynomials and the trapezoid are accurate as core evaluates them.
core::ProgramSample program_near_end(core::MotionProgram program, double tau, double T, double L) {
  if (program != core::MotionProgram::kCycloidal) return core::evaluate_program(program, tau, T, L);
  const double u = std::clamp(tau / T, 0.0, 1.0);
  const double w = 2.0 * core::kPi, x = w * u;
  double f;  // u - sin(x) / w = (x - sin x) / w
  if (x < 0.5) {
    // x^3/3! - x^5/5! + ... to x^19 (the next term is below 1e-16 of the first)
    double term = x * x * x / 6.0, sum = 0;
    for (int k = 3; k <= 19; k += 2) {
      sum += term;
      term *= -x * x / double((k + 1) * (k + 2));
    }
    f = sum / w;
  } else {
    f = u - std::sin(x) / w;
  }
  const double sh = std::sin(0.5 * x);
  core::ProgramSample p;
  p.s = L * f;
  p.sd = L / T * 2.0 * sh * sh;
  p.sdd = L / (T * T) * w * std::sin(x);
  p.sddd = L / (T * T * T) * w * w * std::cos(x);
  return p;
}

struct QuadSegment {
  double a = 0, b = 0, value = 0, error = 0;
  bool operator<(const QuadSegment& o) const { return error < o.error; }
};

// G7-K15 on [a, b]; false when the integrand is not finite at a node
template <typename F>
bool gk15(const F& f, double a, double b, QuadSegment& out, int& evaluations) {
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  double k = 0, g = 0, abs_k = 0;
  for (int i = 0; i < 8; ++i) {
    const int n = i == 7 ? 1 : 2;
    const double x = h * kGkNode[i];
    const double f1 = f(c - x), f2 = n == 2 ? f(c + x) : 0.0;
    evaluations += n;
    if (!std::isfinite(f1) || !std::isfinite(f2)) return false;
    k += kGkWeight[i] * (f1 + f2);
    abs_k += kGkWeight[i] * (std::abs(f1) + std::abs(f2));
    if (i % 2 == 1) g += kGaussWeight[i / 2] * (f1 + f2);
  }
  out.a = a;
  out.b = b;
  out.value = k * h;
  out.error = std::max(std::abs(k - g) * h, 50.0 * kEps * abs_k * h);
  return true;
}

// integral over l in [0, 1] of |a + l (b - a)|
double mean_abs_on_segment(double a, double b) {
  if ((a >= 0) == (b >= 0)) return 0.5 * std::abs(a + b);
  return 0.5 * (a * a + b * b) / std::abs(b - a);
}

struct FoldJump {
  double energy = 0, error = 0;
};

// The folded elbow's reversal term at t* (quadrature.hpp). The one-sided rates qd-, qd+ at t*
// are limits (the formula is 0/0 there); each side is analytic in |t - t*|, so they are
// extrapolated to t* by Neville's scheme from t* -+ h 2^-k, k = 0..4, h = 3e-4 T (quartic:
// error ~ h^5; the rounding of the rates grows like 1/|t - t*| and stays near 1e-12 here).
// The error is the change of the term between the last two orders. The mass matrix at the
// fold: c2 = -1, s2 = 0.
FoldJump fold_jump(const Arm2& arm, const LinePower& power) {
  constexpr int kOrders = 5;
  const double ts = power.t_closest(), h = 3e-4 * power.duration();
  const auto rates = [&](double side, int orders) {
    Eigen::Vector2d tab[kOrders];
    double step[kOrders];
    for (int k = 0; k < orders; ++k) {
      step[k] = h * std::ldexp(1.0, -k);
      const Arm2Sample o = power.sample(ts + side * step[k]);
      tab[k] = Eigen::Vector2d(o.qd1, o.qd2);
    }
    for (int m = 1; m < orders; ++m)
      for (int k = orders - 1; k >= m; --k)
        tab[k] = (step[k - m] * tab[k] - step[k] * tab[k - 1]) / (step[k - m] - step[k]);
    return tab[orders - 1];
  };
  const double g = -arm.A;  // A c2 - B s2 at c2 = -1, s2 = 0
  Eigen::Matrix2d m;
  m << arm.a11 + 2 * g, arm.a12 + g, arm.a12 + g, arm.a22;
  const auto term = [&](int orders) {
    const Eigen::Vector2d before = rates(-1, orders), after = rates(+1, orders);
    const Eigen::Vector2d impulse = m * (after - before);
    double e = 0;
    for (int i = 0; i < 2; ++i)
      e += std::abs(impulse[i]) * mean_abs_on_segment(before[i], after[i]);
    return e;
  };
  FoldJump j;
  j.energy = term(kOrders);
  j.error = std::abs(term(kOrders - 1) - j.energy);
  return j;
}

}  // namespace

LinePower::LinePower(const Arm2& arm, core::MotionProgram program, double duration, double length,
                     const Line& line, int configuration)
    : arm_(arm),
      program_(program),
      T_(duration),
      L_(length),
      sign_(configuration == 1 ? 1.0 : -1.0),
      line_(line) {
  ARM_THROW_UNLESS(duration > 0 && length > 0, "the quadrature needs T > 0 and L > 0");
  const double inner = std::abs(arm.L1 - arm.L2), outer = arm.L1 + arm.L2;
  end_ = line.start + length * line.dir;
  s_star_ = -line.start.dot(line.dir);
  // the root's distance from the line: |start x dir|, no cancellation
  const double h = std::abs(line.start.x() * line.dir.y() - line.start.y() * line.dir.x());
  foot_on_segment_ = s_star_ > 0 && s_star_ < length;
  din_foot_ = diff_sq(h, inner);
  din0_ = diff_sq(line.start.norm(), inner);
  dout0_ = diff_sq(outer, line.start.norm());
  dinL_ = diff_sq(end_.norm(), inner);
  doutL_ = diff_sq(outer, end_.norm());
  t_closest_ = std::numeric_limits<double>::quiet_NaN();
  if (foot_on_segment_) {
    // s(t) is monotone: bisection to the last bit
    double lo = 0, hi = duration;
    for (int it = 0; it < 200 && hi - lo > 0; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (core::evaluate_program(program, mid, duration, length).s < s_star_ ? lo : hi) = mid;
    }
    t_closest_ = 0.5 * (lo + hi);
  }
}

JointPowers LinePower::at(double t) const {
  const Arm2Sample o = sample(t);
  return {o.tau1 * o.qd1, o.tau2 * o.qd2};
}

Arm2Sample LinePower::sample(double t) const {
  // the half nearer to its end: s (or L - s, by the programs' symmetry) from that end
  const bool tail = t > 0.5 * T_;
  const double tau = tail ? T_ - t : t;
  const core::ProgramSample ps = program_near_end(program_, tau, T_, L_);
  const double sigma = ps.s;  // distance along the line from the nearer end
  const double sd = ps.sd, sdd = tail ? -ps.sdd : ps.sdd;
  Eigen::Vector2d p;
  double din, dout;  // r^2 - inner^2, outer^2 - r^2
  if (!tail) {
    p = line_.start + sigma * line_.dir;
    const double w = sigma * (sigma - 2.0 * s_star_);  // r^2 - |start|^2
    din = din0_ + w;
    dout = dout0_ - w;
  } else {
    p = end_ - sigma * line_.dir;
    const double w = sigma * (sigma - 2.0 * (L_ - s_star_));  // r^2 - |end|^2
    din = dinL_ + w;
    dout = doutL_ - w;
  }
  if (foot_on_segment_) {
    // near t*: h^2 - inner^2 + (s - s*)^2
    const double x = tail ? (L_ - s_star_) - sigma : sigma - s_star_;
    din = din_foot_ + x * x;
  }
  din = std::max(din, 0.0);
  dout = std::max(dout, 0.0);
  const double two_l1l2 = 2.0 * arm_.L1 * arm_.L2;
  const double c2 = dout <= din ? 1.0 - dout / two_l1l2 : din / two_l1l2 - 1.0;
  const double s2 = sign_ * std::sqrt(din * dout) / two_l1l2;
  return arm2_sample_elbow(arm_, p.x(), p.y(), sd * line_.dir.x(), sd * line_.dir.y(),
                           sdd * line_.dir.x(), sdd * line_.dir.y(), c2, s2);
}

namespace {
double joint_power(const JointPowers& p, int j) { return j == 0 ? p.p1 : p.p2; }

// the root of joint j's power in [lo, hi], where it has the signs flo and fhi: the Illinois
// variant of regula falsi (superlinear, the bracket kept) to 1e-12 of `span`: a kink
// misplaced by dt changes the integral by ~ |p'| dt^2
double power_root(const LinePower& power, int j, double lo, double hi, double flo, double fhi,
                  double span, int& evaluations) {
  int side = 0;
  for (int it = 0; it < 200 && hi - lo > 1e-12 * span; ++it) {
    const double secant = (lo * fhi - hi * flo) / (fhi - flo);
    // every fourth step a bisection: the bracket shrinks however the secant stalls
    const double mid = it % 4 == 3 || !(secant > lo && secant < hi) ? 0.5 * (lo + hi) : secant;
    if (mid <= lo || mid >= hi) break;
    const double vm = joint_power(power.at(mid), j);
    ++evaluations;
    if (!std::isfinite(vm)) break;
    if (vm == 0) return mid;
    if ((vm < 0) == (flo < 0)) {
      lo = mid;
      flo = vm;
      if (side == -1) fhi *= 0.5;
      side = -1;
    } else {
      hi = mid;
      fhi = vm;
      if (side == 1) flo *= 0.5;
      side = 1;
    }
  }
  return 0.5 * (lo + hi);
}

// a pair of sign changes of joint j's power hidden between scan points: where |p_j| has a
// local minimum at a scan point (v0, v1, v2 of one sign at t0 < t1 < t2), a golden-section
// search of sign * p_j over [t0, t2] looks for the other sign; found, both roots on either
// side are appended to `kinks`. Without it a lobe narrower than the scan spacing lies between
// the quadrature's nodes too, and the |.| integral misses twice its area (a pair 3.9 ms apart
// on placement-example-3's 3-4-5 optimum: 1.6e-5 J, against an error estimate of 5e-10 J).
void hidden_pair(const LinePower& power, int j, double t0, double t2, double v1, double span,
                 int& evaluations, std::vector<double>& kinks) {
  const double sign = v1 > 0 ? 1.0 : -1.0;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = t0, hi = t2;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = sign * joint_power(power.at(x1), j), f2 = sign * joint_power(power.at(x2), j);
  evaluations += 2;
  for (int it = 0; it < 40 && f1 > 0 && f2 > 0 && hi - lo > 1e-12 * span; ++it) {
    if (f1 < f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = sign * joint_power(power.at(x1), j);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = sign * joint_power(power.at(x2), j);
    }
    ++evaluations;
  }
  if (!(std::min(f1, f2) < 0)) return;  // no other sign (or not finite): no pair
  const double tm = f1 < f2 ? x1 : x2, vm = sign * std::min(f1, f2);
  kinks.push_back(power_root(power, j, t0, tm, sign, vm, span, evaluations));
  kinks.push_back(power_root(power, j, tm, t2, vm, sign, span, evaluations));
}

// the |.| kinks in [a, b]: sign changes of either joint's power on a scan of n points, and
// pairs of them hidden between two scan points (hidden_pair), found to 1e-12 of the interval
// and appended to `kinks`; false when the power is not finite at a scanned point
bool power_kinks(const LinePower& power, double a, double b, int n, int& evaluations,
                 std::vector<double>& kinks) {
  std::vector<double> t(n);
  std::vector<JointPowers> p(n);
  for (int k = 0; k < n; ++k) {
    t[k] = a + (b - a) * (k + 0.5) / n;
    p[k] = power.at(t[k]);
    ++evaluations;
    if (!std::isfinite(p[k].p1) || !std::isfinite(p[k].p2)) return false;
  }
  for (int j = 0; j < 2; ++j)
    for (int k = 1; k < n; ++k) {
      const double v0 = joint_power(p[k - 1], j), v1 = joint_power(p[k], j);
      if ((v0 < 0 && v1 > 0) || (v0 > 0 && v1 < 0))
        kinks.push_back(power_root(power, j, t[k - 1], t[k], v0, v1, b - a, evaluations));
      if (k + 1 == n) continue;
      const double v2 = joint_power(p[k + 1], j);
      const bool one_sign = (v0 > 0 && v1 > 0 && v2 > 0) || (v0 < 0 && v1 < 0 && v2 < 0);
      if (one_sign && std::abs(v1) <= std::abs(v0) && std::abs(v1) <= std::abs(v2))
        hidden_pair(power, j, t[k - 1], t[k + 1], v1, b - a, evaluations, kinks);
    }
  return true;
}

// the value and error summed afresh from the segments (no drift of running sums)
void heap_totals(const std::priority_queue<QuadSegment>& heap, double& value, double& error) {
  std::priority_queue<QuadSegment> copy = heap;
  value = 0;
  error = 0;
  while (!copy.empty()) {
    value += copy.top().value;
    error += copy.top().error;
    copy.pop();
  }
}

// adaptive G7-K15 of f over the intervals between the breakpoints bp: the segment of the
// largest error halved until the error is within tol_rel or max_intervals are used; fills
// q's energy, error, intervals and converged (infinite energy when f is not finite)
template <typename F>
void adaptive_gk15(const F& f, const std::vector<double>& bp, double T, double tol_rel,
                   int max_intervals, int& evaluations, EnergyQuadrature& q) {
  std::priority_queue<QuadSegment> heap;
  for (size_t i = 0; i + 1 < bp.size(); ++i) {
    if (!(bp[i + 1] > bp[i])) continue;
    QuadSegment s;
    if (!gk15(f, bp[i], bp[i + 1], s, evaluations)) {
      q.energy = std::numeric_limits<double>::infinity();
      return;
    }
    heap.push(s);
  }
  double value = 0, error = 0;
  heap_totals(heap, value, error);
  while (int(heap.size()) < max_intervals && !(error <= tol_rel * std::abs(value))) {
    const QuadSegment worst = heap.top();
    const double mid = 0.5 * (worst.a + worst.b);
    // an interval that cannot be halved any more: the estimate stays as it is
    if (!(mid > worst.a && mid < worst.b) || worst.b - worst.a < 1e-15 * T) break;
    QuadSegment left, right;
    if (!gk15(f, worst.a, mid, left, evaluations) || !gk15(f, mid, worst.b, right, evaluations)) {
      q.energy = std::numeric_limits<double>::infinity();
      return;
    }
    heap.pop();
    heap.push(left);
    heap.push(right);
    value += left.value + right.value - worst.value;
    error += left.error + right.error - worst.error;
    if (heap.size() % 256 == 0) heap_totals(heap, value, error);
  }
  heap_totals(heap, value, error);
  q.energy = value;
  q.error = error;
  q.intervals = int(heap.size());
  q.converged = std::isfinite(value) && error <= tol_rel * std::abs(value);
}
}  // namespace

EnergyQuadrature energy_quadrature(const Arm2& arm, core::MotionProgram program, double duration,
                                   double length, const Line& line, int configuration,
                                   double tol_rel, int max_intervals) {
  const LinePower power(arm, program, duration, length, line, configuration);
  const double T = duration;
  EnergyQuadrature q;
  q.tolerance_rel = tol_rel;
  q.t_closest = power.t_closest();
  int evaluations = 0;
  // breakpoints: the ends, t*, the trapezoidal program's corners
  std::vector<double> bp = {0.0, T};
  if (std::isfinite(q.t_closest)) bp.push_back(q.t_closest);
  if (program == core::MotionProgram::kTrapezoidal) {
    bp.push_back(T / 3.0);
    bp.push_back(2.0 * T / 3.0);
  }
  std::sort(bp.begin(), bp.end());
  // the |.| kinks: sign changes of either joint's power on a scan inside each interval
  std::vector<double> kinks;
  constexpr int kScan = 256;
  for (size_t i = 0; i + 1 < bp.size(); ++i) {
    const double a = bp[i], b = bp[i + 1];
    if (!(b > a)) continue;
    const int n = std::max(8, int(std::lround(kScan * (b - a) / T)));
    if (!power_kinks(power, a, b, n, evaluations, kinks)) {
      q.energy = std::numeric_limits<double>::infinity();
      q.evaluations = evaluations;
      return q;
    }
  }
  for (const double k : kinks) bp.push_back(k);
  std::sort(bp.begin(), bp.end());
  bp.erase(std::unique(bp.begin(), bp.end()), bp.end());
  q.breakpoints = int(bp.size()) - 2;

  const auto f = [&](double t) { return power.at(t).abs_sum(); };
  adaptive_gk15(f, bp, T, tol_rel, max_intervals, evaluations, q);
  if (power.folds() && std::isfinite(q.energy)) {
    const FoldJump j = fold_jump(arm, power);
    q.jump = j.energy;
    q.jump_error = j.error;
    q.energy += j.energy;
    q.error += j.error;
    q.converged = std::isfinite(q.energy) && q.error <= tol_rel * std::abs(q.energy);
  }
  q.evaluations = evaluations;
  return q;
}

}  // namespace armstudy::studies::placement
