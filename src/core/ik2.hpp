// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Closed-form inverse kinematics of a 2-link planar arm (both configurations), with
/// velocity and acceleration analysis. Angles are RELATIVE: q1 absolute angle of link 1,
/// q2 the elbow angle of link 2 relative to link 1.
/// Configuration 1: q2 in (0, pi) ("elbow left"); configuration 2: q2 in (-pi, 0).

#include <optional>

#include <Eigen/Dense>

namespace armstudy::core {

/// Where a point lies with respect to the reachable annulus [|L1-L2|, L1+L2].
struct Reach {
  double radius = 0;  ///< m, distance of the point from the root
  double inner = 0;   ///< m, |L1 - L2|
  double outer = 0;   ///< m, L1 + L2
  /// m, signed distance to the nearer boundary: > 0 inside, < 0 outside (how far out).
  double margin = 0;
  bool reachable() const { return margin >= 0; }
};

/// Reachability of p (relative to the root) by links L1, L2.
Reach reach_2link(double L1, double L2, const Eigen::Vector2d& p);

/// Joint positions, velocities and accelerations of a 2-link arm.
struct Ik2State {
  Eigen::Vector2d q;    ///< rad (q1 absolute, q2 relative)
  Eigen::Vector2d qd;   ///< rad/s
  Eigen::Vector2d qdd;  ///< rad/s^2
  double sin_q2 = 0;    ///< sin of the relative elbow angle (0: singular)
};

/// Position IK for configuration 1 or 2; nullopt when p is outside the annulus.
std::optional<Eigen::Vector2d> ik_2link(double L1, double L2, const Eigen::Vector2d& p,
                                        int configuration);

/// Position, velocity (J^-1 v) and acceleration (J^-1 (a - Jdot qd)) IK. Velocities and
/// accelerations are infinite at a singular pose (sin q2 = 0). nullopt if unreachable.
std::optional<Ik2State> ik_2link_motion(double L1, double L2, const Eigen::Vector2d& p,
                                        const Eigen::Vector2d& v, const Eigen::Vector2d& a,
                                        int configuration);

}  // namespace armstudy::core
