// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// A MuJoCo model compiled from bytes already read (through MuJoCo's virtual file system,
/// under the file's own name, so that its mesh files are looked up beside it).

#include <memory>
#include <string>

#include <mujoco/mujoco.h>

namespace armstudy::model_import {

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;
using DataPtr = std::unique_ptr<mjData, DataDeleter>;

/// Compiles `text` (MJCF or URDF) as the file `path`. @throws ImportError with MuJoCo's
/// message and the path.
ModelPtr load_mujoco_model(const std::string& path, const std::string& text);

}  // namespace armstudy::model_import
