// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The throwing problem of nlopt_solve.hpp (the same variables, objective and constraints,
/// the same back-off) solved by IPOPT (Waechter & Biegler 2006, an interior-point method with
/// a filter line search) in place of SLSQP: for the fine control grids, where SLSQP's dense
/// QP subproblem (n variables x 6P + 3 rows) costs most of the time.
///
/// Derivatives are exact (throw_gradient.hpp) and the Jacobian is given to IPOPT sparse:
/// the simulation is single shooting, so stage k's six rows (its maxima over the RK4
/// samples) depend only on the node rates up to node k + 1 (the first 2k + 2 variables), the
/// release row on all of them, and the displacement equalities on every other one. The
/// Hessian of the Lagrangian is IPOPT's limited-memory (L-BFGS) approximation; the linear
/// solver is MUMPS.
///
/// The answer is IPOPT's last iterate or, when that is higher or misses a back-off target, the
/// lowest-energy point IPOPT evaluated inside every back-off target (to 1e-4) with the
/// displacement exact: IPOPT's iterates are not monotone, and its last one was measured to end
/// above a feasible start (6.7439 J from 6.7318 J on 16 stages). It is measured as run_nlopt's
/// is: feasible (every
/// constraint met without the back-off, displacement exact), and its first-order measure
/// (first_order_optimality: kkt_residual, active, binding). Converged: feasible, IPOPT ended
/// on its tolerances (Solve_Succeeded or Solved_To_Acceptable_Level) and kkt_residual <=
/// settings.kkt_tolerance.

#include <Eigen/Dense>

#include "studies/throwing/nlopt_solve.hpp"
#include "studies/throwing/profile.hpp"
#include "studies/throwing/simulate.hpp"

namespace armstudy::studies {

struct IpoptSettings {
  int max_iterations = 3000;           ///< IPOPT iterations (each one or more simulations)
  double tolerance = 1e-6;             ///< IPOPT's tol (scaled NLP error)
  double acceptable_tolerance = 1e-4;  ///< acceptable_tol (after acceptable_iter such iterates)
  double mu_init = 1e-3;               ///< initial barrier parameter (a warm start is near optimal)
  int lbfgs_memory = 20;               ///< limited_memory_max_history
  /// the stage constraints sample by sample (smooth; throw_derivatives' per_sample rows)
  /// instead of the stages' maxima (kinked where two samples tie)
  bool per_sample_rows = false;
};

/// Runs IPOPT from `initial` (any profile meeting the displacement). Uses settings.backoff,
/// kkt_tolerance and max_evaluations (simulations with derivatives) of `settings`; never
/// throws on IPOPT failures: they are reported in return_code (IPOPT's ApplicationReturnStatus).
/// @throws std::invalid_argument unless derivatives_apply(setup) and P >= 2.
NloptOutcome run_ipopt(const ThrowSetup& setup, const VelocityProfile& initial,
                       const Eigen::Vector2d& delta, const NloptSettings& settings,
                       const IpoptSettings& ipopt = {});

}  // namespace armstudy::studies
