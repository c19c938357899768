// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/throwing/nlopt_solve.hpp"

#include <nlopt.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "studies/throwing/idp.hpp"
#include "studies/throwing/throw_gradient.hpp"

namespace armstudy::studies {
namespace {

struct Problem {
  const ThrowSetup* setup;
  VelocityProfile base;
  Eigen::Vector2d delta;
  NloptSettings settings;
  Objective objective;
  std::vector<double> cached_x;
  int ineq = 0;  // 6 per stage + 1 (release)
  // values: objective, then the inequality constraints (<= 0); grads row-major
  std::vector<double> values, grads;
  NloptOutcome* out;
  nlopt_opt opt = nullptr;
  VelocityProfile last;  // the last point SLSQP evaluated (not a difference neighbour)
};

int num_vars(const VelocityProfile& p) { return 2 * (p.stages() - 1); }

VelocityProfile to_profile(const Problem& pr, const double* x) {
  VelocityProfile p = pr.base;
  const int P = p.stages();
  for (int k = 1; k < P; ++k) {
    p.v(0, k) = x[2 * (k - 1)];
    p.v(1, k) = x[2 * (k - 1) + 1];
  }
  return p;
}

void quantities(const Problem& pr, const ProfileEvaluation& e, double* q) {
  const std::vector<double> g = constraint_values(*pr.setup, e, pr.settings.backoff);
  std::copy(g.begin(), g.end(), q + 1);
  if (pr.objective == Objective::kEnergy) {
    q[0] = e.energy;
  } else {
    // aim twice the back-off inside, so that the descent crosses into the feasible set
    q[0] = 0.0;
    for (double v : g) q[0] += std::pow(std::max(0.0, v + pr.settings.backoff), 2);
  }
}

// the point's values and exact gradients (throw_gradient.hpp): the energy objective only
void compute_exact(Problem& pr, const double* x) {
  const int n = num_vars(pr.base);
  const int m = 1 + pr.ineq;
  const VelocityProfile p = to_profile(pr, x);
  const ThrowDerivatives d = throw_derivatives(*pr.setup, p, pr.settings.backoff);
  pr.out->simulations += 1;
  pr.values.assign(m, 0.0);
  pr.grads.assign(size_t(m) * n, 0.0);
  quantities(pr, d.evaluation, pr.values.data());
  for (int i = 0; i < n; ++i) pr.grads[i] = d.energy_gradient[i];
  for (int j = 1; j < m; ++j)
    for (int i = 0; i < n; ++i) pr.grads[size_t(j) * n + i] = d.constraint_jacobian(j - 1, i);
  pr.out->history.push_back(pr.values[0]);
  pr.out->violation_history.push_back(d.evaluation.violation);
  pr.last = p;
}

void compute(Problem& pr, const double* x) {
  const int n = num_vars(pr.base);
  if (!pr.cached_x.empty() && std::equal(pr.cached_x.begin(), pr.cached_x.end(), x)) return;
  pr.cached_x.assign(x, x + n);
  const int m = 1 + pr.ineq;
  if (!std::all_of(x, x + n, [](double v) { return std::isfinite(v); })) {
    // SLSQP stepped to a non-finite point (it can on an infeasible problem): no simulation,
    // a huge objective and violation, no gradient
    pr.values.assign(m, 1e3);
    pr.grads.assign(m * n, 0.0);
    pr.out->history.push_back(pr.values[0]);
    pr.out->violation_history.push_back(INFINITY);
    return;
  }
  if (pr.settings.exact_gradient && pr.objective == Objective::kEnergy &&
      derivatives_apply(*pr.setup))
    return compute_exact(pr, x);
  // the point and the 2n central-difference neighbours, simulated in parallel; x[i] is a rate
  // of node i / 2 + 1, so its neighbours resume from the point's simulation at stage i / 2
  std::vector<VelocityProfile> ps;
  ps.reserve(2 * n + 1);
  ps.push_back(to_profile(pr, x));
  std::vector<double> xx(x, x + n);
  const double h = pr.settings.fd_step;
  std::vector<int> first_stage(2 * n + 1, 0);
  for (int i = 0; i < n; ++i) {
    xx[i] = x[i] + h;
    ps.push_back(to_profile(pr, xx.data()));
    xx[i] = x[i] - h;
    ps.push_back(to_profile(pr, xx.data()));
    xx[i] = x[i];
    first_stage[1 + 2 * i] = first_stage[2 + 2 * i] = i / 2;
  }
  const auto evs =
      evaluate_neighbours(*pr.setup, ps, first_stage, pr.settings.threads, pr.settings.backoff);
  pr.out->simulations += static_cast<long>(evs.size());
  pr.values.assign(m, 0.0);
  pr.grads.assign(m * n, 0.0);
  quantities(pr, evs[0], pr.values.data());
  std::vector<double> qp(m), qm(m);
  for (int i = 0; i < n; ++i) {
    quantities(pr, evs[1 + 2 * i], qp.data());
    quantities(pr, evs[2 + 2 * i], qm.data());
    for (int j = 0; j < m; ++j) pr.grads[j * n + i] = (qp[j] - qm[j]) / (2 * h);
  }
  pr.out->history.push_back(pr.values[0]);
  pr.out->violation_history.push_back(evs[0].violation);
  pr.last = ps[0];
}

double objective(unsigned n, const double* x, double* grad, void* data) {
  Problem& pr = *static_cast<Problem*>(data);
  compute(pr, x);
  if (grad) std::copy(pr.grads.begin(), pr.grads.begin() + n, grad);
  return pr.values[0];
}

void inequalities(unsigned m, double* result, unsigned n, const double* x, double* grad,
                  void* data) {
  Problem& pr = *static_cast<Problem*>(data);
  compute(pr, x);
  for (unsigned j = 0; j < m; ++j) {
    result[j] = pr.values[1 + j];
    if (grad)
      std::copy(pr.grads.begin() + (1 + j) * n, pr.grads.begin() + (2 + j) * n, grad + j * n);
  }
}

// displacement of joints 1, 2 (trapezoid rule over the nodes) minus the wanted one
void equalities(unsigned m, double* result, unsigned n, const double* x, double* grad, void* data) {
  Problem& pr = *static_cast<Problem*>(data);
  const VelocityProfile p = to_profile(pr, x);
  const Eigen::Vector2d d = displacement(p) - pr.delta;
  result[0] = d[0];
  result[1] = d[1];
  if (grad) {
    std::fill(grad, grad + m * n, 0.0);
    const double h = p.stage_length();
    for (unsigned i = 0; i < n; ++i) grad[(i % 2) * n + i] = h;  // interior nodes weigh h
  }
}

std::string code_name(nlopt_result r) {
  switch (r) {
    case NLOPT_SUCCESS: return "SUCCESS";
    case NLOPT_STOPVAL_REACHED: return "STOPVAL_REACHED";
    case NLOPT_FTOL_REACHED: return "FTOL_REACHED";
    case NLOPT_XTOL_REACHED: return "XTOL_REACHED";
    case NLOPT_MAXEVAL_REACHED: return "MAXEVAL_REACHED";
    case NLOPT_MAXTIME_REACHED: return "MAXTIME_REACHED";
    case NLOPT_FAILURE: return "FAILURE";
    case NLOPT_INVALID_ARGS: return "INVALID_ARGS";
    case NLOPT_OUT_OF_MEMORY: return "OUT_OF_MEMORY";
    case NLOPT_ROUNDOFF_LIMITED: return "ROUNDOFF_LIMITED";
    case NLOPT_FORCED_STOP: return "FORCED_STOP";
    default: return "UNKNOWN";
  }
}

// Multipliers for grad f + sum_j w_j a_j = 0 (rows of A: the equalities first, free sign,
// then the active inequalities, w >= 0), least squares; an inequality whose multiplier comes
// out negative leaves the set (the most negative first) and the rest is solved again. The
// residual never overstates convergence: every multiplier set tried is admissible.
struct KktFit {
  double residual = INFINITY;  // |grad f + A^T w|
  std::vector<int> kept;       // indices (into A's inequality rows) with w > 0
};

KktFit kkt_fit(const Eigen::VectorXd& gf, const Eigen::MatrixXd& eq,
               const std::vector<Eigen::VectorXd>& ineq) {
  std::vector<int> set(ineq.size());
  for (size_t i = 0; i < ineq.size(); ++i) set[i] = static_cast<int>(i);
  while (true) {
    const int ne = static_cast<int>(eq.rows()), m = ne + static_cast<int>(set.size());
    Eigen::MatrixXd A(gf.size(), m);
    for (int j = 0; j < ne; ++j) A.col(j) = eq.row(j).transpose();
    for (size_t i = 0; i < set.size(); ++i) A.col(ne + static_cast<int>(i)) = ineq[set[i]];
    const Eigen::VectorXd w = A.completeOrthogonalDecomposition().solve(-gf);
    int worst = -1;
    for (size_t i = 0; i < set.size(); ++i)
      if (w[ne + static_cast<int>(i)] < 0 &&
          (worst < 0 || w[ne + static_cast<int>(i)] < w[ne + worst]))
        worst = static_cast<int>(i);
    if (worst < 0) {
      KktFit k;
      k.residual = (gf + A * w).norm();
      for (size_t i = 0; i < set.size(); ++i)
        if (w[ne + static_cast<int>(i)] > 0) k.kept.push_back(set[i]);
      return k;
    }
    set.erase(set.begin() + worst);
  }
}

// the first-order measure at x (pr's values and gradients computed there)
void measure_kkt(Problem& pr, const std::vector<double>& x, NloptOutcome& out) {
  const int n = static_cast<int>(x.size());
  compute(pr, x.data());
  Eigen::VectorXd gf(n);
  const double f = pr.values[0];
  for (int i = 0; i < n; ++i) gf[i] = pr.grads[i];
  // the displacement equalities: node i's rate of joint i % 2 weighs the stage length
  Eigen::MatrixXd eq = Eigen::MatrixXd::Zero(2, n);
  for (int i = 0; i < n; ++i) eq(i % 2, i) = pr.base.stage_length();
  std::vector<Eigen::VectorXd> ineq;
  std::vector<int> index;
  if (pr.objective != Objective::kViolation)
    for (int j = 0; j < pr.ineq; ++j)
      if (pr.values[1 + j] >= -kActiveBand) {  // values hold the back-off: 0 is the target
        ineq.emplace_back(Eigen::Map<const Eigen::VectorXd>(pr.grads.data() + (1 + j) * n, n));
        index.push_back(j);
      }
  const KktFit k = kkt_fit(gf, eq, ineq);
  out.active_constraints = static_cast<int>(ineq.size());
  out.kkt_residual = f != 0 ? k.residual / std::abs(f) : k.residual;
  out.binding.clear();
  const int P = pr.base.stages();
  for (int i : k.kept) {
    const int kind = index[i] >= 6 * P ? 6 : index[i] / P;
    const std::string name = constraint_name(static_cast<ConstraintKind>(kind));
    if (std::find(out.binding.begin(), out.binding.end(), name) == out.binding.end())
      out.binding.push_back(name);
  }
}

// one NLopt SLSQP run from x (updated to NLopt's returned point) with `budget` evaluations
nlopt_result slsqp_once(Problem& pr, std::vector<double>& x, int budget) {
  const int n = static_cast<int>(x.size());
  nlopt_opt opt = nlopt_create(NLOPT_LD_SLSQP, n);
  pr.opt = opt;
  nlopt_set_min_objective(opt, objective, &pr);
  const std::vector<double> tol_ineq(pr.ineq, 1e-8), tol_eq(2, 1e-10);
  if (pr.objective != Objective::kViolation)
    nlopt_add_inequality_mconstraint(opt, pr.ineq, inequalities, &pr, tol_ineq.data());
  nlopt_add_equality_mconstraint(opt, 2, equalities, &pr, tol_eq.data());
  nlopt_set_maxeval(opt, budget);
  nlopt_set_maxtime(opt, pr.settings.max_time);
  nlopt_set_ftol_rel(opt, pr.settings.ftol_rel);
  nlopt_set_xtol_rel(opt, pr.settings.xtol_rel);
  if (pr.objective == Objective::kViolation) nlopt_set_stopval(opt, 0.0);
  double f = 0;
  const nlopt_result r = nlopt_optimize(opt, x.data(), &f);
  nlopt_destroy(opt);
  pr.opt = nullptr;
  return r;
}

std::vector<double> node_rates(const VelocityProfile& p) {
  std::vector<double> x(num_vars(p));
  for (int k = 1; k < p.stages(); ++k) {
    x[2 * (k - 1)] = p.v(0, k);
    x[2 * (k - 1) + 1] = p.v(1, k);
  }
  return x;
}

}  // namespace

Optimality first_order_optimality(const ThrowSetup& setup, const VelocityProfile& profile,
                                  const Eigen::Vector2d& delta, const NloptSettings& settings) {
  NloptOutcome out;
  Problem pr{
      &setup, profile, delta,   settings, Objective::kEnergy, {}, 6 * profile.stages() + 1, {},
      {},     &out,    nullptr, {}};
  measure_kkt(pr, node_rates(profile), out);
  return {out.kkt_residual, out.active_constraints, out.binding};
}

NloptOutcome run_nlopt(const ThrowSetup& setup, const VelocityProfile& initial,
                       const Eigen::Vector2d& delta, const NloptSettings& settings,
                       Objective objective_kind) {
  const auto t0 = std::chrono::steady_clock::now();
  NloptOutcome out;
  Problem pr{&setup, initial, delta,   settings, objective_kind, {}, 6 * initial.stages() + 1, {},
             {},     &out,    nullptr, {}};
  const bool repair = objective_kind == Objective::kViolation;
  std::vector<double> x = node_rates(initial);
  nlopt_result r = NLOPT_FAILURE;
  // SLSQP, restarted from its last iterate while the first-order measure is not met
  // a point is converged when its first-order residual is within the tolerance and a fresh
  // SLSQP run from it (a new quasi-Newton model) changes the energy by less than
  // restart_gain: the constraints are maxima over samples, so the residual alone has a floor
  // of a few 1e-3 where samples tie, and an early stop can sit below kkt_tolerance
  double previous = NAN;
  int last_round = settings.restarts;
  for (int round = 0;; ++round) {
    const int used = static_cast<int>(out.history.size());
    const int budget = settings.max_evaluations - used;
    if (budget <= 0) break;
    r = slsqp_once(pr, x, budget);
    if (r < 0 && pr.last.v.size() == 0) break;  // NLopt failed before any evaluation
    // the answer is SLSQP's last iterate (NLopt's returned x is the best point that met the
    // constraints to 1e-8, often the start: SQP iterates approach the boundary from
    // outside); for the repair (no inequality constraints) the returned x
    if (!repair && pr.last.v.size() != 0) x = node_rates(pr.last);
    if (repair) break;
    measure_kkt(pr, x, out);
    out.restarts = round;
    const double energy = pr.values[0];
    out.restart_gain = std::abs(previous - energy) / std::max(std::abs(energy), 1e-12);
    previous = energy;
    if (out.kkt_residual <= settings.kkt_tolerance && out.restart_gain <= settings.restart_gain)
      break;
    // out of restarts, or no progress possible
    if (round < last_round && static_cast<int>(out.history.size()) != used) continue;
    if (!pr.settings.exact_gradient || !derivatives_apply(setup)) break;
    // exact derivatives see one side of a kink where a stage's samples tie (the first-order
    // test's multiplier fit too): a run they leave short of the test is finished by central
    // differences, which straddle it, with restarts of their own
    pr.settings.exact_gradient = false;
    pr.cached_x.clear();
    out.central_polish = true;
    last_round = round + 1 + settings.restarts;
  }
  out.return_code = code_name(r);
  out.best = to_profile(pr, x.data());
  out.evaluation = simulate_profile(setup, out.best, nullptr, settings.backoff);
  out.objective = repair ? out.evaluation.violation : out.evaluation.energy;
  out.rate_change = (out.best.v - initial.v).cwiseAbs().maxCoeff();
  double worst = -INFINITY;
  for (double g : constraint_values(setup, out.evaluation, 0.0)) worst = std::max(worst, g);
  out.feasible =
      out.evaluation.finite && worst <= 0.0 && (displacement(out.best) - delta).norm() <= 1e-8;
  out.iterations = static_cast<int>(out.history.size());
  const size_t H = out.history.size();
  if (H >= 2)
    out.last_gain =
        (out.history[H - 2] - out.history[H - 1]) / std::max(std::abs(out.history[H - 1]), 1e-12);
  out.converged = out.feasible && (repair ? r == NLOPT_STOPVAL_REACHED
                                          : out.kkt_residual <= settings.kkt_tolerance &&
                                                out.restart_gain <= settings.restart_gain);
  out.run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace armstudy::studies
