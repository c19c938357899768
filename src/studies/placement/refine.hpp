#pragma once
/// Constrained local refinement of a placement and what decides it.
///
/// The energy E(x_s, phi) of the sampled motion is minimised near a start candidate with the
/// constraints as constraints, never as a penalty:
///   inner clearance  (|L1 - L2| + margin) - r_min <= 0,
///   outer clearance  r_max - (L1 + L2 - margin) <= 0,
///   peak |tau_j| / limit_j - 1 <= 0 and peak |power_j| / limit_j - 1 <= 0 when limits are given,
/// where r_min, r_max are the exact least and largest distances of the line from the root.
/// Stages: NLopt COBYLA with those inequality constraints; Nelder-Mead restricted to the
/// admissible set and Newton steps on quadratics fitted to 3 x 3 stencils of shrinking
/// spacing (an interior optimum); a golden-section search along each nearly active
/// constraint, parameterised by one variable with the other solved from g = 0 by bisection
/// on its admissible side (a boundary optimum); then a COBYLA restart from the best point.
/// The recorded final tolerance is the larger of the relative energy the restart still
/// gains and the decrease the last fitted quadratic still predicts (interior); the stages
/// repeat (at most 3 rounds) until it is below 1e-7.

#include <cstdint>
#include <limits>
#include <string>

#include "studies/placement/result.hpp"
#include "studies/placement/spec.hpp"

namespace armstudy::studies::placement {

/// "interior", "inner_clearance", "outer_clearance", "torque_limit", "power_limit".
const char* binding_name(Binding b);

/// The constraints' slacks at candidate `c` and which one binds (spec's margin and limits).
/// A clearance binds when its slack is below `active_m`; a limit when its slack is below
/// `active_rel` of the limit.
Decision decide(const Spec& spec, const Candidate& c, double active_m = 1e-9,
                double active_rel = 1e-7);

/// What the refinement found.
struct Refinement {
  Candidate best;      ///< the least-energy admissible point evaluated (classified)
  std::string method;  ///< the stages that ran
  double tolerance_rel = std::numeric_limits<double>::quiet_NaN();  ///< see above
  double target_rel = 1e-7;  ///< converged when tolerance_rel <= target_rel
  bool converged = false;
  int evaluations = 0;  ///< energy evaluations (table.size() samples each)
  int rounds = 0;
};

/// Refines `start` (an admissible candidate of the sweep) in a box of +-4 (hx, hphi) around
/// it with spec's margin and limits; the energy uses `table`'s samples.
Refinement refine_constrained(const Spec& spec, const Arm2& arm, const ProgramTable& table,
                              int configuration, const Candidate& start, double hx, double hphi,
                              double target_rel = 1e-7);

}  // namespace armstudy::studies::placement
