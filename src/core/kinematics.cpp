// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "core/kinematics.hpp"

#include <cmath>

#include "core/check.hpp"

namespace armstudy::core {
namespace {
Eigen::Vector2d rotate(double angle, const Eigen::Vector2d& v) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}
// ez x v
Eigen::Vector2d perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }
}  // namespace

ChainPose forward_kinematics(const PlanarChain& chain, const JointVector& q) {
  const int n = chain.num_links();
  ARM_THROW_UNLESS(q.size() == n, "q has " << q.size() << " entries; chain has " << n << " joints");
  ChainPose pose;
  pose.angle.resize(n);
  pose.p_WJ.resize(2, n + 1);
  pose.p_WJ.col(0) = chain.base;
  double a = chain.base_angle;
  for (int i = 0; i < n; ++i) {
    a += q[i];
    pose.angle[i] = a;
    pose.p_WJ.col(i + 1) =
        pose.p_WJ.col(i) + chain.links[i].length * Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  return pose;
}

Eigen::Vector2d point_position(const ChainPose& pose, int link, const Eigen::Vector2d& p_L) {
  return pose.p_WJ.col(link) + rotate(pose.angle[link], p_L);
}

Eigen::Vector2d end_effector(const PlanarChain& chain, const JointVector& q) {
  const ChainPose pose = forward_kinematics(chain, q);
  return pose.p_WJ.col(chain.num_links());
}

PointJacobian point_jacobian(const ChainPose& pose, int link, const Eigen::Vector2d& p_L) {
  const int n = static_cast<int>(pose.angle.size());
  const Eigen::Vector2d p = point_position(pose, link, p_L);
  PointJacobian J = PointJacobian::Zero(2, n);
  // column j: ez x (p - p_j) for every joint j up to the link
  for (int j = 0; j <= link; ++j) J.col(j) = perp(p - pose.p_WJ.col(j));
  return J;
}

PointJacobian point_jacobian_dot(const ChainPose& pose, const JointVector& qd, int link,
                                 const Eigen::Vector2d& p_L) {
  return point_jacobian_dot(pose, point_jacobian(pose, link, p_L), qd, link);
}

PointJacobian point_jacobian_dot(const ChainPose& pose, const PointJacobian& J,
                                 const JointVector& qd, int link) {
  const int n = static_cast<int>(pose.angle.size());
  // velocity of the point and of each joint origin
  const Eigen::Vector2d v = J * qd;
  PointJacobian Jd = PointJacobian::Zero(2, n);
  Eigen::Vector2d v_j = Eigen::Vector2d::Zero();  // joint 0 is fixed
  double omega = 0.0;                             // absolute rate of link j-1
  for (int j = 0; j <= link; ++j) {
    if (j > 0) {
      // joint j moves with link j-1: v_j = v_{j-1} + omega_{j-1} ez x (p_j - p_{j-1})
      v_j += omega * perp(pose.p_WJ.col(j) - pose.p_WJ.col(j - 1));
    }
    omega += qd[j];
    Jd.col(j) = perp(v - v_j);
  }
  return Jd;
}

PointJacobian end_effector_jacobian(const PlanarChain& chain, const JointVector& q) {
  const ChainPose pose = forward_kinematics(chain, q);
  const int n = chain.num_links();
  return point_jacobian(pose, n - 1, Eigen::Vector2d(chain.links[n - 1].length, 0.0));
}

double manipulability(const PlanarChain& chain, const JointVector& q) {
  const PointJacobian J = end_effector_jacobian(chain, q);
  const double d = (J * J.transpose()).determinant();
  return std::sqrt(std::max(0.0, d));
}

double smallest_singular_value(const PlanarChain& chain, const JointVector& q) {
  const PointJacobian J = end_effector_jacobian(chain, q);
  const Eigen::MatrixXd Jm = J;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jm);
  const auto& s = svd.singularValues();
  return s.size() < 2 ? 0.0 : s[s.size() - 1];
}

}  // namespace armstudy::core
