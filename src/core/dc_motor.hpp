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
  /// rad/s, sign(qd) of the Coulomb term taken as a smooth step within |qd| < band (0: the
  /// exact sign). A numerical regularisation, not a friction model: with the exact sign the
  /// current jumps by 2 tau_f / kt where a joint's rate crosses 0, so a sampled energy or
  /// current jumps wherever that crossing passes a sample, and a gradient method stalls on
  /// the jump's edge; a linear ramp leaves kinks at +-band, where it stalls as well
  /// (docs/throwing.md, "The Coulomb term")
  double coulomb_band = 1e-3;
};

/// sign(qd) of the Coulomb term of `m`: within the band the cubic r (3 - r^2) / 2 of
/// r = qd / coulomb_band (odd, continuous with its slope at r = +-1); the exact sign (sign(0)
/// = 0) outside the band or when the band is 0. For any scalar type that compares with double
/// (motor_electrics' instances); the SIMD kernel (simulate_kernel.cpp) writes the same
/// operations with its lane selects.
template <typename T>
T coulomb_sign(const DcMotor& m, const T& qd) {
  if (m.coulomb_band > 0) {
    if (qd >= m.coulomb_band) return T(1.0);
    if (qd <= -m.coulomb_band) return T(-1.0);
    const T r = qd / m.coulomb_band;
    return 0.5 * r * (3.0 - r * r);
  }
  return qd > 0.0 ? T(1.0) : (qd < 0.0 ? T(-1.0) : T(0.0));
}

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
/// its double instance; throw_gradient.hpp differentiates them), with coulomb_sign.
template <typename T>
void motor_electrics(const DcMotor& m, const T& qd, const T& qdd, const T& tau, T& voltage,
                     T& current) {
  const double b3 = m.Ra / m.kt;
  const T sg = coulomb_sign(m, qd);
  voltage = (m.kv + b3 * m.Dm) * qd + b3 * m.Im * qdd + b3 * tau + b3 * m.tau_f * sg;
  current = (voltage - m.kv * qd) / m.Ra;
}

/// Voltage, current and power split of `motor` driving a joint at (qd, qdd) with load tau
/// (sign(qd) as coulomb_sign).
MotorSample motor_sample(const DcMotor& motor, double qd, double qdd, double tau);

/// Joint acceleration produced by voltage e (the inverse of eq. 5 for qdd) given load tau
/// (sign(qd) as coulomb_sign).
/// @throws std::invalid_argument if Im == 0 (then eq. 5 cannot be solved for qdd).
double motor_acceleration(const DcMotor& motor, double e, double qd, double tau);

}  // namespace armstudy::core
