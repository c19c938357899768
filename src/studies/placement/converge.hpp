#pragma once
/// Energy of one motion converged by doubling the samples per trajectory: no
/// printed energy, peak or saving comes from an unconverged integral. A line that touches
/// a workspace boundary (|sin q2| = 0 on it) is a singular motion whatever the doubling
/// shows: tangent to the inner circle the elbow folds and its rate jumps (an impulsive
/// torque that no sample sees, so the sampled energy settles on a value that misses it);
/// an end on the outer circle at rest gives the elbow rate a square-root cusp and the
/// sampled peak torque grows like h^-1/2 without bound.

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

/// What the doubling found for one motion.
struct EnergyConvergence {
  bool checked = false;  ///< converge_energy ran (false: not a printed candidate)
  bool converged = false;
  /// on one doubling the energy changed by < tol and the sampled peak torque by < peak_tol
  bool touches_boundary = false;  ///< the line is on a boundary (exact geometry, 1e-9 m)
  /// no energy, peak or saving may be printed: touching a boundary or not converged
  bool singular() const { return checked && (touches_boundary || !converged); }
  int samples = 0;  ///< samples of `metrics`: the coarser of the converged pair
  double rel_change = std::numeric_limits<double>::quiet_NaN();  ///< energy, at the last doubling
  double peak_rel_change = std::numeric_limits<double>::quiet_NaN();  ///< peak torque, same
  double tolerance = 0;              ///< the relative tolerance asked for
  LineMetrics metrics;               ///< at `samples`
  std::vector<ConvergenceRow> rows;  ///< every doubling tried, coarsest first
};

/// Doubles the samples (n -> 2 n - 1, nested grids) from `samples` until the energy
/// changes by less than `tol` and the sampled peak torque by less than `peak_tol`
/// (relative), or `max_samples` is passed. `touches`: the exact line check puts the line
/// on a boundary (|boundary distance| within 1e-9 m, so |sin q2| ~ 1e-4 or less on it).
EnergyConvergence converge_energy(const Arm2& arm, core::MotionProgram program, double duration,
                                  double length, const Line& line, int configuration, int samples,
                                  bool touches, double tol = 1e-4, double peak_tol = 1e-3,
                                  int max_samples = 409601);

/// The sentence printed instead of an energy, peak or saving of a singular motion.
inline constexpr const char* kSingularNote =
    "singular: energy not converged, peak torque unbounded";

}  // namespace armstudy::studies::placement
