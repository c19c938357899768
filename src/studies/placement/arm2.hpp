// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Specialised closed-form evaluator of a 2-link arm in a horizontal plane carrying its tip
/// along a straight line: inverse kinematics, velocities, accelerations, actuator torques
/// and power for every sample of a motion, without allocation. It is the hot loop of the
/// placement sweeps; tests prove it equals core's generic ik_2link_motion +
/// inverse_dynamics.
///
/// Model (relative angles q1 = theta1, q2 = theta2 - theta1 of Kopmaz (2016);
/// torques on relative angles, so M2 is the elbow actuator and M1 the root actuator):
///   T = 1/2 (J1 + m_2 L1^2) qd1^2 + 1/2 J2 w^2 + g(q2) qd1 w,   w = qd1 + qd2,
///   g(q2) = A cos q2 - B sin q2, A = L1 sum(m x), B = L1 sum(m y) over link 2's bodies,
///   M = [[a11 + 2 g, a12 + g], [a12 + g, a22]], g' = dg/dq2 = -A sin q2 - B cos q2,
///   tau1 = M11 qdd1 + M12 qdd2 + g' (2 qd1 qd2 + qd2^2),
///   tau2 = M12 qdd1 + M22 qdd2 - g' qd1^2.
/// For the thesis's arm A = L1 (m2 rG2 + m L2), B = 0 and the torques are (6.35) for M2
/// and (6.29) + (6.35) for M1 (its printed (7.2) is wrong, see docs/defects.md).

#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Dense>

#include "core/motion_program.hpp"
#include "core/planar_chain.hpp"

namespace armstudy::studies::placement {

/// Constant parameters of the closed-form 2-link model above (SI).
struct Arm2 {
  double L1 = 0, L2 = 0;             ///< m, link lengths
  double a11 = 0, a12 = 0, a22 = 0;  ///< kg m^2, constant parts of M
  double A = 0, B = 0;               ///< kg m^2, coefficients of g(q2)
};

/// The closed-form parameters of `chain` (links, point masses, spinners).
/// @throws std::invalid_argument unless the chain has 2 links, both joints active, and
/// gravity 0 (the placement study lives in a horizontal plane).
Arm2 make_arm2(const core::PlanarChain& chain);

/// A motion program sampled on the uniform time grid t_k = k T / (n - 1), k = 0..n-1.
struct ProgramTable {
  core::MotionProgram program = core::MotionProgram::kCycloidal;
  double duration = 1;             ///< s
  double length = 1;               ///< m
  double dt = 0;                   ///< s, T / (n - 1)
  std::vector<double> s, sd, sdd;  ///< m, m/s, m/s^2 (n each)
  int size() const { return static_cast<int>(s.size()); }
};

/// Samples `program` (rest to rest over `length` m in `duration` s) at `samples` >= 3
/// instants. @throws std::invalid_argument for samples < 3 or non-positive T, L.
ProgramTable make_program_table(core::MotionProgram program, double duration, double length,
                                int samples);

/// Joint state and torques at one sample (rad, rad/s, rad/s^2, N m).
struct Arm2Sample {
  double c1 = 1, s1 = 0;  ///< cos, sin of the absolute angle of link 1
  double c2 = 1, s2 = 0;  ///< cos, sin of the relative elbow angle q2
  double qd1 = 0, qd2 = 0;
  double qdd1 = 0, qdd2 = 0;
  double tau1 = 0, tau2 = 0;
};

/// Closed-form IK, velocity, acceleration and inverse dynamics at tip position p, velocity
/// v and acceleration a (root at the origin; m, m/s, m/s^2) in configuration `sign`
/// (+1: configuration 1, q2 in (0, pi); -1: configuration 2). Outside the annulus c2 is
/// clamped; at a singular pose (s2 = 0) rates are infinite.
inline Arm2Sample arm2_sample_elbow(const Arm2& arm, double px, double py, double vx, double vy,
                                    double ax, double ay, double c2, double s2);

inline Arm2Sample arm2_sample(const Arm2& arm, double px, double py, double vx, double vy,
                              double ax, double ay, double sign) {
  const double L1 = arm.L1, L2 = arm.L2;
  const double r2 = px * px + py * py;
  // law of cosines for the elbow, eq. 3.3 in relative form
  double c2 = (r2 - L1 * L1 - L2 * L2) / (2.0 * L1 * L2);
  c2 = c2 > 1.0 ? 1.0 : (c2 < -1.0 ? -1.0 : c2);
  const double s2 = sign * std::sqrt(1.0 - c2 * c2);
  return arm2_sample_elbow(arm, px, py, vx, vy, ax, ay, c2, s2);
}

/// arm2_sample with the elbow's cos q2 and sin q2 given (signed as the configuration): for a
/// caller that knows them more accurately than the law of cosines on p gives them near a
/// boundary of the annulus (quadrature.hpp).
inline Arm2Sample arm2_sample_elbow(const Arm2& arm, double px, double py, double vx, double vy,
                                    double ax, double ay, double c2, double s2) {
  Arm2Sample o;
  const double L1 = arm.L1, L2 = arm.L2;
  const double r2 = px * px + py * py;
  // link 1 direction without trigonometry: p = R(theta1) (L1 + L2 c2, L2 s2)
  const double k1 = L1 + L2 * c2, k2 = L2 * s2;
  const double inv_r2 = 1.0 / r2;
  const double c1 = (px * k1 + py * k2) * inv_r2;
  const double s1 = (py * k1 - px * k2) * inv_r2;
  // elbow-to-tip vector f = p - e, e = L1 (c1, s1)
  const double ex = L1 * c1, ey = L1 * s1;
  const double fx = px - ex, fy = py - ey;
  // J = [[-py, -fy], [px, fx]], det J = L1 L2 s2; J^-1 = [[fx, fy], [-px, -py]] / det
  const double inv_det = 1.0 / (L1 * L2 * s2);
  const double qd1 = (fx * vx + fy * vy) * inv_det;
  const double qd2 = -(px * vx + py * vy) * inv_det;
  // qdd = J^-1 (a - Jdot qd), Jdot qd = -(w1^2 e + w12^2 f), eq. 3.16 in relative form
  const double w12 = qd1 + qd2;
  const double bx = ax + qd1 * qd1 * ex + w12 * w12 * fx;
  const double by = ay + qd1 * qd1 * ey + w12 * w12 * fy;
  const double qdd1 = (fx * bx + fy * by) * inv_det;
  const double qdd2 = -(px * bx + py * by) * inv_det;
  // inverse dynamics; M2 is (6.35), M1 = (6.29) + (6.35)
  const double g = arm.A * c2 - arm.B * s2;
  const double gp = -arm.A * s2 - arm.B * c2;
  const double m11 = arm.a11 + 2.0 * g, m12 = arm.a12 + g, m22 = arm.a22;
  o.tau1 = m11 * qdd1 + m12 * qdd2 + gp * (2.0 * qd1 * qd2 + qd2 * qd2);
  o.tau2 = m12 * qdd1 + m22 * qdd2 - gp * qd1 * qd1;
  o.c1 = c1;
  o.s1 = s1;
  o.c2 = c2;
  o.s2 = s2;
  o.qd1 = qd1;
  o.qd2 = qd2;
  o.qdd1 = qdd1;
  o.qdd2 = qdd2;
  return o;
}

/// A straight task line in the arm's frame (root at the origin): from `start` along the
/// unit vector `dir`.
struct Line {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();  ///< m
  Eigen::Vector2d dir = Eigen::Vector2d::UnitX();   ///< unit
};

/// The line of the thesis's search: start (x_s, 0), direction angle phi (rad), eq. 4.3-4.5.
inline Line thesis_line(double x_s, double phi) {
  return {Eigen::Vector2d(x_s, 0.0), Eigen::Vector2d(std::cos(phi), std::sin(phi))};
}

/// Integrals and peaks of one motion along a line on the table's time grid.
struct LineMetrics {
  double energy = 0;  ///< J, integral of |tau1 qd1| + |tau2 qd2| dt (eq. 8.1)
  /// J, integral of tau1 qd1 + tau2 qd2 dt (0 rest to rest), by Gregory's end-corrected
  /// trapezoidal rule (O(h^6) for this smooth integrand; plain trapezoid below 12 samples)
  double signed_work = 0;
  double peak_torque[2] = {0, 0};  ///< N m, max |tau_j| over the samples
  double peak_power[2] = {0, 0};   ///< W, max |tau_j qd_j| over the samples
  double min_abs_sin = 1;          ///< smallest sampled |sin q2|
  /// J, the same trapezoid on every other sample (0, 2, 4, ..., and the last): its
  /// difference from `energy` estimates the quadrature error at no extra cost
  double energy_coarse = 0;
  bool finite() const { return std::isfinite(energy); }
  /// Richardson estimate of the relative quadrature error of `energy` (the trapezoid
  /// converges like h^2: error ~ (energy - energy_coarse) / 3); infinite when not finite
  double energy_error_estimate() const {
    if (!finite() || !(energy > 0)) return std::numeric_limits<double>::infinity();
    return std::abs(energy - energy_coarse) / (3.0 * energy);
  }
};

/// Energy, signed work and peaks of the motion `table` along `line` in configuration 1 or
/// 2. Non-finite energy when a sample is singular. Costs table.size() samples.
/// Structure of arrays: arm2_sample's arithmetic over blocks of samples in a loop the
/// compiler vectorises, then the sums and peaks in sample order, so that it returns exactly
/// evaluate_line_scalar's figures (tests compare them bit for bit).
LineMetrics evaluate_line(const Arm2& arm, const ProgramTable& table, const Line& line,
                          int configuration);

/// The same metrics one sample at a time through arm2_sample: the reference of
/// evaluate_line.
LineMetrics evaluate_line_scalar(const Arm2& arm, const ProgramTable& table, const Line& line,
                                 int configuration);

/// Time series of one motion (for optima and evaluated placements). Angles are relative
/// (q1 absolute angle of link 1, unwrapped; q2 elbow), rad; power_j = tau_j qd_j, W.
struct TimeSeries {
  std::vector<double> t;                    ///< s
  std::vector<Eigen::Vector2d> tip;         ///< m, tip position in the arm's frame
  std::vector<Eigen::Vector2d> q, qd, qdd;  ///< rad, rad/s, rad/s^2
  std::vector<Eigen::Vector2d> tau;         ///< N m
  std::vector<Eigen::Vector2d> power;       ///< W, signed
  std::vector<double> energy;               ///< J, cumulative integral of |power_1| + |power_2|
};

/// The full time series of evaluate_line's motion (same samples, same integral).
TimeSeries sample_series(const Arm2& arm, const ProgramTable& table, const Line& line,
                         int configuration);

}  // namespace armstudy::studies::placement
