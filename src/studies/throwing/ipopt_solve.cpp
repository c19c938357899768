// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/throwing/ipopt_solve.hpp"

#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/check.hpp"
#include "studies/throwing/throw_gradient.hpp"

namespace armstudy::studies {
namespace {

using Ipopt::Index;
using Ipopt::Number;

// the node rates of `p` as IPOPT's variables: node k's rate of joint j at 2 (k - 1) + j
std::vector<double> ipopt_node_rates(const VelocityProfile& p) {
  std::vector<double> x(2 * size_t(p.stages() - 1));
  for (int k = 1; k < p.stages(); ++k) {
    x[2 * size_t(k - 1)] = p.v(0, k);
    x[2 * size_t(k - 1) + 1] = p.v(1, k);
  }
  return x;
}

// the throw as an IPOPT TNLP: rows 0, 1 the displacement equalities, then the 6P + 1
// inequalities of constraint_values (<= 0)
class ThrowTnlp : public Ipopt::TNLP {
 public:
  ThrowTnlp(const ThrowSetup& setup, const VelocityProfile& initial, const Eigen::Vector2d& delta,
            const NloptSettings& settings, bool per_sample, NloptOutcome& out)
      : setup_(setup),
        base_(initial),
        delta_(delta),
        settings_(settings),
        out_(out),
        P_(initial.stages()),
        n_(2 * (initial.stages() - 1)),
        x0_(ipopt_node_rates(initial)),
        per_sample_(per_sample),
        samples_(std::max(1, setup.steps_per_stage) + 1),
        rows_(per_sample ? P_ * samples_ * kSampleRows : 6 * P_) {}

  std::vector<double> answer;  // IPOPT's final point
  Ipopt::SolverReturn status = Ipopt::UNASSIGNED;

  VelocityProfile profile(const Number* x) const {
    VelocityProfile p = base_;
    for (int k = 1; k < P_; ++k) {
      p.v(0, k) = x[2 * (k - 1)];
      p.v(1, k) = x[2 * (k - 1) + 1];
    }
    return p;
  }

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag,
                    IndexStyleEnum& index_style) override {
    n = n_;
    m = 2 + rows_ + 1;
    nnz_jac_g = n_ + n_;  // the equalities and the release row
    for (int r = 0; r < rows_; ++r) nnz_jac_g += columns(stage_of(r));
    nnz_h_lag = 0;
    index_style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l,
                       Number* g_u) override {
    std::fill(x_l, x_l + n, -2e19);
    std::fill(x_u, x_u + n, 2e19);
    g_l[0] = g_u[0] = g_l[1] = g_u[1] = 0.0;
    std::fill(g_l + 2, g_l + m, -2e19);
    std::fill(g_u + 2, g_u + m, 0.0);
    return true;
  }

  bool get_constraints_linearity(Index m, LinearityType* types) override {
    std::fill(types, types + m, NON_LINEAR);
    types[0] = types[1] = LINEAR;
    return true;
  }

  bool get_starting_point(Index n, bool init_x, Number* x, bool init_z, Number*, Number*, Index,
                          bool init_lambda, Number*) override {
    if (!init_x || init_z || init_lambda) return false;
    std::copy(x0_.begin(), x0_.begin() + n, x);
    return true;
  }

  bool eval_f(Index, const Number* x, bool new_x, Number& f) override {
    if (!update(x, new_x)) return false;
    f = d_.evaluation.energy;
    return true;
  }

  bool eval_grad_f(Index n, const Number* x, bool new_x, Number* g) override {
    if (!update(x, new_x)) return false;
    std::copy(d_.energy_gradient.data(), d_.energy_gradient.data() + n, g);
    return true;
  }

  bool eval_g(Index, const Number* x, bool new_x, Index m, Number* g) override {
    const VelocityProfile p = profile(x);
    const Eigen::Vector2d d = displacement(p) - delta_;
    g[0] = d[0];
    g[1] = d[1];
    if (!update(x, new_x)) return false;
    if (per_sample_) {
      std::copy(d_.sample_constraints.begin(), d_.sample_constraints.end(), g + 2);
      g[2 + rows_] = d_.constraints.back();
      return static_cast<int>(d_.sample_constraints.size()) == rows_ && 3 + rows_ == m;
    }
    std::copy(d_.constraints.begin(), d_.constraints.end(), g + 2);
    return static_cast<int>(d_.constraints.size()) + 2 == m;
  }

  bool eval_jac_g(Index, const Number* x, bool new_x, Index, Index nele, Index* row, Index* col,
                  Number* values) override {
    if (values == nullptr) {  // the structure
      Index e = 0;
      for (int i = 0; i < n_; ++i) row[e] = i % 2, col[e++] = i;
      for (int r = 0; r < rows_; ++r)
        for (int i = 0; i < columns(stage_of(r)); ++i) row[e] = 2 + r, col[e++] = i;
      for (int i = 0; i < n_; ++i) row[e] = 2 + rows_, col[e++] = i;
      return e == nele;
    }
    if (!update(x, new_x)) return false;
    Index e = 0;
    const double h = base_.stage_length();
    for (int i = 0; i < n_; ++i) values[e++] = h;  // interior nodes weigh the stage length
    const Eigen::MatrixXd& J = per_sample_ ? d_.sample_jacobian : d_.constraint_jacobian;
    for (int r = 0; r < rows_; ++r)
      for (int i = 0; i < columns(stage_of(r)); ++i) values[e++] = J(r, i);
    for (int i = 0; i < n_; ++i) values[e++] = d_.constraint_jacobian(6 * P_, i);
    return e == nele;
  }

  bool intermediate_callback(Ipopt::AlgorithmMode, Index, Number obj, Number inf_pr, Number, Number,
                             Number, Number, Number, Number, Index, const Ipopt::IpoptData*,
                             Ipopt::IpoptCalculatedQuantities*) override {
    out_.history.push_back(obj);
    out_.violation_history.push_back(inf_pr);
    return out_.simulations < settings_.max_evaluations;
  }

  void finalize_solution(Ipopt::SolverReturn s, Index n, const Number* x, const Number*,
                         const Number*, Index, const Number*, const Number*, Number,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    status = s;
    answer.assign(x, x + n);
  }

 private:
  // stage k's rows depend on the first columns(k) variables (nodes up to k + 1)
  int columns(int k) const { return std::min(n_, 2 * k + 2); }
  // the stage of inequality row r (the release row excluded)
  int stage_of(int r) const { return per_sample_ ? r / kSampleRows / samples_ : r % P_; }

  // the values and derivatives at x (one simulation with sensitivities per new point)
  bool update(const Number* x, bool new_x) {
    if (new_x || !have_ || !std::equal(x_.begin(), x_.end(), x)) {
      x_.assign(x, x + n_);
      have_ = false;
      if (!std::all_of(x, x + n_, [](double v) { return std::isfinite(v); })) return false;
      d_ = throw_derivatives(setup_, profile(x), settings_.backoff, per_sample_);
      ++out_.simulations;
      have_ = true;
      keep_if_best(x);
    }
    return d_.evaluation.finite;
  }

  // the lowest energy met at a point inside every back-off target (to kTargetSlack) with the
  // displacement exact: IPOPT's iterates are not monotone in the energy, and its last one can
  // end above a feasible start
  void keep_if_best(const Number* x) {
    if (!d_.evaluation.finite) return;
    const double worst = *std::max_element(d_.constraints.begin(), d_.constraints.end());
    if (worst > kTargetSlack || d_.evaluation.energy >= best_energy) return;
    if ((displacement(profile(x)) - delta_).norm() > 1e-8) return;
    best_energy = d_.evaluation.energy;
    best.assign(x, x + n_);
  }

 public:
  static constexpr double kTargetSlack = 1e-4;  // normalised constraint units
  std::vector<double> best;                     // the lowest such point met (empty: none)
  double best_energy = INFINITY;

 private:
  const ThrowSetup& setup_;
  const VelocityProfile base_;
  const Eigen::Vector2d delta_;
  const NloptSettings settings_;
  NloptOutcome& out_;
  const int P_, n_;
  const std::vector<double> x0_;
  const bool per_sample_;
  const int samples_, rows_;  // samples per stage, inequality rows before the release row
  std::vector<double> x_;
  bool have_ = false;
  ThrowDerivatives d_;
};

std::string ipopt_status_name(Ipopt::ApplicationReturnStatus s) {
  switch (s) {
    case Ipopt::Solve_Succeeded: return "Solve_Succeeded";
    case Ipopt::Solved_To_Acceptable_Level: return "Solved_To_Acceptable_Level";
    case Ipopt::Infeasible_Problem_Detected: return "Infeasible_Problem_Detected";
    case Ipopt::Search_Direction_Becomes_Too_Small: return "Search_Direction_Becomes_Too_Small";
    case Ipopt::Diverging_Iterates: return "Diverging_Iterates";
    case Ipopt::User_Requested_Stop: return "User_Requested_Stop (evaluation budget)";
    case Ipopt::Feasible_Point_Found: return "Feasible_Point_Found";
    case Ipopt::Maximum_Iterations_Exceeded: return "Maximum_Iterations_Exceeded";
    case Ipopt::Restoration_Failed: return "Restoration_Failed";
    case Ipopt::Error_In_Step_Computation: return "Error_In_Step_Computation";
    case Ipopt::Maximum_CpuTime_Exceeded: return "Maximum_CpuTime_Exceeded";
    case Ipopt::Not_Enough_Degrees_Of_Freedom: return "Not_Enough_Degrees_Of_Freedom";
    case Ipopt::Invalid_Problem_Definition: return "Invalid_Problem_Definition";
    case Ipopt::Invalid_Option: return "Invalid_Option";
    case Ipopt::Invalid_Number_Detected: return "Invalid_Number_Detected";
    default: return "IPOPT error " + std::to_string(static_cast<int>(s));
  }
}

}  // namespace

NloptOutcome run_ipopt(const ThrowSetup& setup, const VelocityProfile& initial,
                       const Eigen::Vector2d& delta, const NloptSettings& settings,
                       const IpoptSettings& ipopt) {
  ARM_THROW_UNLESS(derivatives_apply(setup) && initial.stages() >= 2,
                   "IPOPT needs the exact derivatives (the tray arm's chain) and >= 2 stages");
  const auto t0 = std::chrono::steady_clock::now();
  NloptOutcome out;
  Ipopt::SmartPtr<ThrowTnlp> nlp =
      new ThrowTnlp(setup, initial, delta, settings, ipopt.per_sample_rows, out);
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetIntegerValue("print_level", 0);
  app->Options()->SetStringValue("sb", "yes");  // no banner
  app->Options()->SetStringValue("hessian_approximation", "limited-memory");
  app->Options()->SetIntegerValue("limited_memory_max_history", ipopt.lbfgs_memory);
  app->Options()->SetStringValue("linear_solver", "mumps");
  app->Options()->SetNumericValue("tol", ipopt.tolerance);
  app->Options()->SetNumericValue("acceptable_tol", ipopt.acceptable_tolerance);
  app->Options()->SetNumericValue("mu_init", ipopt.mu_init);
  app->Options()->SetIntegerValue("max_iter", ipopt.max_iterations);
  app->Options()->SetStringValue("jac_d_constant", "no");
  Ipopt::ApplicationReturnStatus s = app->Initialize();
  if (s == Ipopt::Solve_Succeeded) s = app->OptimizeTNLP(Ipopt::SmartPtr<Ipopt::TNLP>(nlp));
  out.return_code = ipopt_status_name(s);
  out.iterations = static_cast<int>(out.history.size());
  out.best = nlp->answer.empty() ? initial : nlp->profile(nlp->answer.data());
  out.evaluation = simulate_profile(setup, out.best, nullptr, settings.backoff);
  // the answer: IPOPT's last iterate, or the lowest point inside the back-off targets met on
  // the way when that is lower or the last iterate misses a target
  if (!nlp->best.empty()) {
    double worst_target = -INFINITY;
    for (double g : constraint_values(setup, out.evaluation, settings.backoff))
      worst_target = std::max(worst_target, g);
    if (!out.evaluation.finite || worst_target > ThrowTnlp::kTargetSlack ||
        nlp->best_energy < out.evaluation.energy) {
      out.best = nlp->profile(nlp->best.data());
      out.evaluation = simulate_profile(setup, out.best, nullptr, settings.backoff);
    }
  }
  out.objective = out.evaluation.energy;
  out.rate_change = (out.best.v - initial.v).cwiseAbs().maxCoeff();
  double worst = -INFINITY;
  for (double g : constraint_values(setup, out.evaluation, 0.0)) worst = std::max(worst, g);
  out.feasible =
      out.evaluation.finite && worst <= 0.0 && (displacement(out.best) - delta).norm() <= 1e-8;
  NloptSettings exact = settings;
  exact.exact_gradient = true;
  const Optimality o = first_order_optimality(setup, out.best, delta, exact);
  out.kkt_residual = o.kkt_residual;
  out.active_constraints = o.active_constraints;
  out.binding = o.binding;
  const size_t H = out.history.size();
  if (H >= 2)
    out.last_gain =
        (out.history[H - 2] - out.history[H - 1]) / std::max(std::abs(out.history[H - 1]), 1e-12);
  const bool stopped_on_tolerance =
      s == Ipopt::Solve_Succeeded || s == Ipopt::Solved_To_Acceptable_Level;
  out.converged =
      out.feasible && stopped_on_tolerance && out.kkt_residual <= settings.kkt_tolerance;
  out.run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace armstudy::studies
