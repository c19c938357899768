// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Forward kinematics, point Jacobians and their time derivatives of a PlanarChain.
/// Frames: W is the world frame; all positions are in W, in metres.

#include <Eigen/Dense>

#include "core/planar_chain.hpp"
#include "core/types.hpp"

namespace armstudy::core {

/// Absolute angles and joint positions of every link for one configuration.
struct ChainPose {
  JointVector angle;  ///< (N) rad, absolute angle of link i
  Eigen::Matrix<double, 2, Eigen::Dynamic, 0, 2, kMaxLinks + 1> p_WJ;  ///< (2 x N+1) joints, tip
};

/// Pose of every link. @throws std::invalid_argument if q.size() != N.
ChainPose forward_kinematics(const PlanarChain& chain, const JointVector& q);

/// World position of the point (x, y) of link `link`'s frame, m.
Eigen::Vector2d point_position(const ChainPose& pose, int link, const Eigen::Vector2d& p_L);

/// End effector (the tip of the last link), m.
Eigen::Vector2d end_effector(const PlanarChain& chain, const JointVector& q);

/// Translational Jacobian (2 x N) of the point p_L of link `link`: v = J qd, m/rad.
PointJacobian point_jacobian(const ChainPose& pose, int link, const Eigen::Vector2d& p_L);

/// Time derivative of point_jacobian (2 x N) along qd, m/(rad s).
PointJacobian point_jacobian_dot(const ChainPose& pose, const JointVector& qd, int link,
                                 const Eigen::Vector2d& p_L);
/// The same with the point's Jacobian J = point_jacobian(pose, link, p_L) given (the same
/// numbers without computing it again).
PointJacobian point_jacobian_dot(const ChainPose& pose, const PointJacobian& J,
                                 const JointVector& qd, int link);

/// End-effector Jacobian (2 x N).
PointJacobian end_effector_jacobian(const PlanarChain& chain, const JointVector& q);

/// Yoshikawa manipulability sqrt(det(J J^T)) of the end effector, m^2 (0 at a singularity).
double manipulability(const PlanarChain& chain, const JointVector& q);

/// Smallest singular value of the end-effector Jacobian, m: the distance to singularity.
double smallest_singular_value(const PlanarChain& chain, const JointVector& q);

}  // namespace armstudy::core
