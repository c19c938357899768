// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The figures of one checked motion (an optimum, an evaluated placement, the thesis's best):
/// - its energy by adaptive Gauss-Kronrod quadrature with an error estimate (quadrature.hpp),
///   printed when the estimate is within the tolerance;
/// - its sampled peak torque and power, and the other sampled metrics, converged by doubling
///   the samples per trajectory; withheld when the peak does not settle.
/// Near a workspace boundary these part: a line at d > 0 from the inner circle has a finite
/// energy with a finite limit as d -> 0+ while its peak torque grows like d^-1/2; a line
/// ending on the outer circle at rest has a finite energy while its torque grows like
/// (T - t)^-1/2 at that end, so the sampled peak grows like h^-1/2 without bound. So the
/// energy is printed with its error and only the peak (and the peak power) is withheld.
/// A line exactly tangent to the inner circle folds the elbow at its closest approach, where
/// both joint rates reverse at once: its energy is the limit of the lines at d -> 0+, the
/// integral on both sides plus the reversal's jump term (quadrature.hpp); its peak torque
/// is unbounded (an impulse) and withheld.

#include <cmath>
#include <limits>
#include <vector>

#include "core/motion_program.hpp"
#include "studies/placement/arm2.hpp"

namespace armstudy::studies::placement {

/// One row of a convergence table: the energy with `samples` samples per trajectory.
struct ConvergenceRow {
  int samples = 0;
  double energy = 0;       ///< J
  double peak_torque = 0;  ///< N m, max over both joints
};

/// What the quadrature and the doubling found for one motion.
struct EnergyConvergence {
  bool checked = false;  ///< converge_energy ran (false: not a printed candidate)
  /// on one doubling the sampled energy changed by < tol and the sampled peak torque by
  /// < peak_tol
  bool converged = false;
  /// the sampled peak torque changed by < peak_tol on the last doubling
  bool peak_converged = false;
  bool touches_boundary = false;  ///< the line is on a boundary (exact geometry, 1e-9 m)
  /// touches the inner circle |L1 - L2| (an exact tangent, or an end on it): the elbow
  /// folds; its energy stands (with the jump term of a tangent), its peak torque is withheld
  bool touches_inner = false;
  /// the energy below comes from the adaptive quadrature (check_energy); false: the energy
  /// is the doubling's (converge_energy alone, the sweep)
  bool quadrature = false;
  double energy = std::numeric_limits<double>::quiet_NaN();       ///< J, the quadrature's
  double energy_error = std::numeric_limits<double>::infinity();  ///< J, its estimate
  double quadrature_tolerance = 0;  ///< relative error the quadrature was asked for
  /// J, the part of `energy` that is the folded elbow's reversal (a line exactly tangent to
  /// the inner circle; 0 otherwise)
  double energy_jump = 0;
  int quadrature_intervals = 0, quadrature_evaluations = 0;
  /// the energy may be printed: the quadrature's estimate within `tolerance` (or, without
  /// the quadrature, the doubling converged, off the boundaries)
  bool energy_converged() const {
    if (!checked) return false;
    if (quadrature) return std::isfinite(energy) && energy_error <= tolerance * std::abs(energy);
    return converged && !touches_boundary;
  }
  /// no energy (nor saving) may be printed
  bool energy_withheld() const { return checked && !energy_converged(); }
  /// no peak torque or peak power may be printed: the line touches a boundary or the
  /// sampled peak did not settle (it grows without bound at a singular pose)
  bool peak_withheld() const { return checked && (touches_boundary || !peak_converged); }
  /// every figure of the motion may be printed
  bool regular() const { return checked && !energy_withheld() && !peak_withheld(); }
  int samples = 0;  ///< samples of `metrics`: the finer of the converged pair
  double rel_change = std::numeric_limits<double>::quiet_NaN();  ///< energy, at the last doubling
  double peak_rel_change = std::numeric_limits<double>::quiet_NaN();  ///< peak torque, same
  double tolerance = 0;  ///< the relative tolerance asked for (energy error, doubling)
  /// relative resolution of the peaks in `metrics` when they are the continuous motion's
  /// (peaks.hpp: a case with a torque or power limit); 0: sampled peaks
  double peak_resolution = 0;
  /// at `samples`; with the quadrature, metrics.energy is the quadrature's energy
  LineMetrics metrics;
  std::vector<ConvergenceRow> rows;  ///< every doubling tried, coarsest first (sampled)
};

/// Doubles the samples (n -> 2 n - 1, nested grids) from `samples` until the energy
/// changes by less than `tol` and the sampled peak torque by less than `peak_tol`
/// (relative) and by at most half its change on the doubling before (or is exactly still),
/// or `max_samples` is passed; the finer of the last pair is kept. `touches`: the exact line check
/// puts the line on a boundary (|boundary distance| within 1e-9 m, so |sin q2| ~ 1e-4 or less on
/// it).
EnergyConvergence converge_energy(const Arm2& arm, core::MotionProgram program, double duration,
                                  double length, const Line& line, int configuration, int samples,
                                  bool touches, double tol = 1e-4, double peak_tol = 1e-3,
                                  int max_samples = 409601);

/// converge_energy, then the energy by energy_quadrature (relative tolerance
/// `quad_tol`): what the checked candidates get. `touches_inner`: the line is within 1e-9 m
/// of the inner circle (the elbow folds).
EnergyConvergence check_energy(const Arm2& arm, core::MotionProgram program, double duration,
                               double length, const Line& line, int configuration, int samples,
                               bool touches, bool touches_inner, double tol = 1e-4,
                               double quad_tol = 1e-9, double peak_tol = 1e-3,
                               int max_samples = 409601);

/// The sentence printed instead of the energy, peak and saving of a motion whose energy is
/// withheld (a quadrature that did not converge).
inline constexpr const char* kSingularNote =
    "singular: energy not converged, peak torque unbounded";
/// The sentence printed instead of the peak torque (and peak power) of a motion whose energy
/// is printed but whose sampled peak does not settle.
inline constexpr const char* kPeakUnboundedNote = "peak torque unbounded (singular pose)";
/// The same for a line on the inner circle: the trouble is the folded elbow, not the energy.
inline constexpr const char* kFoldedElbowNote =
    "the elbow folds on the inner circle, where the joint rates reverse at once: the energy "
    "holds that reversal, the peak torque is an impulse (unbounded)";

}  // namespace armstudy::studies::placement
