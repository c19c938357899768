// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "model_import/mujoco_load.hpp"

#include <cstring>
#include <filesystem>

#include "model_import/imported_arm.hpp"
#include "model_import/mujoco_message.hpp"

namespace armstudy::model_import {
namespace {
// MuJoCo 2.2's default error handler exits the process: a thrown error instead (the scene
// library installs its own, which throws as well, once it is used)
void throw_error(const char* msg) { throw ImportError("MuJoCo error: " + mujoco_message(msg)); }
}  // namespace

ModelPtr load_mujoco_model(const std::string& path, const std::string& text) {
  if (!mju_user_error) mju_user_error = &throw_error;
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const std::string name = std::filesystem::path(path).filename().string();
  if (name.empty() || name.size() >= mjMAXVFSNAME ||
      mj_makeEmptyFileVFS(vfs.get(), name.c_str(), static_cast<int>(text.size())) != 0)
    throw ImportError(path + ": cannot give the model to MuJoCo (file name too long?)");
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), name.c_str())], text.data(), text.size());
  char err[1000] = "";
  mjModel* m = nullptr;
  try {
    m = mj_loadXML(path.c_str(), vfs.get(), err, sizeof err);
  } catch (...) {
    mj_deleteVFS(vfs.get());
    throw;
  }
  mj_deleteVFS(vfs.get());
  if (!m) {
    // MuJoCo's message spans lines: one line in a case error
    throw ImportError(path + ": MuJoCo could not load the model: " + mujoco_message(err));
  }
  return ModelPtr(m);
}

}  // namespace armstudy::model_import
