// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// A headless OpenGL context from OSMesa (llvmpipe), made current on the calling thread.
/// MuJoCo renders into its own off-screen framebuffer inside this context.

#include <memory>
#include <string>
#include <vector>

namespace armstudy::scene {

class OsmesaContext {
 public:
  /// Creates an RGBA context with a 24-bit depth and 8-bit stencil buffer and makes it
  /// current with a width x height (px) window buffer. Sets GALLIUM_DRIVER=llvmpipe unless
  /// the environment sets it (softpipe is ~20x slower); LP_NUM_THREADS is left to the
  /// environment. `format` is the OSMesa pixel format (OSMESA_RGBA unless testing).
  /// @throws SceneError that names the cause and suggests --no-render when OSMesa cannot
  /// create or bind the context, or when the GL renderer is softpipe.
  OsmesaContext(int width, int height, unsigned format = 0);
  ~OsmesaContext();
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  /// Makes this context current on the calling thread again. @throws SceneError.
  void make_current();
  /// Makes no context current on the calling thread (so that another thread may take it).
  static void release_current();
  int width() const { return width_; }
  int height() const { return height_; }
  /// GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  const std::string& renderer() const { return renderer_; }
  /// GL_VERSION, with the Mesa version, e.g. "4.5 (Compatibility Profile) Mesa 22.3.6".
  const std::string& version() const { return version_; }

 private:
  void* ctx_ = nullptr;  // OSMesaContext
  std::vector<unsigned char> buffer_;
  int width_ = 0, height_ = 0;
  std::string renderer_;
  std::string version_;
};

/// A context of width x height px, current on the calling thread: one a renderer gave back
/// (give_back_context) if there is one of that size, else a new one. A context keeps what
/// llvmpipe compiled for it (MuJoCo's fixed-function shaders, ~70 ms per new context on
/// mjr_makeContext), so a reused one makes the next renderer's MuJoCo context in ~1 ms.
/// The caller must leave no MuJoCo object in it when giving it back (mjr_freeContext).
/// Thread-safe. @throws SceneError as OsmesaContext.
std::unique_ptr<OsmesaContext> take_context(int width, int height);

/// Gives `context` back for take_context (it stops being current on this thread); at most a
/// few are kept, the others destroyed. Thread-safe.
void give_back_context(std::unique_ptr<OsmesaContext> context);

/// GL_RENDERER and GL_VERSION of the contexts this process created (for provenance).
struct GlInfo {
  std::string renderer;  ///< empty when no context was created
  std::string version;
};

/// The renderer and version of the last OsmesaContext created in this process (thread-safe).
GlInfo gl_info();

}  // namespace armstudy::scene
