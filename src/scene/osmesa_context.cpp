// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/osmesa_context.hpp"

#include <GL/osmesa.h>

#include <cstdlib>
#include <mutex>

#include "scene/scene_error.hpp"

namespace armstudy::scene {
namespace {
std::mutex g_info_mutex;
GlInfo g_info;

constexpr const char* kNoRender =
    "; frames cannot be rendered on this machine: run with --no-render to produce everything "
    "else";
}  // namespace

OsmesaContext::OsmesaContext(int width, int height, unsigned format)
    : width_(width), height_(height) {
  if (width <= 0 || height <= 0)
    throw SceneError("OSMesa window size " + std::to_string(width) + " x " +
                     std::to_string(height) + " px should be positive" + kNoRender);
  // llvmpipe, never softpipe, unless the user chose a driver
  ::setenv("GALLIUM_DRIVER", "llvmpipe", 0);
  const GLenum fmt = format == 0 ? OSMESA_RGBA : static_cast<GLenum>(format);
  OSMesaContext ctx = OSMesaCreateContextExt(fmt, 24, 8, 0, nullptr);
  if (!ctx) throw SceneError(std::string("OSMesa could not create an OpenGL context") + kNoRender);
  ctx_ = ctx;
  buffer_.resize(static_cast<size_t>(width) * height * 4);
  make_current();
  const GLubyte* r = glGetString(GL_RENDERER);
  renderer_ = r ? reinterpret_cast<const char*>(r) : "";
  if (renderer_.find("softpipe") != std::string::npos) {
    OSMesaDestroyContext(ctx);
    ctx_ = nullptr;
    throw SceneError("OSMesa runs the softpipe renderer ('" + renderer_ +
                     "'), about 20x slower than llvmpipe; unset GALLIUM_DRIVER" + kNoRender);
  }
  const GLubyte* v = glGetString(GL_VERSION);
  version_ = v ? reinterpret_cast<const char*>(v) : "";
  std::lock_guard<std::mutex> lock(g_info_mutex);
  g_info = {renderer_, version_};
}

GlInfo gl_info() {
  std::lock_guard<std::mutex> lock(g_info_mutex);
  return g_info;
}

void OsmesaContext::release_current() {
  OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
}

namespace {
// contexts given back, kept for the process's life (never destroyed at exit, when Mesa may
// already be gone)
constexpr size_t kKeptContexts = 4;
std::mutex g_pool_mutex;
std::vector<std::unique_ptr<OsmesaContext>>& pool() {
  static auto* p = new std::vector<std::unique_ptr<OsmesaContext>>();
  return *p;
}
}  // namespace

std::unique_ptr<OsmesaContext> take_context(int width, int height) {
  std::unique_ptr<OsmesaContext> c;
  {
    std::lock_guard<std::mutex> lock(g_pool_mutex);
    auto& p = pool();
    for (auto it = p.begin(); it != p.end(); ++it)
      if ((*it)->width() == width && (*it)->height() == height) {
        c = std::move(*it);
        p.erase(it);
        break;
      }
  }
  if (!c) return std::make_unique<OsmesaContext>(width, height);
  c->make_current();
  return c;
}

void give_back_context(std::unique_ptr<OsmesaContext> context) {
  if (!context) return;
  OsmesaContext::release_current();
  std::lock_guard<std::mutex> lock(g_pool_mutex);
  if (pool().size() < kKeptContexts) pool().push_back(std::move(context));
}

void OsmesaContext::make_current() {
  if (!OSMesaMakeCurrent(static_cast<OSMesaContext>(ctx_), buffer_.data(), GL_UNSIGNED_BYTE, width_,
                         height_))
    throw SceneError(std::string("OSMesa could not make its context current") + kNoRender);
}

OsmesaContext::~OsmesaContext() {
  if (ctx_) OSMesaDestroyContext(static_cast<OSMesaContext>(ctx_));
}

}  // namespace armstudy::scene
