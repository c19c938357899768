// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
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
///
/// The stages run twice: first on the energy of the sampled motion (the trapezoid on the
/// table's samples: cheap, but its |power| kinks crossing samples leave a ripple with local
/// minima ~5e-6 relative apart, and its own O(h^2) error moves the optimum by up to 1e-5
/// relative), then from the point found on the converged energy, the adaptive quadrature of
/// quadrature.hpp asked for 1e-11: Nelder-Mead (at an interior point), the quadratic polish,
/// the boundary search (+-0.1 scaled, to 1e-10) and the COBYLA restart; there the limits are
/// kept on the continuous motion (peaks.hpp: each sampled maximum refined between the
/// samples; a peak on its limit at 401 samples is up to ~2e-5 relative higher between them),
/// and the point the first pass found, when it breaks them, is moved back by COBYLA. The
/// final tolerance is the second pass's; a nearly active limit adds its multiplier times its
/// peak's resolution to the energy's error (limit_energy_error).
///
/// The optimum's location error (x_s_error, phi_error) is its distance from the minimum of
/// the converged energy: at an interior optimum, the Newton step to the minimum of the
/// quadratic fitted on a 3 x 3 stencil, extrapolated from spacings d = 3e-4 and 2 d (scaled)
/// to d -> 0, plus its truncation (the spacing-d step's change from the extrapolated one),
/// plus the objective's noise e moved through the fit (gradient error e / d times the
/// inverse curvature); e is twice the quadrature's change when asked for 100 times less
/// error, plus 1e-15 of the energy. On a boundary the same along it (5 points on g = 0),
/// carried to (x_s, phi) by the boundary's tangent; at a corner of the admissible set the
/// constraints fix the point (1e-12 scaled).

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
  int quadratures = 0;  ///< of those, by the adaptive quadrature (the second pass)
  int rounds = 0;
  /// m and rad: the distance of `best` from the minimum of the converged energy (see above;
  /// NaN when no quadratic could be fitted)
  double x_s_error = std::numeric_limits<double>::quiet_NaN();
  double phi_error = std::numeric_limits<double>::quiet_NaN();
  double objective_error = std::numeric_limits<double>::quiet_NaN();  ///< J, at best
  /// J, the energy's error from the resolution of the continuous peaks a nearly active limit
  /// is kept on: the limit's multiplier (|grad E| / |grad g|) times that resolution (0: no
  /// limit near)
  double limit_energy_error = 0;
};

/// Sets the peaks of `c` (at the table's samples) to those of the continuous motion
/// (peaks.hpp) and classifies it again, when the spec has a torque or power limit: what the
/// limits are kept on.
void with_continuous_peaks(const Spec& spec, const Arm2& arm, const ProgramTable& table,
                           int configuration, Candidate& c);

/// Refines `start` (an admissible candidate of the sweep) in a box of +-4 (hx, hphi) around
/// it with spec's margin and limits; the energy uses `table`'s samples.
Refinement refine_constrained(const Spec& spec, const Arm2& arm, const ProgramTable& table,
                              int configuration, const Candidate& start, double hx, double hphi,
                              double target_rel = 1e-7);

}  // namespace armstudy::studies::placement
