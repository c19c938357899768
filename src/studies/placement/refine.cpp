#include "studies/placement/refine.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include <nlopt.hpp>

#include "studies/placement/candidate.hpp"
#include "studies/placement/geometry.hpp"

namespace armstudy::studies::placement {
namespace {

constexpr double kRefineInf = std::numeric_limits<double>::infinity();
constexpr double kRefineNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kMaxConstraints = 6;  // inner, outer, torque 1, 2, power 1, 2

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
    double g[kMaxConstraints] = {};
    bool feasible = false;
  };

  double x_s(double u) const { return x0_ + u * hx_; }
  double phi(double v) const { return p0_ + v * hphi_; }
  bool used(int k) const { return used_[k]; }
  int evaluations() const { return evals_; }
  bool has_best() const { return best_.feasible; }
  const Eval& best() const { return best_; }

  // the geometric constraints alone (no motion evaluated)
  double geometric(int k, double u, double v) const {
    const LineCheck chk = check_line(arm_.L1, arm_.L2, thesis_line(x_s(u), phi(v)), spec_.length);
    return k == 0 ? (an_.inner + spec_.singularity_margin) - chk.r_min
                  : chk.r_max - (an_.outer - spec_.singularity_margin);
  }

  // energy and every constraint at (u, v); the last point is cached (COBYLA asks for the
  // objective and each constraint at the same point)
  const Eval& at(double u, double v) {
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
    if (chk.boundary_distance >= 0)
      m = evaluate_line(arm_, table_, line, configuration_);
    else
      m.energy = kRefineInf;
    for (int j = 0; j < 2; ++j) {
      e.g[2 + j] =
          spec_.torque_limit ? m.peak_torque[j] / (*spec_.torque_limit)[j] - 1.0 : -kRefineInf;
      e.g[4 + j] =
          spec_.power_limit ? m.peak_power[j] / (*spec_.power_limit)[j] - 1.0 : -kRefineInf;
    }
    e.energy = m.finite() ? m.energy : kRefineInf;
    e.feasible = std::isfinite(e.energy);
    for (int k = 0; k < kMaxConstraints; ++k) e.feasible = e.feasible && !(e.g[k] > 0);
    if (e.feasible && (!best_.feasible || e.energy < best_.energy)) best_ = e;
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
  int evals_ = 0;
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

// golden-section search along the boundary g_k = 0 through the best point
void along_boundary(Problem& pr, int k) {
  if (!pr.has_best()) return;
  const double ub = pr.best().u, vb = pr.best().v;
  const auto gk = [&](double u, double v) {
    return k < 2 ? pr.geometric(k, u, v) : pr.at(u, v).g[k];
  };
  const double d = 1e-6;
  const double gu = (gk(ub + d, vb) - gk(ub - d, vb)) / (2 * d);
  const double gv = (gk(ub, vb + d) - gk(ub, vb - d)) / (2 * d);
  if (!std::isfinite(gu) || !std::isfinite(gv) || (gu == 0 && gv == 0)) return;
  const bool dep_is_u = std::abs(gu) >= std::abs(gv);
  const double free0 = dep_is_u ? vb : ub, dep0 = dep_is_u ? ub : vb;
  double dep_guess = dep0;
  // energy on the boundary at free value f (admissible points only)
  const auto h = [&](double f) {
    const auto dep =
        solve_on_boundary([&](double x) { return dep_is_u ? gk(x, f) : gk(f, x); }, dep_guess);
    if (!dep) return kRefineInf;
    dep_guess = *dep;
    const Problem::Eval& e = dep_is_u ? pr.at(*dep, f) : pr.at(f, *dep);
    return e.feasible ? e.energy : kRefineInf;
  };
  // scan one grid spacing either side, then golden section around the best scan point
  constexpr int kScan = 20;
  double best_f = free0, best_h = h(free0);
  for (int side : {-1, 1}) {
    dep_guess = dep0;
    for (int i = 1; i <= kScan / 2; ++i) {
      const double f = free0 + side * i * (2.0 / kScan);
      const double v = h(f);
      if (v < best_h) {
        best_h = v;
        best_f = f;
      }
    }
  }
  if (!std::isfinite(best_h)) return;
  double a = best_f - 2.0 / kScan, b = best_f + 2.0 / kScan;
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - r * (b - a), e = a + r * (b - a);
  double hc = h(c), he = h(e);
  for (int i = 0; i < 200 && b - a > 1e-13; ++i) {
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

}  // namespace

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
  for (int round = 0; round < 3 && pr.has_best(); ++round) {
    out.rounds = round + 1;
    const Problem::Eval b = pr.best();
    // inside the admissible set, and along every nearly active constraint
    nelder_mead(pr, b.u, b.v, 0.05);
    // the sampled |power| has kinks that leave shallow local minima a fraction of a grid
    // spacing apart (~1e-7 relative): restart from a ring of admissible points around the best
    for (const double r : {0.03, 0.1}) {
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
        along_boundary(pr, k);
        boundary_searched = true;
      }
    }
    // a COBYLA restart from the best point: what it still gains is the final tolerance
    const double before = pr.best().energy;
    cobyla(pr, pr.best().u, pr.best().v, 0.01, 1500);
    const double after = pr.best().energy;
    // the final tolerance: what the restart gained, or what the last quadratic model of an
    // interior optimum still predicted, whichever is larger
    out.tolerance_rel = std::max(std::max(0.0, (before - after) / after), predicted);
    if (out.tolerance_rel <= target_rel) break;
  }
  out.converged = pr.has_best() && out.tolerance_rel <= target_rel;
  std::ostringstream target;
  target << target_rel;
  out.method = std::string("NLopt COBYLA with the inner and outer clearances") +
               (spec.torque_limit ? ", the torque limits" : "") +
               (spec.power_limit ? ", the power limits" : "") +
               " as inequality constraints; Nelder-Mead and Newton steps on fitted quadratics "
               "inside the admissible set" +
               (boundary_searched ? "; golden section along the nearly active constraint" : "") +
               "; converged when a COBYLA restart gains, and a fitted quadratic predicts, < " +
               target.str() + " relative in energy";
  out.evaluations = pr.evaluations();
  if (pr.has_best()) {
    out.best = evaluate_candidate(spec, arm, table, configuration, pr.x_s(pr.best().u),
                                  pr.phi(pr.best().v));
  } else {
    out.best = start;
  }
  return out;
}

}  // namespace armstudy::studies::placement
