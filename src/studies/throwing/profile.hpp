// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Velocity profiles of the two active joints: the decision variables of IDP and NLopt.
///
/// Time [0, tf] is cut into P equal stages of length h = tf / P. Each active joint's rate is
/// linear inside a stage between node values v_0 .. v_P (so its acceleration is constant
/// per stage, as in the paper's IDP, which gives the active accelerations stage by stage).
/// v_0 and v_P are the prescribed start and release rates; v_1 .. v_{P-1} are free. The
/// displacement  q(tf) - q(0) = h sum_k (v_k + v_{k+1}) / 2  must equal the prescribed one:
/// project_displacement() restores it by adding c sin(pi t_k / tf) to the interior nodes
/// (the shape of eq. 8's correction term), so every candidate meets the release angles of
/// joints 1 and 2 exactly.

#include <Eigen/Dense>

namespace armstudy::studies {

/// Node rates of joints 1 and 2 over P stages.
struct VelocityProfile {
  double tf = 0.8;                               ///< s
  Eigen::Vector2d q0 = Eigen::Vector2d::Zero();  ///< rad, angles at t = 0
  Eigen::Matrix<double, 2, Eigen::Dynamic> v;    ///< rad/s, 2 x (P + 1) node rates

  int stages() const { return static_cast<int>(v.cols()) - 1; }
  double stage_length() const { return tf / stages(); }
};

/// Angles, rates and accelerations of the active joints at one instant.
struct ActiveState {
  Eigen::Vector2d q, qd, qdd;  ///< rad, rad/s, rad/s^2
};

/// The active joints at time t inside stage `stage` (0-based; t in [t_stage, t_stage+1];
/// the stage decides which side of a node's acceleration jump is returned).
ActiveState evaluate_profile(const VelocityProfile& p, int stage, double t);

/// Same, with the stage found from t (t = tf belongs to the last stage).
ActiveState evaluate_profile(const VelocityProfile& p, double t);

/// Angle change q(tf) - q(0) of each joint, rad.
Eigen::Vector2d displacement(const VelocityProfile& p);

/// Adds c_j sin(pi t_k / tf) to the interior nodes of joint j so that the displacement is
/// `delta` (rad). @throws std::invalid_argument if P < 2 (no interior node).
void project_displacement(VelocityProfile& p, const Eigen::Vector2d& delta);

/// The same rate function on `factor` x the stages: each stage cut into `factor` equal
/// stages, the new nodes on the coarse stage's line. Exact: the prolonged profile is the same
/// function of time (same angles, rates and accelerations everywhere), so simulated with the
/// same RK4 step (steps_per_stage / factor) it costs the same energy and meets the same
/// constraints. @throws std::invalid_argument if factor < 1.
VelocityProfile prolong_profile(const VelocityProfile& p, int factor);

/// The initial trajectory of 003 eq. 8 (corrected form of docs/defects.md) sampled at the nodes:
///   qd(t) = qd_i + (qd_f - qd_i) t/tf + (pi/2) ((q_f - q_i)/tf - (qd_i + qd_f)/2) sin(pi t/tf),
/// then projected so that the piecewise-linear profile meets q_f exactly.
/// @throws std::invalid_argument if stages < 2 or tf <= 0.
VelocityProfile eq8_profile(const Eigen::Vector2d& q_i, const Eigen::Vector2d& qd_i,
                            const Eigen::Vector2d& q_f, const Eigen::Vector2d& qd_f, double tf,
                            int stages);

/// Eq. 8 itself (the continuous curve), rad/s, for comparison.
Eigen::Vector2d eq8_rate(const Eigen::Vector2d& q_i, const Eigen::Vector2d& qd_i,
                         const Eigen::Vector2d& q_f, const Eigen::Vector2d& qd_f, double tf,
                         double t);

}  // namespace armstudy::studies
