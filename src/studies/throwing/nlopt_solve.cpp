#include "studies/throwing/nlopt_solve.hpp"

#include <nlopt.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "studies/throwing/idp.hpp"

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
  bool found = false;    // kViolation: a feasible point was met
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

void compute(Problem& pr, const double* x) {
  const int n = num_vars(pr.base);
  if (!pr.cached_x.empty() && std::equal(pr.cached_x.begin(), pr.cached_x.end(), x)) return;
  pr.cached_x.assign(x, x + n);
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
  const int m = 1 + pr.ineq;
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

}  // namespace

NloptOutcome run_nlopt(const ThrowSetup& setup, const VelocityProfile& initial,
                       const Eigen::Vector2d& delta, const NloptSettings& settings,
                       Objective objective_kind) {
  const auto t0 = std::chrono::steady_clock::now();
  NloptOutcome out;
  Problem pr{&setup, initial, delta, settings, objective_kind, {}, 6 * initial.stages() + 1,
             {},     {},      &out,  nullptr,  false,          {}};
  const bool repair = objective_kind == Objective::kViolation;
  const int n = num_vars(initial);
  std::vector<double> x(n);
  for (int k = 1; k < initial.stages(); ++k) {
    x[2 * (k - 1)] = initial.v(0, k);
    x[2 * (k - 1) + 1] = initial.v(1, k);
  }
  nlopt_opt opt = nlopt_create(NLOPT_LD_SLSQP, n);
  pr.opt = opt;
  nlopt_set_min_objective(opt, objective, &pr);
  const std::vector<double> tol_ineq(pr.ineq, 1e-8), tol_eq(2, 1e-10);
  if (!repair) nlopt_add_inequality_mconstraint(opt, pr.ineq, inequalities, &pr, tol_ineq.data());
  nlopt_add_equality_mconstraint(opt, 2, equalities, &pr, tol_eq.data());
  nlopt_set_maxeval(opt, settings.max_evaluations);
  nlopt_set_maxtime(opt, settings.max_time);
  nlopt_set_ftol_rel(opt, settings.ftol_rel);
  nlopt_set_xtol_rel(opt, settings.xtol_rel);
  if (repair) nlopt_set_stopval(opt, 0.0);  // every constraint 2 backoff inside
  double f = 0;
  const nlopt_result r = nlopt_optimize(opt, x.data(), &f);
  nlopt_destroy(opt);
  out.return_code = code_name(r);
  // the answer is SLSQP's last iterate (NLopt's returned x is the best point that met the
  // constraints to 1e-8, often the start: SQP iterates approach the boundary from outside);
  // for the repair (no inequality constraints) the returned x, the least violation
  out.best = (repair || pr.last.v.size() == 0) ? to_profile(pr, x.data()) : pr.last;
  out.evaluation = simulate_profile(setup, out.best, nullptr, settings.backoff);
  out.objective = repair ? out.evaluation.violation : out.evaluation.energy;
  out.rate_change = (out.best.v - initial.v).cwiseAbs().maxCoeff();
  double worst = -INFINITY;
  for (double g : constraint_values(setup, out.evaluation, settings.backoff))
    worst = std::max(worst, g);
  // an SQP iterate meets its constraints only to its own tolerance: it must be at least
  // 3/4 of the back-off inside every limit (the finer check samples between its steps)
  out.feasible = out.evaluation.finite && worst <= (repair ? 0.0 : 0.25 * settings.backoff) &&
                 (displacement(out.best) - delta).norm() <= 1e-8;
  out.iterations = static_cast<int>(out.history.size());
  const size_t H = out.history.size();
  if (H >= 2)
    out.last_gain =
        (out.history[H - 2] - out.history[H - 1]) / std::max(std::abs(out.history[H - 1]), 1e-12);
  out.converged =
      out.feasible &&
      (repair ? r == NLOPT_STOPVAL_REACHED
              : (r == NLOPT_FTOL_REACHED || r == NLOPT_XTOL_REACHED || r == NLOPT_SUCCESS));
  out.run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace armstudy::studies
