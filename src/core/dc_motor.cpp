// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "core/dc_motor.hpp"

#include "core/check.hpp"

namespace armstudy::core {
MotorSample motor_sample(const DcMotor& m, double qd, double qdd, double tau) {
  MotorSample s;
  motor_electrics(m, qd, qdd, tau, s.voltage, s.current);  // eq. 5, 6
  s.power = s.voltage * s.current;
  s.copper = m.Ra * s.current * s.current;
  s.friction = (m.Dm * qd + m.tau_f * coulomb_sign(m, qd)) * qd;
  s.load = tau * qd;
  return s;
}

double motor_acceleration(const DcMotor& m, double e, double qd, double tau) {
  ARM_THROW_UNLESS(m.Im > 0, "motor rotor inertia " << m.Im << " kg m^2 should be > 0");
  const double b3 = m.Ra / m.kt;
  return (e - (m.kv + b3 * m.Dm) * qd - b3 * tau - b3 * m.tau_f * coulomb_sign(m, qd)) /
         (b3 * m.Im);
}

}  // namespace armstudy::core
