// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Fixed-capacity joint-space types: N is 2 to kMaxLinks at run time, with no heap allocation.

#include <Eigen/Dense>

namespace armstudy::core {

/// Largest number of joints of a planar chain.
inline constexpr int kMaxLinks = 7;

using JointVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxLinks, 1>;
using JointMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxLinks, kMaxLinks>;
/// 2 x N point Jacobian (planar translation).
using PointJacobian = Eigen::Matrix<double, 2, Eigen::Dynamic, 0, 2, kMaxLinks>;

inline constexpr double kPi = 3.14159265358979323846;
/// One degree in radians.
inline constexpr double kDeg = kPi / 180.0;

}  // namespace armstudy::core
