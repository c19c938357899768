#pragma once
/// The throwing problem solved by a gradient-based optimiser on the SAME parameterisation
/// and the SAME constraints as IDP (the interior node rates of profile.hpp): NLopt's SLSQP
/// (sequential least squares quadratic programming, Kraft 1988) minimising the consumed
/// energy (eq. 7) subject to
///   displacement of joints 1, 2 = release angles - start angles   (2 linear equalities),
///   constraint_values(setup, e, backoff) <= 0 (simulate.hpp: per stage contact force,
///   friction needed, tray angle, voltage, current, power; and the release angle).
/// Gradients are central differences of the simulation (step `fd_step` rad/s), evaluated
/// on `threads` threads.
///
/// Convergence: SLSQP's own tolerances (ftol_rel on the objective, xtol_rel on the rates).
/// A run that stops on max_evaluations or max_time (the budget), or whose final point is
/// infeasible, is not converged.
///
/// The same routine also repairs an infeasible start (Objective::kViolation): it then
/// minimises the squared violation sum_i max(0, g_i + 2 backoff)^2 (only the displacement
/// equalities as constraints) and stops when it reaches 0 (STOPVAL_REACHED): the first
/// profile on the descent of the violation from the start that is twice the back-off inside
/// every limit (so that IDP, a random search, starts from inside the feasible set).

#include <string>
#include <vector>

#include "studies/throwing/profile.hpp"
#include "studies/throwing/simulate.hpp"

namespace armstudy::studies {

struct NloptSettings {
  int max_evaluations = 400;  ///< budget: SLSQP iterations (each 1 + 2n simulations)
  double max_time = 900.0;    ///< s, wall-clock safety net (the budget is max_evaluations:
                              ///< a wall-clock limit would make the answer load-dependent)
  double ftol_rel = 1e-6;     ///< relative objective change that stops SLSQP
  double xtol_rel = 1e-6;     ///< relative rate change that stops SLSQP
  double fd_step = 1e-5;      ///< rad/s, central-difference step
  double backoff = 0.02;      ///< constraint back-off (constraint_values)
  int threads = 2;
};

/// What SLSQP minimises.
enum class Objective {
  kEnergy,     ///< eq. 7
  kViolation,  ///< squared constraint violation (repair of an infeasible start)
};

struct NloptOutcome {
  VelocityProfile best;  ///< SLSQP's answer (its last iterate)
  ProfileEvaluation evaluation;
  std::vector<double> history;            ///< J (or (rad/s)^2), objective at each SLSQP evaluation
  std::vector<double> violation_history;  ///< total violation at each evaluation
  std::string return_code;                ///< NLopt's, e.g. "FTOL_REACHED"
  bool feasible = false;   ///< every constraint >= 3/4 backoff inside (repair: backoff)
  bool converged = false;  ///< stopped on ftol/xtol at a feasible point
  double last_gain = NAN;  ///< relative objective change of the last iteration
  double objective = 0;    ///< the final objective
  double rate_change = 0;  ///< rad/s, max |change of a node rate| from the start
  int iterations = 0;      ///< SLSQP evaluations
  long simulations = 0;
  double run_time = 0;  ///< s
};

/// Runs SLSQP from `initial` (usually the feasible reference). Never throws on NLopt
/// failures: they are reported in return_code.
NloptOutcome run_nlopt(const ThrowSetup& setup, const VelocityProfile& initial,
                       const Eigen::Vector2d& delta, const NloptSettings& settings,
                       Objective objective = Objective::kEnergy);

}  // namespace armstudy::studies
