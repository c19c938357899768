// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Off-screen rendering of a MuJoCo model: one OSMesa context (taken from those earlier
/// renderers gave back, osmesa_context.hpp), one mjvScene and one mjrContext, reused for
/// every frame of a run (pitfalls found here: the off-screen size
/// comes from the model's <global offwidth offheight>, checked after mjr_setBuffer; no
/// shadows, reflections or skybox unless asked; offsamples set explicitly in the MJCF).

#include <memory>
#include <span>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>
#include <Eigen/Dense>

#include "cases/case_info.hpp"
#include "scene/image.hpp"
#include "scene/osmesa_context.hpp"

namespace armstudy::scene {

/// The world rectangle (m) in the model's x-y plane that a frame must show.
struct ViewBox {
  double x_min = -1, x_max = 1, y_min = -1, y_max = 1;
};

struct RenderSettings {
  cases::FrameSize frame;  ///< px
  bool shadows = false;    ///< shadow mapping (about 2.5x slower on llvmpipe)
  double margin = 0.06;    ///< fraction of the view box added on every side
};

/// Text drawn over a frame with MuJoCo's own font (mjr_overlay).
struct FrameLabels {
  std::string top_left;
  std::string top_right;
  std::string bottom_left;
};

class Renderer {
 public:
  /// Creates the OSMesa context and MuJoCo's scene and GPU context for `model`, with a
  /// camera above the x-y plane looking down -z (x right, y up) that frames `view`: the
  /// top view of a horizontal arm and the side view of a vertical one (the arm's plane is
  /// the model's x-y plane in both). @throws SceneError (OSMesa failures suggest
  /// --no-render; a model whose offwidth/offheight are smaller than the frame).
  Renderer(const mjModel* model, const RenderSettings& settings, const ViewBox& view);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Renders the model in the state of `data` (positions must be current: call
  /// mj_forward or mj_kinematics first), with `extra` geoms appended to the scene and
  /// `labels` drawn over it; reads the pixels back. @throws SceneError if the scene has no
  /// room for `extra`.
  Image render(mjData* data, const FrameLabels& labels = {}, std::span<const mjvGeom> extra = {});

  /// The geoms of the moving bodies in the state of `data` (for stroboscopic loci).
  std::vector<mjvGeom> dynamic_geoms(mjData* data);

  /// Pixel (x right, y down; px) where the world point p_W (m) appears in frames of this
  /// renderer (camera of the last render). Exact for MuJoCo's perspective projection.
  Eigen::Vector2d project(const Eigen::Vector3d& p_W) const;

  /// Metres per pixel in the plane z = 0.
  double metres_per_pixel() const;

  /// Frame size, px, and the GL renderer's name (e.g. "llvmpipe ...").
  int width() const { return settings_.frame.width; }
  int height() const { return settings_.frame.height; }
  const std::string& gl_renderer() const { return context_->renderer(); }

 private:
  const mjModel* model_;
  RenderSettings settings_;
  std::unique_ptr<OsmesaContext> context_;
  mjvScene scene_;
  mjvScene scratch_;
  mjrContext con_;
  mjvOption opt_;
  mjvCamera cam_;
  mjvGLCamera glcam_{};
  std::vector<unsigned char> pixels_;
  bool have_glcam_ = false;
};

/// A line segment geom (capsule) from a to b (m) of radius `radius`, colour rgba.
mjvGeom segment_geom(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius,
                     const float rgba[4]);

/// A sphere geom at p (m) of radius `radius`.
mjvGeom sphere_geom(const Eigen::Vector3d& p, double radius, const float rgba[4]);

}  // namespace armstudy::scene
