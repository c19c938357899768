// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The throwing problem solved by a gradient-based optimiser on the SAME parameterisation
/// and the SAME constraints as IDP (the interior node rates of profile.hpp): NLopt's SLSQP
/// (sequential least squares quadratic programming, Kraft 1988) minimising the consumed
/// energy (eq. 7) subject to
///   displacement of joints 1, 2 = release angles - start angles   (2 linear equalities),
///   constraint_values(setup, e, backoff) <= 0 (simulate.hpp: per stage contact force,
///   friction needed, tray angle, voltage, current, power; and the release angle).
/// Gradients are central differences of the simulation (step `fd_step` rad/s), evaluated
/// on `threads` threads, or (exact_gradient) the simulation's exact derivatives
/// (throw_gradient.hpp); a run that exact derivatives leave short of the first-order test is
/// finished by central differences (central_polish).
///
/// Convergence is first order, not SLSQP's own stop: at the final point the routine solves
/// for the Lagrange multipliers of the equalities and of the active inequalities
/// (g_i >= -kActiveBand; multipliers >= 0, kkt_multipliers) and measures the KKT residual
/// |grad f + sum mu_j grad h_j + sum lambda_i grad g_i| (2-norm over the node rates) as a
/// fraction of |f|: the first-order change of the objective that one rad/s of a feasible
/// change of the rates could still buy. The constraints are maxima over the RK4 samples of a
/// stage, which tie at an optimum, so central differences leave this residual a floor of a
/// few 1e-3; it is therefore paired with a restart test: after SLSQP stops (on ftol/xtol) it
/// is restarted from its last iterate with a fresh quasi-Newton model, `restarts` times at
/// most, within the budget of `max_evaluations` gradient evaluations in all, until a restart
/// changes the energy by at most `restart_gain` (relative). Converged: the final point meets
/// every constraint (no back-off; the back-off is the optimiser's target, not a limit), its
/// residual is at most kkt_tolerance and its last restart gained at most restart_gain. A
/// run that ends on its budget or its restarts otherwise is not converged, whatever SLSQP's
/// return code says.
///
/// The same routine also repairs an infeasible start (Objective::kViolation): it then
/// minimises the squared violation sum_i max(0, g_i + 2 backoff)^2 (only the displacement
/// equalities as constraints) and stops when it reaches 0 (STOPVAL_REACHED): the first
/// profile on the descent of the violation from the start that is twice the back-off inside
/// every limit (IDP's start: IDP, a random search, starts inside the feasible set). That
/// point is no optimum and moves with the last digit of an input, so no saving is quoted
/// against it.

#include <string>
#include <vector>

#include "studies/throwing/profile.hpp"
#include "studies/throwing/simulate.hpp"

namespace armstudy::studies {

struct NloptSettings {
  int max_evaluations = 1500;   ///< budget: gradient evaluations (each 1 + 2n simulations)
  double max_time = 900.0;      ///< s, wall-clock safety net (the budget is max_evaluations:
                                ///< a wall-clock limit would make the answer load-dependent)
  double ftol_rel = 1e-7;       ///< relative objective change that stops one SLSQP run
  double xtol_rel = 1e-7;       ///< relative rate change that stops one SLSQP run
  double kkt_tolerance = 1e-2;  ///< converged: KKT residual / |f| (per rad/s) at most this
  double restart_gain = 1e-4;   ///< and a restart from the point changes f by at most this
  int restarts = 4;             ///< SLSQP restarts from its last iterate, at most
  int perturbed_starts = 0;     ///< starts beside the reference, IDP's and eq. 8's: the
                                ///< reference with seeded uniform changes of its node rates
  double perturbation = 1.0;    ///< rad/s, half-width of those changes
  /// starts of the global phase beside those: eq. 8 plus a seeded sum of `smooth_modes`
  /// sine modes per joint (mode k's amplitude uniform in +-smooth_amplitude / k): whole-profile
  /// changes that reach other basins, where node-by-node noise of that size is infeasible
  int smooth_starts = 12;
  double smooth_amplitude = 5.0;  ///< rad/s, the first mode's half-width
  int smooth_modes = 4;           ///< sine modes per joint
  int hops = 3;                   ///< then starts from the best local optimum so far, perturbed
  double hop_size = 0.5;          ///< rad/s, half-width of a hop's changes
  double fd_step = 1e-5;          ///< rad/s, central-difference step
  /// the energy's and the constraints' gradients exact (forward sensitivities of the RK4
  /// simulation, throw_gradient.hpp; one simulation with sensitivities in place of 2n + 1)
  /// instead of central differences; the violation objective keeps central differences
  bool exact_gradient = false;
  double backoff = 0.02;  ///< constraint back-off (constraint_values)
  int threads = 2;
};

/// What SLSQP minimises.
enum class Objective {
  kEnergy,     ///< eq. 7
  kViolation,  ///< squared constraint violation (no inequality constraints)
};

/// Band (normalised constraint units) within which an inequality counts as active.
inline constexpr double kActiveBand = 1e-3;

struct NloptOutcome {
  VelocityProfile best;  ///< SLSQP's answer (its last iterate)
  ProfileEvaluation evaluation;
  std::vector<double> history;            ///< J (or (rad/s)^2), objective at each SLSQP evaluation
  std::vector<double> violation_history;  ///< total violation at each evaluation
  std::string return_code;                ///< NLopt's, e.g. "FTOL_REACHED"
  bool feasible = false;       ///< every constraint met (without the back-off), displacement exact
  bool converged = false;      ///< feasible and kkt_residual <= kkt_tolerance
  double kkt_residual = NAN;   ///< (1/|f|) |KKT residual| per rad/s at the answer
  int active_constraints = 0;  ///< inequalities within kActiveBand of their bound
  std::vector<std::string> binding;  ///< kinds of the active inequalities with lambda > 0
  int restarts = 0;                  ///< SLSQP restarts used
  double restart_gain = NAN;         ///< relative energy change of the last restart (NaN: none)
  double last_gain = NAN;            ///< relative objective change of the last iteration
  double objective = 0;              ///< the final objective
  double rate_change = 0;            ///< rad/s, max |change of a node rate| from the start
  int iterations = 0;                ///< SLSQP evaluations
  long simulations = 0;
  double run_time = 0;  ///< s
  /// exact_gradient: the run did not pass the first-order test with exact derivatives and was
  /// finished by central differences (its verdict is theirs)
  bool central_polish = false;
};

/// The first-order measure of run_nlopt (kkt_residual, active and binding constraints) at
/// any profile meeting the displacement, e.g. IDP's answer.
struct Optimality {
  double kkt_residual = NAN;
  int active_constraints = 0;
  std::vector<std::string> binding;
};
Optimality first_order_optimality(const ThrowSetup& setup, const VelocityProfile& profile,
                                  const Eigen::Vector2d& delta, const NloptSettings& settings);

/// Runs SLSQP from `initial` (any profile meeting the displacement; it need not be
/// feasible). Never throws on NLopt failures: they are reported in return_code.
NloptOutcome run_nlopt(const ThrowSetup& setup, const VelocityProfile& initial,
                       const Eigen::Vector2d& delta, const NloptSettings& settings,
                       Objective objective = Objective::kEnergy);

}  // namespace armstudy::studies
