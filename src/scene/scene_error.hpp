// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Errors of MuJoCo, OSMesa and image output.

#include <stdexcept>
#include <string>

namespace armstudy::scene {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A model file or generated MJCF that MuJoCo cannot load: bad input (exit code 2 at the
/// CLI), where other SceneErrors are runtime failures (exit 3). The message holds MuJoCo's
/// own text and the file.
class ModelError : public SceneError {
 public:
  using SceneError::SceneError;
};

/// A helper process (the frame helper) that made no progress within
/// sys::helper_timeout_seconds(): it was ended, and the case ends with this error (exit 3).
class HelperStuck : public SceneError {
 public:
  using SceneError::SceneError;
};

/// Installs mju_user_error / mju_user_warning handlers (once per process): MuJoCo errors
/// throw SceneError instead of exiting the process (the 2.2.2 default); warnings are
/// recorded and can be read with take_mujoco_warnings().
void install_mujoco_handlers();

/// Warnings MuJoCo raised since the last call (and clears them).
std::string take_mujoco_warnings();

}  // namespace armstudy::scene
