// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The arm with a passive tray of Sato et al. as a core::PlanarChain.
///
/// Derivation (first principles; the printed eq. 1-4 are inconsistent, docs/defects.md)
/// ---------------------------------------------------------------------------------
/// Coordinates, all RELATIVE (as C2, C23, C234 of eq. 1), in a vertical plane with gravity
/// g along -y; e(a) = (cos a, sin a) and e_ijk = e(theta_i + theta_j + theta_k):
///   theta1  link 1 against the base (motor 1),
///   theta2  link 2 against link 1 (motor 2),
///   theta3  the tray against link 2 (PASSIVE hinge, no torque),
///   theta4  the ball against the tray: its centre lies on a circle of radius r4 about the
///           point C of the tray; theta4 = 0 on the tray's axis (the bottom of the cup).
/// C lies on the tray's axis at the distance d = `circle_offset` from the tray hinge
/// (Table 1's l3 by default). Positions of the centres of mass:
///   p1 = r1 e1,  p2 = l1 e1 + r2 e12,
///   p3 = l1 e1 + l2 e12 + r3 e123 + r3' e123^perp   (tray; r3' = com_lateral),
///   p4 = l1 e1 + l2 e12 + d e123 + r4 e1234         (ball centre).
/// Rolling without slip inside the cup (radius r4 + r_b about C): the contact point has the
/// tray's velocity, so relative to the tray r4 theta4' + r_b phi' = 0 (eq. 2, phi the spin
/// relative to the tray) and the ball's ABSOLUTE angular velocity is
///   omega_b = (theta1' + theta2' + theta3') - (r4 / r_b) theta4'.
/// Kinetic and potential energy:
///   K = sum_{i=1..3} (m_i |p_i'|^2 + I_Gi omega_i^2) / 2 + m4 |p4'|^2 / 2 + I_Gb omega_b^2 / 2
///       + sum_motors I_m omega_m^2 / 2,
///   U = g (m1 y1 + m2 y2 + m3 y3 + m4 y4),
/// with omega_i = theta1' + ... + thetai'. Lagrange's equations of K - U are exactly what
/// core/dynamics.hpp builds for a PlanarChain with
///   link 1: (l1, m1, com r1, I_G1, active),  link 2: (l2, m2, com r2, I_G2, active),
///   link 3: (d, m3, com r3, com_lateral r3', I_G3, passive),
///   link 4: (r4, massless, passive) carrying the ball as a PointMass m4 at its tip,
///   the ball's spin as a SpinningInertia I_Gb with coefficients (1, 1, 1, -r4/r_b),
///   each motor rotor as a SpinningInertia I_m on its motor rate (see below).
/// Differences from the print: eq. 3 keeps only a5/2 theta4'^2 of the spin (drops the tray's
/// rate: wrong whenever the tray turns) and a5 = I_Gb r_b^2/r4^2 is inverted (I_Gb r4^2/r_b^2
/// is right); a3 = I_G3 + m3 r3^2 + m4 d^2, a8 = (m3 r3 + m4 d) l1, a7 = (m3 r3 + m4 d) l2,
/// a11 = m4 d r4 (the print mixes d = r4 and d = r3); eq. 4's S234 reads S1234.
///
/// Motors (eq. 5-7 with core::DcMotor): motor 1 turns with theta1. Motor 2 either sits on
/// link 1 and turns with theta2 (`Motor2Mount::kOnLink1`, eq. 5 as printed), or sits on the
/// base and drives link 2's absolute angle theta1 + theta2 through the closed mechanism
/// (`kOnBase`, as the rig of Sec. 5 suggests). Motor rates are qd_m = B qd with
///   B = [1 0 0 0; 0 1 0 0] (kOnLink1) or [1 0 0 0; 1 1 0 0] (kOnBase),
/// and by virtual work the joint torques are Q = B^T tau_m. Rotor inertia I_m enters the
/// chain as a spinner on each row of B, so eq. 5's b2 term is already inside the torque the
/// chain's dynamics returns (the DcMotor passed to eq. 5 then has Im = 0: no double count).

#include <Eigen/Dense>

#include "core/dc_motor.hpp"
#include "core/planar_chain.hpp"
#include "core/types.hpp"

namespace armstudy::studies {

/// Where motor 2 sits (see the header comment).
enum class Motor2Mount {
  kOnLink1,  ///< drives the relative angle theta2
  kOnBase,   ///< drives link 2's absolute angle theta1 + theta2
};

/// Physical parameters of the tray arm, SI. Defaults are Table 1 of 003.
struct TrayArmParams {
  double l1 = 0.080, m1 = 0.020, r1 = 0.044, I1 = 1.7e-5;  ///< link 1: m, kg, m, kg m^2
  double l2 = 0.115, m2 = 0.047, r2 = 0.078, I2 = 8.4e-5;  ///< link 2
  double circle_offset = 0.015;  ///< m, tray hinge to the centre C of the ball's circle (l3)
  double m3 = 0.018;             ///< kg, tray
  double r3 = 0.028;             ///< m, tray centre of mass along its axis
  double r3_lateral = 0.0;       ///< m, tray centre of mass off its axis (r3')
  double I3 = 1.2e-6;            ///< kg m^2, tray about its centre of mass
  double m4 = 0.012;             ///< kg, ball
  double r4 = 0.005;             ///< m, radius of the ball centre's circle
  double rb = 0.010;             ///< m, ball radius
  double Ib = 4.8e-7;            ///< kg m^2, ball about its centre (Table 1 = 2/5 m4 rb^2)
  double rotor_inertia = 0.0;    ///< kg m^2, each motor's rotor (missing from Table 1)
  Motor2Mount motor2 = Motor2Mount::kOnLink1;
  double gravity = 9.81;  ///< m/s^2 along -y
};

/// Builds the 4-coordinate chain described in the header comment.
/// @throws std::invalid_argument (from core::make_chain) on non-physical parameters, or if
/// r4 or rb is not > 0.
core::PlanarChain make_tray_arm(const TrayArmParams& p);

/// Motor-rate matrix B (2 x 4): qd_m = B qd.
Eigen::Matrix<double, 2, 4> motor_matrix(Motor2Mount mount);

/// Motor torques tau_m (N m) that produce the generalized torques Q of joints 1 and 2
/// (Q = B^T tau_m); `tau` has 4 entries (entries 3, 4 ignored).
Eigen::Vector2d motor_torques(Motor2Mount mount, const core::JointVector& tau);

/// Generalized joint torques (4, N m; passive entries 0) of motor torques tau_m.
core::JointVector joint_torques(Motor2Mount mount, const Eigen::Vector2d& tau_m);

/// Ball centre (the tip of link 4) in the world, m.
Eigen::Vector2d ball_position(const core::PlanarChain& chain, const core::JointVector& q);

/// Ball centre velocity in the world, m/s.
Eigen::Vector2d ball_velocity(const core::PlanarChain& chain, const core::JointVector& q,
                              const core::JointVector& qd);

/// A solid sphere's inertia about its centre, 2/5 m r^2, kg m^2.
inline double solid_sphere_inertia(double mass, double radius) {
  return 0.4 * mass * radius * radius;
}

}  // namespace armstudy::studies
