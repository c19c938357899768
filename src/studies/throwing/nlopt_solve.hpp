#pragma once
/// The throwing problem solved by a gradient-based optimiser on the SAME parameterisation
/// as IDP (the interior node rates of profile.hpp), for comparison: NLopt's SLSQP
/// (sequential least squares quadratic programming, Kraft 1988) minimising the consumed
/// energy (eq. 7) subject to
///   displacement of joints 1, 2 = release angles - start angles   (2 linear equalities),
///   per stage: max |theta4| <= lambda/2, max |e| <= voltage_max, max |i| <= current_max,
///   |theta3(tf) - theta3_release| <= release_tolerance           (3 P + 1 inequalities).
/// Gradients are central differences of the simulation (step `fd_step` rad/s), evaluated
/// on `threads` threads. The limits enter as constraints here, where IDP penalises them.

#include <string>
#include <vector>

#include "studies/throwing/profile.hpp"
#include "studies/throwing/simulate.hpp"

namespace armstudy::studies {

struct NloptSettings {
  int max_evaluations = 150;       ///< SLSQP iterations (each costs 1 + 2n simulations)
  double max_time = 15.0;          ///< s, wall-clock budget
  double ftol_rel = 1e-7;          ///< relative energy change that stops SLSQP
  double fd_step = 1e-5;           ///< rad/s, central-difference step
  double release_tolerance = 0.005;  ///< rad, allowed |theta3(tf) - theta3_release|
  int threads = 2;
};

struct NloptOutcome {
  VelocityProfile best;
  ProfileEvaluation evaluation;
  VelocityProfile last;              ///< SLSQP's last point (may violate a constraint)
  ProfileEvaluation last_evaluation;
  std::vector<double> history;  ///< J, energy at each SLSQP evaluation
  std::string return_code;      ///< NLopt's, e.g. "FTOL_REACHED"
  bool feasible = false;        ///< every constraint met within 1e-6 (relative)
  long simulations = 0;
  double run_time = 0;          ///< s
};

/// Runs SLSQP from `initial` (usually the eq. 8 profile). Never throws on NLopt failures:
/// they are reported in return_code, and the best feasible point seen is returned.
NloptOutcome run_nlopt(const ThrowSetup& setup, const VelocityProfile& initial,
                       const Eigen::Vector2d& delta, const NloptSettings& settings);

}  // namespace armstudy::studies
