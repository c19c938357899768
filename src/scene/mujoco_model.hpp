// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// RAII ownership of an mjModel loaded from MJCF text and its mjData.

#include <memory>
#include <string>

#include <mujoco/mujoco.h>

namespace armstudy::scene {

class MujocoModel {
 public:
  /// Compiles MJCF text (through MuJoCo's virtual file system; nothing touches disk).
  /// `source` names the model in error messages (e.g. the case file or "models/arm.xml").
  /// @throws ModelError (a SceneError) with MuJoCo's message and `source`.
  MujocoModel(const std::string& mjcf, const std::string& source);
  /// Loads an MJCF file. @throws ModelError (a SceneError) with MuJoCo's message and the
  /// file name (a missing file included).
  static MujocoModel from_file(const std::string& path);

  const mjModel* model() const { return model_.get(); }
  mjModel* model() { return model_.get(); }
  mjData* data() { return data_.get(); }
  const mjData* data() const { return data_.get(); }

 private:
  MujocoModel() = default;
  struct ModelDeleter {
    void operator()(mjModel* m) const { mj_deleteModel(m); }
  };
  struct DataDeleter {
    void operator()(mjData* d) const { mj_deleteData(d); }
  };
  std::unique_ptr<mjModel, ModelDeleter> model_;
  std::unique_ptr<mjData, DataDeleter> data_;
};

}  // namespace armstudy::scene
