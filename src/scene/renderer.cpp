// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include "scene/overlay_wrap.hpp"
#include "scene/phase_times.hpp"
#include "scene/scene_error.hpp"

namespace armstudy::scene {
namespace {
constexpr int kMaxGeom = 6000;

int font_scale(int height) {
  // large enough to read in print, where a frame is a third of the page wide
  if (height <= 400) return mjFONTSCALE_150;
  if (height <= 640) return mjFONTSCALE_200;
  if (height <= 960) return mjFONTSCALE_250;
  return mjFONTSCALE_300;
}
}  // namespace

Renderer::Renderer(const mjModel* model, const RenderSettings& s, const ViewBox& view)
    : model_(model), settings_(s) {
  install_mujoco_handlers();
  std::optional<PhaseScope> part(std::in_place, "context");
  context_ = take_context(s.frame.width, s.frame.height);
  part.emplace("mjr_context");
  mjv_defaultScene(&scene_);
  mjv_defaultScene(&scratch_);
  mjr_defaultContext(&con_);
  mjv_defaultOption(&opt_);
  mjv_defaultCamera(&cam_);
  mjv_makeScene(model, &scene_, kMaxGeom);
  mjv_makeScene(model, &scratch_, kMaxGeom);
  mjr_makeContext(model, &con_, font_scale(s.frame.height));
  mjr_setBuffer(mjFB_OFFSCREEN, &con_);
  part.reset();
  if (con_.currentBuffer != mjFB_OFFSCREEN) {
    mjr_freeContext(&con_);
    mjv_freeScene(&scene_);
    mjv_freeScene(&scratch_);
    throw SceneError(
        "MuJoCo's off-screen buffer is not available in the OSMesa context; run "
        "with --no-render");
  }
  if (con_.offWidth < s.frame.width || con_.offHeight < s.frame.height) {
    const std::string msg = "MuJoCo's off-screen buffer is " + std::to_string(con_.offWidth) +
                            " x " + std::to_string(con_.offHeight) + " px, smaller than the " +
                            std::to_string(s.frame.width) + " x " + std::to_string(s.frame.height) +
                            " px frame; expected <global offwidth offheight> of at least that";
    mjr_freeContext(&con_);
    mjv_freeScene(&scene_);
    mjv_freeScene(&scratch_);
    throw SceneError(msg);
  }
  // plain, fast, deterministic: no shadows unless asked, no reflection or skybox
  scene_.flags[mjRND_SHADOW] = s.shadows ? 1 : 0;
  scene_.flags[mjRND_REFLECTION] = 0;
  scene_.flags[mjRND_SKYBOX] = 0;
  // camera above the plane, looking down -z, x right and y up (azimuth 90, elevation -90)
  const double m = s.margin;
  const double w = (view.x_max - view.x_min) * (1 + 2 * m);
  const double h = (view.y_max - view.y_min) * (1 + 2 * m);
  const double aspect = static_cast<double>(s.frame.width) / s.frame.height;
  const double half_h = 0.5 * std::max(h, w / aspect);
  const double fovy = model->vis.global.fovy * mjPI / 180.0;
  cam_.type = mjCAMERA_FREE;
  cam_.lookat[0] = 0.5 * (view.x_min + view.x_max);
  cam_.lookat[1] = 0.5 * (view.y_min + view.y_max);
  cam_.lookat[2] = 0;
  cam_.azimuth = 90;
  cam_.elevation = -90;
  cam_.distance = half_h / std::tan(fovy / 2);
  pixels_.resize(static_cast<size_t>(s.frame.width) * s.frame.height * 4);
}

Renderer::~Renderer() {
  // MuJoCo frees its GL objects in the current context: this renderer's
  try {
    context_->make_current();
  } catch (const SceneError&) {
    context_.reset();  // not current: nothing of it can be freed or reused
  }
  if (context_) mjr_freeContext(&con_);
  mjv_freeScene(&scene_);
  mjv_freeScene(&scratch_);
  if (context_) give_back_context(std::move(context_));
}

// (over 60 lines, kept whole: one frame's GL phases in order, update, draw, labels, finish
// and readback, each timed by its PhaseScope)
Image Renderer::render(mjData* data, const FrameLabels& labels, std::span<const mjvGeom> extra) {
  PhaseScope phase("gl");
  context_->make_current();
  std::optional<PhaseScope> part(std::in_place, "update");
  mjv_updateScene(model_, data, &opt_, nullptr, &cam_, mjCAT_ALL, &scene_);
  if (scene_.ngeom + static_cast<int>(extra.size()) > scene_.maxgeom)
    throw SceneError("the scene has room for " + std::to_string(scene_.maxgeom) + " geoms, " +
                     std::to_string(scene_.ngeom + extra.size()) + " asked");
  for (const mjvGeom& g : extra) scene_.geoms[scene_.ngeom++] = g;
  // mono rendering draws the average of the two eye cameras (mjr_render)
  glcam_ = mjv_averageCamera(scene_.camera, scene_.camera + 1);
  have_glcam_ = true;
  const mjrRect viewport{0, 0, settings_.frame.width, settings_.frame.height};
  part.emplace("draw");
  mjr_setBuffer(mjFB_OFFSCREEN, &con_);
  mjr_render(viewport, &scene_, &con_);
  part.emplace("labels");
  // labels wrapped to the frame: MuJoCo cuts a line off at the frame's edge; the top-left
  // label leaves room for the top-right one, which shares its rows
  const std::span<const int> glyphs(con_.charWidth, 127);
  const int pad = 3 * con_.charWidth[static_cast<int>('M')];
  const int width = settings_.frame.width;
  const std::string top_right = wrap_overlay_text(labels.top_right, glyphs, width / 2 - pad);
  const int right_px = top_right.empty() ? 0 : overlay_text_width(top_right, glyphs) + pad;
  const std::string top_left = wrap_overlay_text(labels.top_left, glyphs, width - right_px - pad);
  const std::string bottom_left = wrap_overlay_text(labels.bottom_left, glyphs, width - pad);
  if (!top_left.empty() || !top_right.empty())
    mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, viewport, top_left.c_str(), nullptr, &con_);
  if (!top_right.empty())
    mjr_overlay(mjFONT_NORMAL, mjGRID_TOPRIGHT, viewport, top_right.c_str(), nullptr, &con_);
  if (!bottom_left.empty())
    mjr_overlay(mjFONT_NORMAL, mjGRID_BOTTOMLEFT, viewport, bottom_left.c_str(), nullptr, &con_);
  // llvmpipe rasterises when the frame is finished: "finish" is the drawing, "readback" the copy
  part.emplace("finish");
  glFinish();
  part.emplace("readback");
  const int w = settings_.frame.width, h = settings_.frame.height;
  Image img(w, h);
  if (con_.offSamples == 0) {
    // the colour buffer as it is stored (RGBA: a copy, where RGB converts pixel by pixel),
    // alpha dropped and rows flipped here (OpenGL rows run bottom-up): mjr_readPixels' bytes
    glBindFramebuffer(GL_READ_FRAMEBUFFER, con_.offFBO);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels_.data());
    for (int y = 0; y < h; ++y) {
      const unsigned char* in = &pixels_[static_cast<size_t>(h - 1 - y) * w * 4];
      std::uint8_t* out = &img.rgb[static_cast<size_t>(y) * w * 3];
      for (int x = 0; x < w; ++x, in += 4, out += 3) {
        out[0] = in[0];
        out[1] = in[1];
        out[2] = in[2];
      }
    }
  } else {
    mjr_readPixels(pixels_.data(), nullptr, viewport, &con_);
    const size_t row = static_cast<size_t>(w) * 3;
    for (int y = 0; y < h; ++y) std::memcpy(&img.rgb[y * row], &pixels_[(h - 1 - y) * row], row);
  }
  return img;
}

std::vector<mjvGeom> Renderer::dynamic_geoms(mjData* data) {
  mjv_updateScene(model_, data, &opt_, nullptr, &cam_, mjCAT_DYNAMIC, &scratch_);
  return std::vector<mjvGeom>(scratch_.geoms, scratch_.geoms + scratch_.ngeom);
}

Eigen::Vector2d Renderer::project(const Eigen::Vector3d& p) const {
  if (!have_glcam_) throw SceneError("Renderer::project before the first render");
  const Eigen::Vector3d pos(glcam_.pos[0], glcam_.pos[1], glcam_.pos[2]);
  const Eigen::Vector3d fwd(glcam_.forward[0], glcam_.forward[1], glcam_.forward[2]);
  const Eigen::Vector3d up(glcam_.up[0], glcam_.up[1], glcam_.up[2]);
  const Eigen::Vector3d right = fwd.cross(up);
  const Eigen::Vector3d v = p - pos;
  const double z = v.dot(fwd);
  // glFrustum(center -/+ halfwidth, bottom, top, near) as in mjr_render
  const double aspect = static_cast<double>(settings_.frame.width) / settings_.frame.height;
  const double halfwidth = 0.5 * aspect * (glcam_.frustum_top - glcam_.frustum_bottom);
  const double xn = v.dot(right) * glcam_.frustum_near / z;
  const double yn = v.dot(up) * glcam_.frustum_near / z;
  const double ndc_x = (xn - glcam_.frustum_center) / halfwidth;
  const double ndc_y = (2 * yn - glcam_.frustum_top - glcam_.frustum_bottom) /
                       (glcam_.frustum_top - glcam_.frustum_bottom);
  return {0.5 * (ndc_x + 1) * settings_.frame.width, 0.5 * (1 - ndc_y) * settings_.frame.height};
}

double Renderer::metres_per_pixel() const {
  const double fovy = model_->vis.global.fovy * mjPI / 180.0;
  return 2 * cam_.distance * std::tan(fovy / 2) / settings_.frame.height;
}

mjvGeom segment_geom(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius,
                     const float rgba[4]) {
  mjvGeom g;
  mjv_initGeom(&g, mjGEOM_CAPSULE, nullptr, nullptr, nullptr, rgba);
  mjv_makeConnector(&g, mjGEOM_CAPSULE, radius, a.x(), a.y(), a.z(), b.x(), b.y(), b.z());
  g.category = mjCAT_DECOR;
  return g;
}

mjvGeom sphere_geom(const Eigen::Vector3d& p, double radius, const float rgba[4]) {
  mjvGeom g;
  const mjtNum size[3] = {radius, radius, radius};
  const mjtNum pos[3] = {p.x(), p.y(), p.z()};
  mjv_initGeom(&g, mjGEOM_SPHERE, size, pos, nullptr, rgba);
  g.category = mjCAT_DECOR;
  return g;
}

}  // namespace armstudy::scene
