// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The one model of every arm in armstudy: a planar serial chain of revolute joints.
///
/// Conventions (SI, radians):
/// - The chain lives in the world x-y plane; gravity (if any) acts along -y.
/// - Joint i (0-based) is at the start of link i; q[i] is the RELATIVE angle of link i
///   with respect to link i-1 (link -1 is the base, whose angle is `base_angle`).
///   The absolute angle of link i is base_angle + q[0] + ... + q[i].
/// - Link i runs along its own x axis from joint i to joint i+1 (length `length`).
/// - Torques act on the relative joint angles (tau[i] is the torque of joint i's actuator).
/// The parameters are constant once built (like mjModel); all algorithms are free
/// functions taking the chain by const reference.

#include <vector>

#include <Eigen/Dense>

#include "core/types.hpp"

namespace armstudy::core {

/// One rigid link. Its centre of mass is at (com, com_lateral) in the link frame.
struct Link {
  double length = 1.0;       ///< m, joint i to joint i+1, > 0
  double mass = 0.0;         ///< kg, >= 0
  double com = 0.0;          ///< m, centre of mass along the link axis from joint i
  double com_lateral = 0.0;  ///< m, centre of mass perpendicular to the link axis
  double inertia = 0.0;      ///< kg m^2, about the centre of mass, out of plane, >= 0
  bool active = true;        ///< false: a passive joint (no actuator, torque 0)
};

/// A point mass rigidly attached to link `link` at (x, y) in that link's frame.
struct PointMass {
  int link = 0;
  double x = 0.0;     ///< m, along the link axis from its joint
  double y = 0.0;     ///< m, perpendicular
  double mass = 0.0;  ///< kg
};

/// A spinning inertia whose angular velocity is a fixed linear combination of the
/// joint velocities: omega = coeffs . qd. It models rotor inertia (a gear ratio times a
/// joint rate) and the spin of a rolling object (e.g. the tray ball of
/// Sato et al.: omega_ball = (qd0+qd1+qd2) - (r4/r_b) qd3). Its kinetic energy
/// 1/2 I (coeffs . qd)^2 adds the constant I coeffs coeffs^T to the mass matrix.
/// (Its mass, if any, belongs to a PointMass or Link.)
struct SpinningInertia {
  double inertia = 0.0;  ///< kg m^2
  JointVector coeffs;    ///< (N), dimensionless
};

/// A planar serial chain. Build it with make_chain(), which validates it.
struct PlanarChain {
  std::vector<Link> links;
  std::vector<PointMass> point_masses;
  std::vector<SpinningInertia> spinners;
  double gravity = 0.0;                            ///< m/s^2 along -y (0: horizontal plane)
  double base_angle = 0.0;                         ///< rad, absolute angle of the base frame
  Eigen::Vector2d base = Eigen::Vector2d::Zero();  ///< m, position of joint 0

  int num_links() const { return static_cast<int>(links.size()); }
  /// Total mass of links and point masses, kg.
  double total_mass() const;
};

/// Validates and returns a chain.
/// @throws std::invalid_argument naming the link and the rule broken (e.g.
/// "link 2 length -0.1 m should be > 0"); 1 <= links <= kMaxLinks.
PlanarChain make_chain(PlanarChain chain);

/// A uniform slender rod's inertia about its centre, m L^2 / 12.
inline double uniform_rod_inertia(double mass, double length) {
  return mass * length * length / 12.0;
}

}  // namespace armstudy::core
