// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Where a study's arm and its limits came from: the case's own YAML, or a robot
/// description (URDF or MJCF) that `arm: {model: FILE}` names. Plain text for model.xml and
/// the report; the study computes nothing from it.

#include <string>
#include <vector>

namespace armstudy::studies {

struct ArmOrigin {
  std::string model;   ///< the model file as the case names it; empty: the case's `arm.links`
  std::string format;  ///< "URDF" or "MJCF"
  std::string name;    ///< the model's own name
  std::string plane;   ///< how the plane and gravity were read (a sentence)
  std::string tip;     ///< what marks the tip
  std::vector<std::string> joint_names;  ///< the model's name of each chain joint
  /// One line per limit the study used: "<key>: <value> from <where>" (the case, the model
  /// or the study's default).
  std::vector<std::string> limits;

  bool from_model() const { return !model.empty(); }

  /// The lines results.json and the page show: the file and its plane, then the limits.
  std::vector<std::string> lines() const {
    std::vector<std::string> out{"arm read from " + model + " (" + format + ", model '" + name +
                                 "') through MuJoCo's parser; solved in " + plane +
                                 "; the tip is " + tip};
    out.insert(out.end(), limits.begin(), limits.end());
    return out;
  }
};

}  // namespace armstudy::studies
