// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/tray_arm.hpp"

#include <cmath>

#include "core/check.hpp"
#include "core/kinematics.hpp"

namespace armstudy::studies {

core::PlanarChain make_tray_arm(const TrayArmParams& p) {
  ARM_THROW_UNLESS(std::isfinite(p.r4) && p.r4 > 0,
                   "ball circle radius r4 " << p.r4 << " m should be > 0");
  ARM_THROW_UNLESS(std::isfinite(p.rb) && p.rb > 0,
                   "ball radius r_b " << p.rb << " m should be > 0");
  core::PlanarChain c;
  c.links = {{p.l1, p.m1, p.r1, 0.0, p.I1, true},
             {p.l2, p.m2, p.r2, 0.0, p.I2, true},
             {p.circle_offset, p.m3, p.r3, p.r3_lateral, p.I3, false},
             {p.r4, 0.0, 0.0, 0.0, 0.0, false}};
  // the ball's centre: a point mass at the tip of the massless link 4
  c.point_masses = {{3, p.r4, 0.0, p.m4}};
  // the ball's absolute spin omega_b = (qd1 + qd2 + qd3) - (r4 / rb) qd4 (rolling, eq. 2)
  core::SpinningInertia ball;
  ball.inertia = p.Ib;
  ball.coeffs.resize(4);
  ball.coeffs << 1.0, 1.0, 1.0, -p.r4 / p.rb;
  c.spinners.push_back(ball);
  // rotors spin with the motor rates B qd
  if (p.rotor_inertia > 0) {
    const Eigen::Matrix<double, 2, 4> B = motor_matrix(p.motor2);
    for (int m = 0; m < 2; ++m) {
      core::SpinningInertia rotor;
      rotor.inertia = p.rotor_inertia;
      rotor.coeffs = B.row(m).transpose();
      c.spinners.push_back(rotor);
    }
  }
  c.gravity = p.gravity;
  return core::make_chain(c);
}

Eigen::Matrix<double, 2, 4> motor_matrix(Motor2Mount mount) {
  Eigen::Matrix<double, 2, 4> B;
  B << 1, 0, 0, 0, (mount == Motor2Mount::kOnBase ? 1.0 : 0.0), 1, 0, 0;
  return B;
}

Eigen::Vector2d motor_torques(Motor2Mount mount, const core::JointVector& tau) {
  // Q1 = tau_m1 + b tau_m2, Q2 = tau_m2 (B^T tau_m with b = B(1, 0))
  const double b = mount == Motor2Mount::kOnBase ? 1.0 : 0.0;
  return {tau[0] - b * tau[1], tau[1]};
}

core::JointVector joint_torques(Motor2Mount mount, const Eigen::Vector2d& tau_m) {
  const double b = mount == Motor2Mount::kOnBase ? 1.0 : 0.0;
  core::JointVector Q = core::JointVector::Zero(4);
  Q[0] = tau_m[0] + b * tau_m[1];
  Q[1] = tau_m[1];
  return Q;
}

Eigen::Vector2d ball_position(const core::PlanarChain& chain, const core::JointVector& q) {
  return core::end_effector(chain, q);
}

Eigen::Vector2d ball_velocity(const core::PlanarChain& chain, const core::JointVector& q,
                              const core::JointVector& qd) {
  return core::end_effector_jacobian(chain, q) * qd;
}

}  // namespace armstudy::studies
