// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// What MuJoCo 2.2's URDF parser drops, read from the URDF with libxml2: each joint's
/// <limit effort velocity>, and the text MuJoCo is given, which keeps fixed links as
/// bodies (<mujoco><compiler fusestatic="false"/></mujoco>) so that the tip's frame is known.

#include <map>
#include <optional>
#include <string>

namespace armstudy::model_import {

struct UrdfJointLimit {
  std::optional<double> effort;    ///< N m (a revolute joint)
  std::optional<double> velocity;  ///< rad/s
};

struct UrdfText {
  std::string for_mujoco;                        ///< the URDF with fusestatic off
  std::map<std::string, UrdfJointLimit> limits;  ///< by joint name
};

/// Whether `bytes` is a URDF (its root element is <robot>); false for MJCF or anything else.
bool is_urdf(const std::string& bytes);

/// Parses a URDF. @throws ImportError (prefixed by `path`) on XML that does not parse or a
/// limit that is not a number >= 0.
UrdfText read_urdf(const std::string& path, const std::string& bytes);

}  // namespace armstudy::model_import
