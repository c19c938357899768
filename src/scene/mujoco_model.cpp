// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/mujoco_model.hpp"

#include <cstring>
#include <mutex>

#include "model_import/mujoco_message.hpp"
#include "scene/scene_error.hpp"

namespace armstudy::scene {
namespace {
std::mutex g_warn_mu;
std::string g_warnings;
void on_error(const char* msg) {
  throw SceneError("MuJoCo error: " + model_import::mujoco_message(msg));
}
void on_warning(const char* msg) {
  std::lock_guard<std::mutex> lock(g_warn_mu);
  g_warnings += std::string(msg) + "\n";
}
}  // namespace

void install_mujoco_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    mju_user_error = &on_error;
    mju_user_warning = &on_warning;
  });
}

std::string take_mujoco_warnings() {
  std::lock_guard<std::mutex> lock(g_warn_mu);
  std::string w;
  w.swap(g_warnings);
  return w;
}

MujocoModel::MujocoModel(const std::string& mjcf, const std::string& source) {
  install_mujoco_handlers();
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* name = "armstudy_model.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), name, static_cast<int>(mjcf.size())) != 0)
    throw SceneError(source + ": cannot create MuJoCo's virtual file");
  const int i = mj_findFileVFS(vfs.get(), name);
  std::memcpy(vfs->filedata[i], mjcf.data(), mjcf.size());
  char err[1000] = "";
  mjModel* m = mj_loadXML(name, vfs.get(), err, sizeof err);
  mj_deleteVFS(vfs.get());
  if (!m)
    throw ModelError(source +
                     ": MuJoCo could not load the model: " + model_import::mujoco_message(err));
  model_.reset(m);
  data_.reset(mj_makeData(m));
  if (!data_) throw SceneError(source + ": MuJoCo could not allocate mjData");
}

MujocoModel MujocoModel::from_file(const std::string& path) {
  install_mujoco_handlers();
  char err[1000] = "";
  mjModel* m = mj_loadXML(path.c_str(), nullptr, err, sizeof err);
  if (!m)
    throw ModelError(path +
                     ": MuJoCo could not load the model: " + model_import::mujoco_message(err));
  MujocoModel out;
  out.model_.reset(m);
  out.data_.reset(mj_makeData(m));
  return out;
}

}  // namespace armstudy::scene
