// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/placement/refine.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include <nlopt.hpp>

#include "studies/placement/candidate.hpp"
#include "studies/placement/geometry.hpp"
#include "studies/placement/peaks.hpp"
#include "studies/placement/quadrature.hpp"

namespace armstudy::studies::placement {
namespace {

constexpr double kRefineInf = std::numeric_limits<double>::infinity();
constexpr double kRefineNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kMaxConstraints = 6;  // inner, outer, torque 1, 2, power 1, 2
// relative error the objective's adaptive quadrature is asked for in the converged stages
constexpr double kObjectiveTol = 1e-11;

// the problem in scaled variables u = (x_s - x0) / hx, v = (phi - p0) / hphi
class Problem {
 public:
  Problem(const Spec& spec, const Arm2& arm, const ProgramTable& table, int configuration,
          double x0, double p0, double hx, double hphi)
      : spec_(spec),
        arm_(arm),
        table_(table),
        configuration_(configuration),
        an_(annulus(arm.L1, arm.L2)),
        x0_(x0),
        p0_(p0),
        hx_(hx),
        hphi_(hphi) {
    used_[0] = used_[1] = true;
    for (int j = 0; j < 2; ++j) {
      used_[2 + j] = spec.torque_limit.has_value();
      used_[4 + j] = spec.power_limit.has_value();
    }
  }

  struct Eval {
    double u = kRefineNaN, v = kRefineNaN;
    double energy = kRefineInf;
    double error = 0;  // J, the objective's quadrature error estimate (0: sampled)
    double g[kMaxConstraints] = {};
    bool feasible = false;
  };

  double x_s(double u) const { return x0_ + u * hx_; }
  double phi(double v) const { return p0_ + v * hphi_; }
  bool used(int k) const { return used_[k]; }
  int evaluations() const { return evals_; }
  bool has_best() const { return best_.feasible; }
  const Eval& best() const { return best_; }
  bool limits() const { return used_[2] || used_[3] || used_[4] || used_[5]; }

  // from now on the objective is the converged energy (adaptive quadrature); the points
  // found on the sampled energy no longer compete
  void use_quadrature() {
    quadrature_ = true;
    best_ = Eval{};
    last_ = Eval{};
  }
  bool quadrature() const { return quadrature_; }
  int quadrature_evaluations() const { return quad_evals_; }

  // J, the objective's noise at (u, v): twice its change from the quadrature asked for
  // kObjectiveTol to one asked for 100 times less (the error the fitted quadratics see from
  // point to point), and 1e-15 of the energy (roundoff)
  double noise(double u, double v) const {
    const Line line = thesis_line(x_s(u), phi(v));
    const auto q = [&](double tol) {
      return energy_quadrature(arm_, table_.program, spec_.duration, spec_.length, line,
                               configuration_, tol)
          .energy;
    };
    const double e = q(kObjectiveTol);
    return 2 * std::abs(e - q(0.01 * kObjectiveTol)) + 1e-15 * std::abs(e);
  }

  // the limit constraint k >= 2 at (u, v) from the sampled peaks alone (no energy, not
  // cached): what a search along a limit's boundary bisects
  double limit(int k, double u, double v) const {
    const double xs = x_s(u);
    if (!(xs > 0)) return kRefineInf;
    const Line line = thesis_line(xs, phi(v));
    const LineCheck chk = check_line(arm_.L1, arm_.L2, line, spec_.length);
    if (chk.boundary_distance < 0) return kRefineInf;
    const int j = (k - 2) % 2;
    if (quadrature_) {
      const MotionPeaks p = peaks(line);
      if (!p.finite) return kRefineInf;
      return k < 4 ? p.torque[j] / (*spec_.torque_limit)[j] - 1.0
                   : p.power[j] / (*spec_.power_limit)[j] - 1.0;
    }
    const LineMetrics m = evaluate_line(arm_, table_, line, configuration_);
    if (!m.finite()) return kRefineInf;
    return k < 4 ? m.peak_torque[j] / (*spec_.torque_limit)[j] - 1.0
                 : m.peak_power[j] / (*spec_.power_limit)[j] - 1.0;
  }

  // the peaks of the continuous motion along `line` (peaks.hpp), refined from the table's
  // samples: the limits of the converged pass
  MotionPeaks peaks(const Line& line) const {
    return continuous_peaks(arm_, table_.program, spec_.duration, spec_.length, line,
                            configuration_, table_.size());
  }

  // the geometric constraints alone (no motion evaluated)
  double geometric(int k, double u, double v) const {
    const LineCheck chk = check_line(arm_.L1, arm_.L2, thesis_line(x_s(u), phi(v)), spec_.length);
    return k == 0 ? (an_.inner + spec_.singularity_margin) - chk.r_min
                  : chk.r_max - (an_.outer - spec_.singularity_margin);
  }

  // energy and every constraint at (u, v); the last point is cached (COBYLA asks for the
  // objective and each constraint at the same point)
  const Eval& at(double u, double v, bool track = true) {
    if (u == last_.u && v == last_.v) return last_;
    ++evals_;
    Eval e;
    e.u = u;
    e.v = v;
    const double xs = x_s(u);
    if (!(xs > 0)) {
      for (double& g : e.g) g = kRefineInf;
      last_ = e;
      return last_;
    }
    const Line line = thesis_line(xs, phi(v));
    const LineCheck chk = check_line(arm_.L1, arm_.L2, line, spec_.length);
    e.g[0] = (an_.inner + spec_.singularity_margin) - chk.r_min;
    e.g[1] = chk.r_max - (an_.outer - spec_.singularity_margin);
    LineMetrics m;
    // the sampled motion: the objective of the first stages, the limits' peaks always
    if (chk.boundary_distance >= 0 && (!quadrature_ || limits()))
      m = evaluate_line(arm_, table_, line, configuration_);
    else if (chk.boundary_distance < 0)
      m.energy = kRefineInf;
    if (quadrature_ && limits() && m.finite()) {
      // the converged pass keeps the limits on the continuous motion, not at the samples
      const MotionPeaks p = peaks(line);
      for (int j = 0; j < 2; ++j) {
        m.peak_torque[j] = p.finite ? p.torque[j] : kRefineInf;
        m.peak_power[j] = p.finite ? p.power[j] : kRefineInf;
      }
    }
    for (int j = 0; j < 2; ++j) {
      e.g[2 + j] =
          spec_.torque_limit ? m.peak_torque[j] / (*spec_.torque_limit)[j] - 1.0 : -kRefineInf;
      e.g[4 + j] =
          spec_.power_limit ? m.peak_power[j] / (*spec_.power_limit)[j] - 1.0 : -kRefineInf;
    }
    e.energy = m.finite() ? m.energy : kRefineInf;
    if (quadrature_ && std::isfinite(e.energy)) {
      ++quad_evals_;
      const EnergyQuadrature q = energy_quadrature(
          arm_, table_.program, spec_.duration, spec_.length, line, configuration_, kObjectiveTol);
      e.energy = std::isfinite(q.energy) ? q.energy : kRefineInf;
      e.error = q.error;
    }
    e.feasible = std::isfinite(e.energy);
    for (int k = 0; k < kMaxConstraints; ++k) e.feasible = e.feasible && !(e.g[k] > 0);
    if (track && e.feasible && (!best_.feasible || e.energy < best_.energy)) best_ = e;
    last_ = e;
    return last_;
  }

  double penalty() const { return best_.feasible ? 10.0 * best_.energy + 1.0 : 1e6; }

 private:
  const Spec& spec_;
  const Arm2& arm_;
  const ProgramTable& table_;
  int configuration_;
  Annulus an_;
  double x0_, p0_, hx_, hphi_;
  bool used_[kMaxConstraints] = {};
  int evals_ = 0, quad_evals_ = 0;
  bool quadrature_ = false;
  Eval last_, best_;
};

constexpr double kBox = 4.0;  // scaled half-width of the search box

double cobyla(Problem& pr, double u0, double v0, double step, int maxeval) {
  struct Con {
    Problem* pr;
    int k;
  };
  nlopt::opt opt(nlopt::LN_COBYLA, 2);
  opt.set_lower_bounds({-kBox, -kBox});
  opt.set_upper_bounds({kBox, kBox});
  opt.set_min_objective(
      [](const std::vector<double>& x, std::vector<double>&, void* d) {
        Problem* p = static_cast<Problem*>(d);
        const double e = p->at(x[0], x[1]).energy;
        return std::isfinite(e) ? e : p->penalty();
      },
      &pr);
  std::vector<Con> cons;
  cons.reserve(kMaxConstraints);
  for (int k = 0; k < kMaxConstraints; ++k) {
    if (!pr.used(k)) continue;
    cons.push_back({&pr, k});
    opt.add_inequality_constraint(
        [](const std::vector<double>& x, std::vector<double>&, void* d) {
          const Con* c = static_cast<const Con*>(d);
          const double g = c->pr->at(x[0], x[1]).g[c->k];
          return std::isfinite(g) ? g : 1.0;
        },
        &cons.back(), 0.0);
  }
  opt.set_xtol_abs(1e-11);
  opt.set_initial_step(step);
  opt.set_maxeval(maxeval);
  std::vector<double> x = {std::clamp(u0, -kBox, kBox), std::clamp(v0, -kBox, kBox)};
  double f = 0;
  try {
    opt.optimize(x, f);
  } catch (const std::exception&) {
    // a roundoff-limited stop: the problem keeps the best admissible point it evaluated
  }
  return pr.has_best() ? pr.best().energy : kRefineInf;
}

void nelder_mead(Problem& pr, double u0, double v0, double step, int maxeval = 2000) {
  nlopt::opt opt(nlopt::LN_NELDERMEAD, 2);
  opt.set_lower_bounds({-kBox, -kBox});
  opt.set_upper_bounds({kBox, kBox});
  opt.set_min_objective(
      [](const std::vector<double>& x, std::vector<double>&, void* d) {
        Problem* p = static_cast<Problem*>(d);
        const Problem::Eval& e = p->at(x[0], x[1]);
        return e.feasible ? e.energy : p->penalty();  // only admissible points compete
      },
      &pr);
  opt.set_xtol_abs(1e-12);
  opt.set_initial_step(step);
  opt.set_maxeval(maxeval);
  std::vector<double> x = {u0, v0};
  double f = 0;
  try {
    opt.optimize(x, f);
  } catch (const std::exception&) {
  }
}

// bisection for g(dep) = 0 near `guess`; returns the end of the final bracket on the
// admissible side (g <= 0)
template <typename G>
std::optional<double> solve_on_boundary(const G& g, double guess) {
  double s = 1e-4;
  double lo = guess - s, hi = guess + s, glo = g(lo), ghi = g(hi);
  for (int i = 0; i < 40 && !((glo <= 0) != (ghi <= 0)); ++i) {
    s *= 2;
    if (s > 2 * kBox) return std::nullopt;
    lo = guess - s;
    hi = guess + s;
    glo = g(lo);
    ghi = g(hi);
  }
  if ((glo <= 0) == (ghi <= 0)) return std::nullopt;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(lo)); ++i) {
    const double mid = 0.5 * (lo + hi), gm = g(mid);
    if ((gm <= 0) == (glo <= 0)) {
      lo = mid;
      glo = gm;
    } else {
      hi = mid;
      ghi = gm;
    }
  }
  return glo <= 0 ? lo : hi;
}

// the boundary g_k = 0 through the best point, parameterised by the scaled variable along
// which g_k changes least (free); the other (dep) solved by bisection on its admissible side
class OnBoundary {
 public:
  OnBoundary(Problem& pr, int k) : pr_(pr), k_(k) {
    if (!pr.has_best()) return;
    const double ub = pr.best().u, vb = pr.best().v;
    const double d = 1e-6;
    const double gu = (g(ub + d, vb) - g(ub - d, vb)) / (2 * d);
    const double gv = (g(ub, vb + d) - g(ub, vb - d)) / (2 * d);
    if (!std::isfinite(gu) || !std::isfinite(gv) || (gu == 0 && gv == 0)) return;
    ok_ = true;
    dep_is_u_ = std::abs(gu) >= std::abs(gv);
    free0_ = dep_is_u_ ? vb : ub;
    dep0_ = dep_guess_ = dep_is_u_ ? ub : vb;
  }
  bool ok() const { return ok_; }
  double free0() const { return free0_; }
  void restart() { dep_guess_ = dep0_; }
  double g(double u, double v) const {
    return k_ < 2 ? pr_.geometric(k_, u, v) : pr_.limit(k_, u, v);
  }
  // the boundary point (u, v) at free value f
  std::optional<Eigen::Vector2d> point(double f) {
    const auto dep =
        solve_on_boundary([&](double x) { return dep_is_u_ ? g(x, f) : g(f, x); }, dep_guess_);
    if (!dep) return std::nullopt;
    dep_guess_ = *dep;
    return dep_is_u_ ? Eigen::Vector2d(*dep, f) : Eigen::Vector2d(f, *dep);
  }
  // the energy on the boundary at free value f (admissible points only)
  double energy(double f) {
    const auto p = point(f);
    if (!p) return kRefineInf;
    const Problem::Eval& e = pr_.at(p->x(), p->y());
    return e.feasible ? e.energy : kRefineInf;
  }

 private:
  Problem& pr_;
  int k_;
  bool ok_ = false, dep_is_u_ = false;
  double free0_ = 0, dep0_ = 0, dep_guess_ = 0;
};

// golden-section search along the boundary g_k = 0 through the best point: a scan of
// `half_width` (scaled) either side, then golden section to `tol` around its best point
void along_boundary(Problem& pr, int k, double half_width = 1.0, double tol = 1e-13) {
  OnBoundary ob(pr, k);
  if (!ob.ok()) return;
  const double free0 = ob.free0();
  const auto h = [&](double f) { return ob.energy(f); };
  constexpr int kScan = 20;
  const double step = 2.0 * half_width / kScan;
  double best_f = free0, best_h = h(free0);
  for (int side : {-1, 1}) {
    ob.restart();
    for (int i = 1; i <= kScan / 2; ++i) {
      const double f = free0 + side * i * step;
      const double v = h(f);
      if (v < best_h) {
        best_h = v;
        best_f = f;
      }
    }
  }
  if (!std::isfinite(best_h)) return;
  double a = best_f - step, b = best_f + step;
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - r * (b - a), e = a + r * (b - a);
  double hc = h(c), he = h(e);
  for (int i = 0; i < 200 && b - a > tol; ++i) {
    if (hc <= he) {
      b = e;
      e = c;
      he = hc;
      c = b - r * (b - a);
      hc = h(c);
    } else {
      a = c;
      c = e;
      hc = he;
      e = a + r * (b - a);
      he = h(e);
    }
  }
}

// Newton steps on a quadratic fitted by central differences on a 3 x 3 stencil of spacing d
// around the best point, d shrinking; only when the whole stencil is admissible (an
// interior point). Returns the relative energy decrease the last fitted model still
// predicts (0 when no model could be fitted: not interior, or not convex).
double quadratic_polish(Problem& pr) {
  double predicted = 0;
  for (const double d : {0.1, 0.03, 0.01, 0.003}) {
    for (int it = 0; it < 3; ++it) {
      const Problem::Eval b = pr.best();
      double f[3][3];
      bool ok = true;
      for (int i = -1; i <= 1 && ok; ++i)
        for (int j = -1; j <= 1 && ok; ++j) {
          const Problem::Eval& e = pr.at(b.u + i * d, b.v + j * d);
          ok = e.feasible;
          f[i + 1][j + 1] = e.energy;
        }
      if (!ok || !pr.has_best()) return predicted;
      const double f0 = f[1][1];
      const double gu = (f[2][1] - f[0][1]) / (2 * d), gv = (f[1][2] - f[1][0]) / (2 * d);
      const double huu = (f[2][1] - 2 * f0 + f[0][1]) / (d * d);
      const double hvv = (f[1][2] - 2 * f0 + f[1][0]) / (d * d);
      const double huv = (f[2][2] - f[2][0] - f[0][2] + f[0][0]) / (4 * d * d);
      const double det = huu * hvv - huv * huv;
      if (!(huu > 0) || !(det > 0)) return predicted;
      const double su = -(hvv * gu - huv * gv) / det, sv = -(huu * gv - huv * gu) / det;
      predicted = 0.5 * -(gu * su + gv * sv) / f0;
      const double len = std::hypot(su, sv);
      const double scale = len > 2 * d ? 2 * d / len : 1.0;
      pr.at(b.u + scale * su, b.v + scale * sv);
      if (len < 1e-3 * d) break;
    }
  }
  return std::max(0.0, predicted);
}

// The error of the best point's location, scaled units: the distance to the minimum of
// the quadratic fitted by central differences at spacing d (the Newton step), plus the
// step's change from spacing d to 2 d (truncation), plus the objective's error e moved
// through the fit (a gradient error e / d times the inverse curvature). Interior: a
// 3 x 3 stencil in (u, v); on a boundary g_k = 0: 5 points along it; at a corner of the
// admissible set (no admissible neighbour along the boundary) the constraints fix the point
// to the bisection's precision.
struct Located {
  double u = kRefineNaN, v = kRefineNaN;
  double step_u = 0, step_v = 0;  // interior: the extrapolated Newton step
};

// the Newton step and the error of the inverse curvature times a gradient error `dg` from a
// 2-D quadratic at spacing d; false when a point is not admissible or the fit not convex
bool newton2(Problem& pr, double u0, double v0, double d, double dg, Eigen::Vector2d& step,
             Eigen::Vector2d& noise) {
  double f[3][3];
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j) {
      const Problem::Eval& e = pr.at(u0 + i * d, v0 + j * d);
      if (!e.feasible) return false;
      f[i + 1][j + 1] = e.energy;
    }
  const Eigen::Vector2d g((f[2][1] - f[0][1]) / (2 * d), (f[1][2] - f[1][0]) / (2 * d));
  Eigen::Matrix2d H;
  H(0, 0) = (f[2][1] - 2 * f[1][1] + f[0][1]) / (d * d);
  H(1, 1) = (f[1][2] - 2 * f[1][1] + f[1][0]) / (d * d);
  H(0, 1) = H(1, 0) = (f[2][2] - f[2][0] - f[0][2] + f[0][0]) / (4 * d * d);
  if (!(H(0, 0) > 0) || !(H.determinant() > 0)) return false;
  const Eigen::Matrix2d Hi = H.inverse();
  step = -Hi * g;
  noise = Hi.cwiseAbs() * Eigen::Vector2d(dg, dg);
  return true;
}

Located located_interior(Problem& pr, double d) {
  Located out;
  const Problem::Eval b = pr.best();
  const double dg = pr.noise(b.u, b.v) / d;
  Eigen::Vector2d s1, s2, n1, n2;
  if (!newton2(pr, b.u, b.v, d, dg, s1, n1) || !newton2(pr, b.u, b.v, 2 * d, dg / 2, s2, n2))
    return out;
  // the step extrapolated to d -> 0 (its truncation ~ d^2), and that truncation
  const Eigen::Vector2d s0 = (4 * s1 - s2) / 3;
  const Eigen::Vector2d err = s0.cwiseAbs() + (s1 - s0).cwiseAbs() + n1;
  out.u = err.x();
  out.v = err.y();
  out.step_u = s0.x();
  out.step_v = s0.y();
  return out;
}

Located located_on_boundary(Problem& pr, int k, double d) {
  Located out;
  const Problem::Eval b = pr.best();
  OnBoundary ob(pr, k);
  if (!ob.ok()) return out;
  const double f0 = ob.free0();
  const auto p0 = ob.point(f0);
  double h[5];
  Eigen::Vector2d pts[5];
  bool corner = !p0;
  for (int i = -2; i <= 2 && !corner; ++i) {
    ob.restart();
    const auto p = ob.point(f0 + i * d);
    if (!p) {
      corner = true;
      break;
    }
    pts[i + 2] = *p;
    const Problem::Eval& e = pr.at(p->x(), p->y());
    corner = !e.feasible;
    h[i + 2] = e.energy;
  }
  if (corner) {
    // both coordinates fixed by constraints: their bisection (1e-15 relative) is the error
    out.u = out.v = 1e-12;
    return out;
  }
  const double dg = pr.noise(b.u, b.v) / d;
  const double g1 = (h[3] - h[1]) / (2 * d), c1 = (h[3] - 2 * h[2] + h[1]) / (d * d);
  const double g2 = (h[4] - h[0]) / (4 * d), c2 = (h[4] - 2 * h[2] + h[0]) / (4 * d * d);
  if (!(c1 > 0) || !(c2 > 0)) return out;
  const double s1 = -g1 / c1, s2 = -g2 / c2, s0 = (4 * s1 - s2) / 3;
  // the distance of the best point from the boundary point at f0 (its bisection) counts too
  const double along = std::abs(s0) + std::abs(s1 - s0) + dg / c1;
  // the Newton step along the boundary (the caller locates again when it gains)
  ob.restart();
  ob.energy(f0 + s0);
  const Eigen::Vector2d tangent = (pts[3] - pts[1]) / (2 * d);
  out.u = std::abs(tangent.x()) * along + std::abs(pts[2].x() - b.u);
  out.v = std::abs(tangent.y()) * along + std::abs(pts[2].y() - b.v);
  return out;
}

// the most nearly active constraint at the best point (-1: none within half a grid spacing)
int nearest_constraint(const Problem& pr, double hx) {
  int k_best = -1;
  double best = -kRefineInf;
  for (int k = 0; k < kMaxConstraints; ++k) {
    if (!pr.used(k)) continue;
    const double scale = k < 2 ? hx : 1.0;
    const double g = pr.best().g[k] / scale;
    if (g > -0.5 && g > best) {
      best = g;
      k_best = k;
    }
  }
  return k_best;
}

// J, the energy's error from the limits' resolution: at each nearly active limit k (slack
// below 1e-6) its multiplier, |grad E| / |grad g_k| by central differences (KKT with one
// active constraint), times the resolution of the continuous peak (peaks.hpp); the
// probes do not move the best point
double limit_energy_error(Problem& pr) {
  if (!pr.quadrature() || !pr.limits() || !pr.has_best()) return 0;
  const Problem::Eval b = pr.best();
  const MotionPeaks p = pr.peaks(thesis_line(pr.x_s(b.u), pr.phi(b.v)));
  constexpr double d = 1e-4;
  double out = 0;
  for (int k = 2; k < kMaxConstraints; ++k) {
    if (!pr.used(k) || b.g[k] < -1e-6) continue;
    const Problem::Eval up = pr.at(b.u + d, b.v, false), um = pr.at(b.u - d, b.v, false);
    const Problem::Eval vp = pr.at(b.u, b.v + d, false), vm = pr.at(b.u, b.v - d, false);
    const double eu = (up.energy - um.energy) / (2 * d), ev = (vp.energy - vm.energy) / (2 * d);
    const double gu = (up.g[k] - um.g[k]) / (2 * d), gv = (vp.g[k] - vm.g[k]) / (2 * d);
    const double lambda = std::hypot(eu, ev) / std::hypot(gu, gv);
    if (std::isfinite(lambda)) out += lambda * p.resolution;
  }
  return out;
}

}  // namespace

void with_continuous_peaks(const Spec& spec, const Arm2& arm, const ProgramTable& table,
                           int configuration, Candidate& c) {
  if ((!spec.torque_limit && !spec.power_limit) || !c.metrics.finite() ||
      c.status == CandidateStatus::kUnreachable)
    return;
  const MotionPeaks p = continuous_peaks(arm, table.program, spec.duration, spec.length,
                                         thesis_line(c.x_s, c.phi), configuration, table.size());
  if (!p.finite) return;
  for (int j = 0; j < 2; ++j) {
    c.metrics.peak_torque[j] = std::max(c.metrics.peak_torque[j], p.torque[j]);
    c.metrics.peak_power[j] = std::max(c.metrics.peak_power[j], p.power[j]);
  }
  c.status = classify(spec, c.boundary_distance, c.metrics);
}

const char* binding_name(Binding b) {
  switch (b) {
    case Binding::kInterior: return "interior";
    case Binding::kInnerClearance: return "inner_clearance";
    case Binding::kOuterClearance: return "outer_clearance";
    case Binding::kTorqueLimit: return "torque_limit";
    case Binding::kPowerLimit: return "power_limit";
  }
  return "?";
}

Decision decide(const Spec& spec, const Candidate& c, double active_m, double active_rel) {
  Decision d;
  d.inner_slack = c.inner_clearance - spec.singularity_margin;
  d.outer_slack = c.outer_clearance - spec.singularity_margin;
  // every constraint within tolerance, in a fixed order: the first names the binding one
  const auto consider = [&](double slack, double tolerance, Binding b, int joint) {
    if (slack / tolerance <= 1.0) d.active.push_back({b, joint, slack});
  };
  consider(d.inner_slack, active_m, Binding::kInnerClearance, -1);
  consider(d.outer_slack, active_m, Binding::kOuterClearance, -1);
  for (int j = 0; j < 2; ++j) {
    if (spec.torque_limit) {
      const double lim = (*spec.torque_limit)[j];
      d.torque_slack[j] = lim - c.metrics.peak_torque[j];
      consider(d.torque_slack[j], active_rel * lim, Binding::kTorqueLimit, j);
    }
    if (spec.power_limit) {
      const double lim = (*spec.power_limit)[j];
      d.power_slack[j] = lim - c.metrics.peak_power[j];
      consider(d.power_slack[j], active_rel * lim, Binding::kPowerLimit, j);
    }
  }
  if (!d.active.empty()) {
    d.binding = d.active.front().kind;
    d.joint = d.active.front().joint;
  }
  return d;
}

namespace {

// the refinement's method, in words, for the report
std::string refinement_method(const Spec& spec, bool boundary_searched, double target_rel) {
  std::ostringstream target;
  target << target_rel;
  return std::string("NLopt COBYLA with the inner and outer clearances") +
         (spec.torque_limit ? ", the torque limits" : "") +
         (spec.power_limit ? ", the power limits" : "") +
         " as inequality constraints; Nelder-Mead and Newton steps on fitted quadratics "
         "inside the admissible set" +
         (boundary_searched ? "; golden section along the nearly active constraint" : "") +
         "; first on the sampled energy, then on the energy by adaptive quadrature "
         "(asked for 1e-11) from the point found" +
         (spec.torque_limit || spec.power_limit
              ? std::string(", with the limits on the continuous motion (peaks refined "
                            "between the samples)")
              : std::string()) +
         "; converged when a COBYLA restart gains, "
         "and a fitted quadratic predicts, < " +
         target.str() + " relative in the quadrature's energy";
}

}  // namespace

// (over 60 lines, kept whole: the rounds of the stages of refine.hpp on one Problem, in the
// order its header gives them)
Refinement refine_constrained(const Spec& spec, const Arm2& arm, const ProgramTable& table,
                              int configuration, const Candidate& start, double hx, double hphi,
                              double target_rel) {
  Refinement out;
  out.target_rel = target_rel;
  Problem pr(spec, arm, table, configuration, start.x_s, start.phi, hx, hphi);
  pr.at(0.0, 0.0);
  cobyla(pr, 0.0, 0.0, 0.5, 4000);
  bool boundary_searched = false;
  // the stages on the sampled energy (cheap), then again on the converged energy from the
  // point they found (the sampled energy's ripple leaves local minima ~5e-6 apart)
  for (const bool converged_objective : {false, true}) {
    if (converged_objective) {
      const Problem::Eval b = pr.best();
      pr.use_quadrature();
      pr.at(b.u, b.v);
      // a limit kept at the samples may be broken between them (~h^2 of the peak): COBYLA
      // from there to the continuous limit
      if (!pr.has_best()) cobyla(pr, b.u, b.v, 0.01, 400);
    }
    const int maxeval = converged_objective ? 100 : 2000;
    // the converged pass's rounds are short (100 evaluations): a start far from the converged
    // optimum (a coarse sweep) may need more of them to reach the target
    const int rounds = converged_objective ? 8 : 3;
    for (int round = 0; round < rounds && pr.has_best(); ++round) {
      out.rounds += 1;
      const Problem::Eval b = pr.best();
      // inside the admissible set, and along every nearly active constraint
      // (on the converged energy only at an interior point: along a constraint the boundary
      // search below does it)
      if (!converged_objective || nearest_constraint(pr, hx) < 0)
        nelder_mead(pr, b.u, b.v, converged_objective ? 0.02 : 0.05, maxeval);
      // the sampled |power| has kinks that leave shallow local minima a fraction of a grid
      // spacing apart (~1e-7 relative): restart from a ring of admissible points around the
      // best
      for (const double r : {0.03, 0.1}) {
        if (converged_objective) break;  // the converged energy is smooth
        const Problem::Eval c = pr.best();
        for (int k = 0; k < 8; ++k) {
          const double a = k * core::kPi / 4;
          const Problem::Eval& e = pr.at(c.u + r * std::cos(a), c.v + r * std::sin(a));
          if (e.feasible) nelder_mead(pr, e.u, e.v, 0.5 * r, 150);
        }
      }
      const double predicted = quadratic_polish(pr);
      for (int k = 0; k < kMaxConstraints; ++k) {
        if (!pr.used(k)) continue;
        const Problem::Eval& now = pr.best();
        const double scale = k < 2 ? hx : 1.0;
        if (now.g[k] > -0.5 * scale) {
          // from the sampled optimum the converged one is a small step away
          if (converged_objective)
            along_boundary(pr, k, 0.1, 1e-10);
          else
            along_boundary(pr, k);
          boundary_searched = true;
        }
      }
      // a COBYLA restart from the best point: what it still gains is the final tolerance
      const double before = pr.best().energy;
      cobyla(pr, pr.best().u, pr.best().v, 0.01, converged_objective ? 80 : 1500);
      const double after = pr.best().energy;
      // the final tolerance: what the restart gained, or what the last quadratic model of an
      // interior optimum still predicted, whichever is larger
      out.tolerance_rel = std::max(std::max(0.0, (before - after) / after), predicted);
      if (out.tolerance_rel <= target_rel) break;
    }
  }
  if (pr.has_best()) {
    // where the minimum of the converged energy lies, to within what
    constexpr double kStencil = 3e-4;
    // interior: Newton steps to the extrapolated minimum while they gain, the error of the
    // last point located; a stencil point lower than it moves the best, and that distance
    // counts too
    Located loc;
    Problem::Eval at = pr.best();
    for (int it = 0; it < 4; ++it) {
      at = pr.best();
      loc = located_interior(pr, kStencil);
      if (!std::isfinite(loc.u) || pr.best().u != at.u || pr.best().v != at.v) break;
      pr.at(at.u + loc.step_u, at.v + loc.step_v);
      if (pr.best().u == at.u && pr.best().v == at.v) break;
    }
    if (!std::isfinite(loc.u)) {
      // on a boundary: the same, along it
      const int k = nearest_constraint(pr, hx);
      for (int it = 0; it < 4 && k >= 0; ++it) {
        at = pr.best();
        loc = located_on_boundary(pr, k, kStencil);
        if (pr.best().u == at.u && pr.best().v == at.v) break;
      }
    }
    out.limit_energy_error = limit_energy_error(pr);
    out.x_s_error = (loc.u + std::abs(pr.best().u - at.u)) * hx;
    out.phi_error = (loc.v + std::abs(pr.best().v - at.v)) * hphi;
    out.objective_error = pr.best().error;
  }
  out.converged = pr.has_best() && out.tolerance_rel <= target_rel;
  out.method = refinement_method(spec, boundary_searched, target_rel);
  out.evaluations = pr.evaluations();
  out.quadratures = pr.quadrature_evaluations();
  if (pr.has_best()) {
    out.best = evaluate_candidate(spec, arm, table, configuration, pr.x_s(pr.best().u),
                                  pr.phi(pr.best().v));
  } else {
    out.best = start;
  }
  with_continuous_peaks(spec, arm, table, configuration, out.best);
  return out;
}

}  // namespace armstudy::studies::placement
