// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// A planar arm read from a robot description (URDF or MJCF) through MuJoCo's own parser
/// (mj_loadXML), so that what armstudy studies is exactly what MuJoCo loads.
///
/// The model must be one planar chain: its moving joints hinges, one per body, in one chain
/// from the world, their axes parallel and pointing the same way. The plane is the one
/// normal to the axes through the first joint; the joint coordinates are the model's own
/// (qpos, zero at the model's reference pose, where the links must lie in one line). Link
/// i is moving body i with every body fixed to it (a fixed body after the last joint is the
/// payload); its length runs from joint i to joint i + 1, the last one's to the tip (a
/// site named `tip`, else the origin of the last fixed body after the last joint). Gravity
/// is the model's (MuJoCo's default for a URDF), projected into the plane.

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/planar_chain.hpp"

namespace armstudy::model_import {

/// A model that is not a planar chain armstudy can study, or that MuJoCo cannot load. The
/// message names the joint or body, what was expected, and the file.
class ImportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One per-joint limit read from the model, and where it was read.
struct ModelLimit {
  double value = 0;  ///< >= 0 (a symmetric bound)
  std::string from;  ///< e.g. "<limit effort> of joint 'j1'"
};

/// A joint range read from the model.
struct ModelRange {
  double lower = 0, upper = 0;  ///< rad
  std::string from;
};

struct ImportedArm {
  core::PlanarChain chain;               ///< validated (core::make_chain)
  std::string path;                      ///< the file as the case names it (set by the case loader)
  std::string format;                    ///< "URDF" or "MJCF"
  std::string model_name;                ///< MuJoCo's model name (the URDF robot's name)
  std::vector<std::string> joint_names;  ///< chain joint i's name in the model
  /// The plane in the model's world frame: its normal (the joints' axis) and the model
  /// directions of the chain's x and y axes; the chain's origin is the model's origin
  /// projected into the plane.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d x_axis = Eigen::Vector3d::UnitX();
  Eigen::Vector3d y_axis = Eigen::Vector3d::UnitY();
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  ///< m/s^2, the model's, in 3D
  std::string tip;                                    ///< what the tip is (a site, a body)
  /// Per chain joint: the model's torque bound (N m), velocity bound (rad/s) and range.
  std::vector<std::optional<ModelLimit>> torque, velocity;
  std::vector<std::optional<ModelRange>> range;

  /// A few lines on how the plane and gravity were read (for model.xml and the report).
  std::string plane_text() const;
};

/// Reads the model `bytes` (the file `path`, already read under the input rules) through
/// MuJoCo: a URDF (root <robot>) or an MJCF (root <mujoco>). URDF effort and velocity
/// limits, which MuJoCo 2.2 does not keep, are read from the same bytes with libxml2.
/// @throws ImportError.
ImportedArm import_arm(const std::string& path, const std::string& bytes);

}  // namespace armstudy::model_import
