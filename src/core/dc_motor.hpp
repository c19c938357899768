// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Armature-controlled DC servomotor of Sato et al. eq. 5-7 (direct drive).
///
///   e = b1 qd + b2 qdd + b3 tau + b3 tau_f sign(qd),
///   b1 = kv + (Ra/kt) Dm, b2 = (Ra/kt) Im, b3 = Ra/kt          (eq. 5)
///   i  = (e - kv qd) / Ra = (tau + Dm qd + Im qdd + tau_f sign(qd)) / kt   (eq. 6)
///   E  = sum_j integral e_j i_j dt                              (eq. 7)
/// With kv = kt (SI), the electrical power splits exactly into
///   e i = tau qd (load) + Dm qd^2 (viscous) + tau_f |qd| (friction)
///         + Im qd qdd (rotor kinetic energy) + Ra i^2 (copper).
/// tau is the load torque on the joint, N m; qd in rad/s.

namespace armstudy::core {

struct DcMotor {
  double kt = 0.046;      ///< N m/A, torque constant
  double kv = 0.046;      ///< V s/rad, back-emf constant
  double Ra = 3.5;        ///< ohm, armature resistance
  double Dm = 7.9e-5;     ///< N m s/rad, viscous damping
  double tau_f = 0.0013;  ///< N m, Coulomb friction
  double Im = 0.0;        ///< kg m^2, rotor inertia (missing from Table 1 of 003)
};

/// Electrical state of one motor at one instant.
struct MotorSample {
  double voltage = 0;   ///< V, eq. 5
  double current = 0;   ///< A, eq. 6
  double power = 0;     ///< W, e i (eq. 7 integrand; negative when regenerating)
  double copper = 0;    ///< W, Ra i^2
  double friction = 0;  ///< W, (Dm qd + tau_f sign qd) qd
  double load = 0;      ///< W, tau qd (mechanical power into the arm)
};

/// Eq. 5's voltage and eq. 6's current for any scalar type (motor_sample's expressions,
/// its double instance; throw_gradient.hpp differentiates them). sign(0) is taken as 0.
template <typename T>
void motor_electrics(const DcMotor& m, const T& qd, const T& qdd, const T& tau, T& voltage,
                     T& current) {
  const double b3 = m.Ra / m.kt;
  const double sg = qd > 0.0 ? 1.0 : (qd < 0.0 ? -1.0 : 0.0);
  voltage = (m.kv + b3 * m.Dm) * qd + b3 * m.Im * qdd + b3 * tau + b3 * m.tau_f * sg;
  current = (voltage - m.kv * qd) / m.Ra;
}

/// Voltage, current and power split of `motor` driving a joint at (qd, qdd) with load tau.
/// sign(0) is taken as 0.
MotorSample motor_sample(const DcMotor& motor, double qd, double qdd, double tau);

/// Joint acceleration produced by voltage e (the inverse of eq. 5 for qdd) given load tau.
/// @throws std::invalid_argument if Im == 0 (then eq. 5 cannot be solved for qdd).
double motor_acceleration(const DcMotor& motor, double e, double qd, double tau);

}  // namespace armstudy::core
