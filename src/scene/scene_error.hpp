#pragma once
/// Errors of MuJoCo, OSMesa and image output.

#include <stdexcept>
#include <string>

namespace armstudy::scene {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Installs mju_user_error / mju_user_warning handlers (once per process): MuJoCo errors
/// throw SceneError instead of exiting the process (the 2.2.2 default); warnings are
/// recorded and can be read with take_mujoco_warnings().
void install_mujoco_handlers();

/// Warnings MuJoCo raised since the last call (and clears them).
std::string take_mujoco_warnings();

}  // namespace armstudy::scene
