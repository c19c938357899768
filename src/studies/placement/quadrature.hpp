// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The energy of one motion, E = integral over [0, T] of |tau1 qd1| + |tau2 qd2| dt (eq. 8.1),
/// by adaptive Gauss-Kronrod quadrature (G7-K15, global subdivision of the interval of
/// largest error) with an error estimate: for the checked candidates (optima, evaluations,
/// the thesis's best), not for the sweep, which keeps evaluate_line's uniform grid.
///
/// Near a workspace boundary the energy stays finite while the torques do not:
/// - a line passing at d > 0 outside the inner circle |L1 - L2|: near the instant t* of
///   closest approach pi - |q2| ~ sqrt(d + c (t - t*)^2), the elbow rate swings through 0
///   within a time ~ sqrt(d), torque and power peak like d^-1/2 over that width: the energy
///   is finite and tends to a finite limit as d -> 0+ (measured on the example-3 family:
///   each decade of d shrinks the change by 2.2-2.8 over d = 1e-4..1e-12 m). That limit
///   holds a jump term that the integral of the exactly tangent line d = 0 does not see.
///   For that line (the elbow folded at t*, both rates reversing at once) the energy is the
///   integral over both sides of t* plus the jump term: as d -> 0+ the torque in the window
///   is M(q*) qdd (the rest stays bounded) and the rates move on a straight segment from
///   qd- to qd+, so joint i adds |J_i| * integral_0^1 |qd-_i + l (qd+_i - qd-_i)| dl with
///   the impulse J = M(q*) (qd+ - qd-) (docs/placement.md: "the folded elbow");
/// - an end on the outer circle L1 + L2 (or on the inner one, the foot of the
///   perpendicular off the segment), at rest: q2 ~ t^{3/2} from that end, torque ~ t^-1/2,
///   power bounded (and not 0 at the end): the energy is finite and continuous in the line;
///   an end within roundoff (64 ulp) of a circle is integrated as exactly on it.
/// Breakpoints: the ends, t* (s(t*) = the foot of the perpendicular from the root, when it
/// lies on the segment; s is monotone and inverted by bisection), the corners of the
/// trapezoidal program and every sign change of a joint's power found on a 256-point scan
/// (the |.| kinks); the adaptive subdivision does the rest. The elbow's cos q2 and sin q2
/// are computed from the distances to both circles written without cancellation near either
/// end (the programs are symmetric, s(T - t) = L - s(t), so L - s comes from s(T - t)) and
/// near t* (r^2 - (L1 - L2)^2 = (h - |L1 - L2|)(h + |L1 - L2|) + (s - s*)^2, h the root's
/// distance from the line), so that a line 1e-8 m from a boundary is integrated to 1e-9.
///
/// The error estimate is the sum over the final intervals of |K15 - G7| (the error of the
/// 7-point Gauss rule, an upper estimate of the 15-point Kronrod value's), floored at 50 ulp
/// of each interval's integral of |f|.

#include <limits>

#include "core/motion_program.hpp"
#include "studies/placement/arm2.hpp"

namespace armstudy::studies::placement {

/// The result of energy_quadrature.
struct EnergyQuadrature {
  double energy = std::numeric_limits<double>::quiet_NaN();  ///< J
  double error = std::numeric_limits<double>::infinity();    ///< J, estimate (see above)
  double tolerance_rel = 0;                                  ///< relative error asked for
  bool converged = false;  ///< error <= tolerance_rel * energy (finite)
  int intervals = 0;       ///< final subintervals
  int evaluations = 0;     ///< integrand evaluations
  int breakpoints = 0;     ///< interior breakpoints (t*, corners, kinks)
  double t_closest = std::numeric_limits<double>::quiet_NaN();  ///< s, t* (NaN: foot off it)
  /// J, the folded elbow's reversal term of a line exactly tangent to the inner circle
  /// (included in `energy`; 0 for every other line), and its error (included in `error`)
  double jump = 0, jump_error = 0;
  double relative_error() const { return error / energy; }
};

/// The joint powers tau_j qd_j (W) of the motion at time t, with the elbow computed as above.
struct JointPowers {
  double p1 = 0, p2 = 0;
  double abs_sum() const { return (p1 < 0 ? -p1 : p1) + (p2 < 0 ? -p2 : p2); }
};

/// The integrand of the energy along one line: the motion program (rest to rest over
/// `length` m in `duration` s) carried along `line` in configuration 1 or 2.
class LinePower {
 public:
  LinePower(const Arm2& arm, core::MotionProgram program, double duration, double length,
            const Line& line, int configuration);
  JointPowers at(double t) const;
  /// the joint state and torques at t (the elbow as above)
  Arm2Sample sample(double t) const;
  /// the line is exactly tangent to the inner circle (within 64 ulp) at t*: the elbow folds
  /// there and both joint rates reverse at once
  bool folds() const { return foot_on_segment_ && din_foot_ == 0.0; }
  /// s, the time when the tip is at the foot of the perpendicular from the root (NaN when
  /// that foot is off the segment)
  double t_closest() const { return t_closest_; }
  double duration() const { return T_; }
  core::MotionProgram program() const { return program_; }

 private:
  Arm2 arm_;
  core::MotionProgram program_;
  double T_, L_, sign_;
  Line line_;
  Eigen::Vector2d end_;
  double s_star_, t_closest_;
  bool foot_on_segment_;
  double din_foot_;      // h^2 - inner^2, h the root's distance from the line
  double din0_, dout0_;  // r^2 - inner^2, outer^2 - r^2 at the start
  double dinL_, doutL_;  // the same at the end
};

/// E of the motion by adaptive G7-K15 to the relative tolerance `tol_rel` (or until
/// `max_intervals` subintervals). Non-finite energy when the integrand is not finite at a
/// node (a singular pose inside the motion).
EnergyQuadrature energy_quadrature(const Arm2& arm, core::MotionProgram program, double duration,
                                   double length, const Line& line, int configuration,
                                   double tol_rel = 1e-9, int max_intervals = 4000);

}  // namespace armstudy::studies::placement
