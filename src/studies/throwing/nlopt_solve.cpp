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
  std::vector<double> cached_x;
  int ineq = 0;  // 3 per stage + 1 (release)
  // values: energy, then the inequality constraints (<= 0); grads row-major
  std::vector<double> values, grads;
  NloptOutcome* out;
  double best_feasible = std::numeric_limits<double>::infinity();
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
  const ThrowSetup& s = *pr.setup;
  const double tol = pr.settings.release_tolerance;
  const int P = pr.base.stages();
  q[0] = e.energy;
  // stage-wise maxima: smoother for SLSQP than one maximum over the whole motion
  for (int k = 0; k < P; ++k) {
    const double th4 = e.finite ? e.stage_theta4[k] : 1e3;
    const double v = e.finite ? e.stage_voltage[k] : 1e3;
    const double i = e.finite ? e.stage_current[k] : 1e3;
    q[1 + k] = (th4 - s.half_width) / s.half_width;
    q[1 + P + k] = (v - s.voltage_max) / s.voltage_max;
    q[1 + 2 * P + k] = (i - s.current_max) / s.current_max;
  }
  // |theta3(tf) - target| <= tol, scaled by tol
  q[1 + 3 * P] = (std::abs(e.theta3_final - s.theta3_release) - tol) / tol;
}

void compute(Problem& pr, const double* x) {
  const int n = num_vars(pr.base);
  if (!pr.cached_x.empty() && std::equal(pr.cached_x.begin(), pr.cached_x.end(), x)) return;
  pr.cached_x.assign(x, x + n);
  // the point and the 2n central-difference neighbours, simulated in parallel
  std::vector<VelocityProfile> ps;
  ps.reserve(2 * n + 1);
  ps.push_back(to_profile(pr, x));
  std::vector<double> xx(x, x + n);
  const double h = pr.settings.fd_step;
  for (int i = 0; i < n; ++i) {
    xx[i] = x[i] + h;
    ps.push_back(to_profile(pr, xx.data()));
    xx[i] = x[i] - h;
    ps.push_back(to_profile(pr, xx.data()));
    xx[i] = x[i];
  }
  const auto evs = evaluate_profiles(*pr.setup, ps, pr.settings.threads);
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
  pr.out->history.push_back(evs[0].energy);
  pr.out->last = ps[0];
  pr.out->last_evaluation = evs[0];
  // keep the best feasible point seen
  bool feasible = evs[0].finite;
  for (int j = 1; j < m; ++j) feasible &= pr.values[j] <= 1e-6;
  if (feasible && evs[0].energy < pr.best_feasible) {
    pr.best_feasible = evs[0].energy;
    pr.out->best = ps[0];
    pr.out->evaluation = evs[0];
    pr.out->feasible = true;
  }
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
    if (grad) std::copy(pr.grads.begin() + (1 + j) * n, pr.grads.begin() + (2 + j) * n, grad + j * n);
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
                       const Eigen::Vector2d& delta, const NloptSettings& settings) {
  const auto t0 = std::chrono::steady_clock::now();
  NloptOutcome out;
  out.best = initial;
  out.evaluation = simulate_profile(setup, initial);
  Problem pr{&setup, initial, delta, settings, {}, 3 * initial.stages() + 1, {}, {}, &out};
  const int n = num_vars(initial);
  std::vector<double> x(n);
  for (int k = 1; k < initial.stages(); ++k) {
    x[2 * (k - 1)] = initial.v(0, k);
    x[2 * (k - 1) + 1] = initial.v(1, k);
  }
  nlopt_opt opt = nlopt_create(NLOPT_LD_SLSQP, n);
  nlopt_set_min_objective(opt, objective, &pr);
  const std::vector<double> tol_ineq(pr.ineq, 1e-8), tol_eq(2, 1e-10);
  nlopt_add_inequality_mconstraint(opt, pr.ineq, inequalities, &pr, tol_ineq.data());
  nlopt_add_equality_mconstraint(opt, 2, equalities, &pr, tol_eq.data());
  nlopt_set_maxeval(opt, settings.max_evaluations);
  nlopt_set_maxtime(opt, settings.max_time);
  nlopt_set_ftol_rel(opt, settings.ftol_rel);
  double f = 0;
  const nlopt_result r = nlopt_optimize(opt, x.data(), &f);
  nlopt_destroy(opt);
  out.return_code = code_name(r);
  out.run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace armstudy::studies
