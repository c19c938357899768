// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Off-screen rendering: frames are not blank, the arm is where the kinematics says,
// rendering is deterministic, the grid is as wide as the captions say, and the OSMesa
// failure path suggests --no-render.

#include <gtest/gtest.h>

#include <GL/osmesa.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/ik2.hpp"
#include "core/kinematics.hpp"
#include "core/motion_program.hpp"
#include "scene/arm_scene.hpp"
#include "scene/frames.hpp"
#include "scene/model_files.hpp"
#include "scene/osmesa_context.hpp"
#include "scene/png_writer.hpp"
#include "scene/scene_error.hpp"
#include "testing/arms.hpp"
#include "testing/files.hpp"

namespace armstudy::scene {
namespace {

namespace fs = std::filesystem;

fs::path out_dir() {
  const fs::path d = testing::temp_path("scene_test");
  fs::create_directories(d);
  return d;
}

// the thesis arm carrying its payload along a line with a cycloidal program, configuration 1
struct LineMotion {
  core::PlanarChain chain = testing::thesis_arm();
  Eigen::Vector2d S{0.45, -0.15}, F{0.25, 0.35};
  double T = 1.0;
  PoseSample at(double t) const {
    const double L = (F - S).norm();
    const Eigen::Vector2d u = (F - S) / L;
    const core::ProgramSample p = core::evaluate_program(core::MotionProgram::kCycloidal, t, T, L);
    const auto ik = core::ik_2link_motion(0.4, 0.2, S + p.s * u, p.sd * u, p.sdd * u, 1);
    EXPECT_TRUE(ik.has_value());
    PoseSample s;
    s.t = t;
    s.q = core::JointVector(ik->q);
    s.qd = core::JointVector(ik->qd);
    return s;
  }
};

ArmScene line_scene(const LineMotion& m) {
  TableDecor d;
  d.task_start = m.S;
  d.task_end = m.F;
  return horizontal_arm_scene(m.chain, d);
}

double colour_distance(Rgb a, Rgb b) {
  return std::sqrt(std::pow(a.r - b.r, 2.0) + std::pow(a.g - b.g, 2.0) + std::pow(a.b - b.b, 2.0));
}

TEST(Renderer, FramesAreNotBlankAndConsecutiveFramesDiffer) {
  const LineMotion m;
  SceneRenderer sr(line_scene(m), "line", RenderSettings{});
  Image previous;
  for (int k = 0; k <= 4; ++k) {
    const Image img = sr.frame(m.at(0.25 * k), {time_label(0.25 * k), "", ""});
    ASSERT_EQ(img.width, 640);
    ASSERT_EQ(img.height, 480);
    const PixelStats st = pixel_stats(img);
    EXPECT_GT(st.mean, 120.0) << "a light table";
    EXPECT_GT(st.stddev, 10.0) << "something drawn on it";
    EXPECT_GT(st.non_background, 0.03);
    EXPECT_LT(st.non_background, 0.9);
    if (k > 0) {
      EXPECT_NE(img.rgb, previous.rgb) << "frame " << k;
    }
    previous = img;
  }
}

TEST(Renderer, PayloadAppearsWhereKinematicsPutsTheEndEffector) {
  const LineMotion m;
  SceneRenderer sr(line_scene(m), "line", RenderSettings{});
  const Rgb orange{245, 140, 20};
  for (int k = 0; k <= 4; ++k) {
    const PoseSample s = m.at(0.25 * k);
    const Image img = sr.frame(s, {});
    const Eigen::Vector2d tip = core::end_effector(m.chain, s.q);
    const Eigen::Vector2d px = sr.renderer().project(Eigen::Vector3d(tip.x(), tip.y(), 0));
    const Rgb c = img.at(static_cast<int>(px.x()), static_cast<int>(px.y()));
    EXPECT_LT(colour_distance(c, orange), 60.0)
        << "t " << s.t << " pixel (" << px.transpose() << ") is " << int(c.r) << "," << int(c.g)
        << "," << int(c.b);
    // and the root pedestal (dark) where the base is
    const Eigen::Vector2d root = sr.renderer().project(Eigen::Vector3d(0, 0, 0));
    const Rgb rc = img.at(static_cast<int>(root.x()), static_cast<int>(root.y()));
    EXPECT_LT(rc.r + rc.g + rc.b, 3 * 90) << "root pixel " << int(rc.r);
  }
}

// The grid the captions name ("grid 0.2 m" on the table, "grid 0.1 m" behind the tray):
// the lines' spacing measured in a frame, along a row of background near the bottom, against
// the frame's scale (the renderer's projection of 1 m), within 10 % (the plane lies a little
// below the arm, farther from the camera)
// the spacing of the vertical grid lines along row y, px (0 if fewer than four lines)
double line_spacing_px(const Image& img, int y) {
  std::vector<int> level(img.width);
  for (int x = 0; x < img.width; ++x) {
    const Rgb c = img.at(x, y);
    const bool grey = std::abs(c.r - c.g) < 12 && std::abs(c.g - c.b) < 16;
    level[x] = grey ? c.g : -1;
  }
  std::vector<int> sorted;
  for (int v : level)
    if (v >= 0) sorted.push_back(v);
  if (sorted.empty()) return 0;
  std::sort(sorted.begin(), sorted.end());
  const int background = sorted[sorted.size() * 3 / 4];
  std::vector<double> centres;
  for (int x = 0; x < img.width;) {
    if (level[x] < 0 || level[x] > background - 3) {
      ++x;
      continue;
    }
    int x1 = x;
    while (x1 + 1 < img.width && level[x1 + 1] >= 0 && level[x1 + 1] <= background - 3) ++x1;
    centres.push_back(0.5 * (x + x1));
    x = x1 + 1;
  }
  std::vector<double> gaps;
  for (size_t i = 1; i < centres.size(); ++i) gaps.push_back(centres[i] - centres[i - 1]);
  if (gaps.size() < 3) return 0;
  std::sort(gaps.begin(), gaps.end());
  return gaps[gaps.size() / 2];
}

// the grid's spacing in a frame, m: along the lowest row of background that crosses the
// vertical lines (a row on a horizontal line is dark all along), against the frame's scale
double grid_spacing_m(SceneRenderer& sr, const Image& img) {
  double px = 0;
  for (int y = img.height - 12; y > img.height / 2 && px == 0; --y) px = line_spacing_px(img, y);
  const double px_per_m = (sr.renderer().project(Eigen::Vector3d(1, 0, 0)) -
                           sr.renderer().project(Eigen::Vector3d(0, 0, 0)))
                              .norm();
  return px / px_per_m;
}

TEST(Renderer, TheGridIsAsWideAsTheCaptionsSay) {
  const LineMotion m;
  SceneRenderer table(line_scene(m), "line", RenderSettings{});
  const double on_table = grid_spacing_m(table, table.frame(m.at(0.0), {}));
  EXPECT_NEAR(on_table, kTableGridM, 0.1 * kTableGridM) << grid_caption(kTableGridM);
  const ArmScene tray = default_tray_scene();
  SceneRenderer wall(tray, "tray", RenderSettings{});
  PoseSample up;
  up.q = core::JointVector::Zero(tray.chain.num_links());
  up.q[0] = M_PI / 2;  // the arm up, the bottom rows background
  const double behind_tray = grid_spacing_m(wall, wall.frame(up, {}));
  EXPECT_NEAR(behind_tray, kWallGridM, 0.1 * kWallGridM) << grid_caption(kWallGridM);
  EXPECT_EQ(grid_caption(kTableGridM), "grid 0.2 m");
}

TEST(Renderer, SameCaseRendersToByteIdenticalPngs) {
  const LineMotion m;
  std::vector<PoseSample> samples;
  for (double t : even_times(0, 1, 6)) samples.push_back(m.at(t));
  std::string first;
  for (int run = 0; run < 2; ++run) {
    SceneRenderer sr(line_scene(m), "line", RenderSettings{});
    const std::string png = encode_png(sr.strip(samples, "cycloidal, configuration 1", 3));
    if (run == 0) {
      first = png;
      std::ofstream(out_dir() / "strip_line.png", std::ios::binary) << png;
    } else {
      EXPECT_TRUE(png == first) << "the second rendering differs";
    }
  }
}

// a renderer in a context another scene drew in before (take_context reuses it, with what
// llvmpipe compiled for it) draws the pixels of a renderer in a fresh context, byte for byte,
// shadows on and off; in turn that scene again in the reused context
TEST(Renderer, ReusedContextDrawsTheFramesOfAFreshOne) {
  const LineMotion m;
  const PoseSample pose = m.at(0.4);
  for (const bool shadows : {false, true}) {
    RenderSettings rs;
    rs.shadows = shadows;
    // hold every kept context so that the first renderer gets a fresh one
    std::vector<std::unique_ptr<OsmesaContext>> held;
    for (int k = 0; k < 8; ++k) held.push_back(take_context(rs.frame.width, rs.frame.height));
    OsmesaContext::release_current();
    Image fresh;
    {
      SceneRenderer sr(line_scene(m), "line", rs);
      fresh = sr.frame(pose, {"t = 0.400 s", "right", "bottom"});
    }
    for (auto& c : held) give_back_context(std::move(c));
    // another scene (the tray arm, other textures and lights) in the kept contexts
    for (int k = 0; k < 3; ++k) {
      SceneRenderer other(default_tray_scene(), "tray", rs);
      PoseSample p;
      p.q = core::JointVector::Constant(other.map().num_chain(), 0.3);
      EXPECT_GT(pixel_stats(other.frame(p, {"tray", "", ""})).stddev, 5.0);
    }
    SceneRenderer again(line_scene(m), "line", rs);
    const Image reused = again.frame(pose, {"t = 0.400 s", "right", "bottom"});
    EXPECT_TRUE(reused.rgb == fresh.rgb) << "shadows " << shadows;
  }
}

// a strip drawn on 2 threads (a twin renderer draws every other frame) is the strip drawn on
// one, byte for byte, also the second time (the twin is kept) and for an odd frame count
TEST(Renderer, StripOnTwoThreadsEqualsTheStripOnOne) {
  const LineMotion m;
  for (const int frames : {7, 16}) {
    std::vector<PoseSample> samples;
    for (double t : even_times(0, 1, frames)) samples.push_back(m.at(t));
    SceneRenderer one(line_scene(m), "line", RenderSettings{});
    one.set_strip_threads(1);
    const std::string ref = encode_png(one.strip(samples, "one thread", 3));
    SceneRenderer two(line_scene(m), "line", RenderSettings{});
    two.set_strip_threads(2);
    for (int run = 0; run < 2; ++run)
      EXPECT_TRUE(encode_png(two.strip(samples, "one thread", 3)) == ref)
          << frames << " frames, run " << run;
    // strip() places each frame as it arrives: the same image as tiling frames() afterwards
    std::vector<FrameLabels> labels(samples.size());
    for (size_t k = 0; k < samples.size(); ++k) labels[k].top_left = time_label(samples[k].t);
    labels[0].bottom_left = "one thread";
    EXPECT_TRUE(encode_png(tile(two.frames(samples, labels), 3, 8, Rgb{255, 255, 255})) == ref)
        << frames << " frames";
  }
}

TEST(Renderer, LocusDrawsOlderPosesFainterAndThePath) {
  const LineMotion m;
  SceneRenderer sr(line_scene(m), "line", RenderSettings{});
  std::vector<PoseSample> poses;
  for (double t : even_times(0, 1, 7)) poses.push_back(m.at(t));
  std::vector<Eigen::Vector2d> path;
  for (double t : even_times(0, 1, 60)) path.push_back(core::end_effector(m.chain, m.at(t).q));
  const Image img = sr.locus(poses, path, {}, {"locus", "", ""});
  write_png(out_dir() / "locus_line.png", img);
  // the path's midpoint is dark (it is drawn above the arm)
  const double top = 3 * 0.04 * 0.4;
  const Eigen::Vector2d mid = path[30];
  const Eigen::Vector2d pm = sr.renderer().project(Eigen::Vector3d(mid.x(), mid.y(), top));
  const Rgb c =
      img.at(static_cast<int>(std::lround(pm.x())), static_cast<int>(std::lround(pm.y())));
  EXPECT_LT(c.r + c.g + c.b, 3 * 100) << int(c.r) << "," << int(c.g) << "," << int(c.b);
  // around the first payload: a faint orange (blended toward white); around the last: full
  auto count_near = [&](const Eigen::Vector2d& p, auto pred) {
    int hits = 0;
    const Eigen::Vector2d centre = sr.renderer().project(Eigen::Vector3d(p.x(), p.y(), 0));
    const int rad = static_cast<int>(0.02 / sr.renderer().metres_per_pixel());
    for (int y = -rad; y <= rad; ++y)
      for (int x = -rad; x <= rad; ++x)
        if (pred(img.at(static_cast<int>(centre.x()) + x, static_cast<int>(centre.y()) + y)))
          ++hits;
    return hits;
  };
  auto faint_orange = [](Rgb q) {
    return q.r > 235 && q.g > 175 && q.g < 235 && q.b > 110 && q.b < q.g - 20;
  };
  auto full_orange = [](Rgb q) { return q.r > 200 && q.g > 100 && q.g < 175 && q.b < 70; };
  const Eigen::Vector2d first_tip = core::end_effector(m.chain, poses.front().q);
  const Eigen::Vector2d last_tip = core::end_effector(m.chain, poses.back().q);
  EXPECT_GT(count_near(first_tip, faint_orange), 10);
  EXPECT_EQ(count_near(first_tip, full_orange), 0);
  EXPECT_GT(count_near(last_tip, full_orange), 10);
}

TEST(Renderer, ShadowsOptionCastsShadowsOnTheTable) {
  const LineMotion m;
  RenderSettings with;
  with.shadows = true;
  SceneRenderer plain(line_scene(m), "line", RenderSettings{});
  SceneRenderer shadowed(line_scene(m), "line", with);
  const Image a = plain.frame(m.at(0.5), {});
  const Image b = shadowed.frame(m.at(0.5), {});
  write_png(out_dir() / "shadows.png", b);
  // the shadow darkens table pixels only: the arm's own pixels are alike
  int darker = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const Rgb p = a.at(x, y), q = b.at(x, y);
      if (p.r + p.g + p.b > 3 * 200 && q.r + q.g + q.b + 3 * 25 < p.r + p.g + p.b) ++darker;
    }
  EXPECT_GT(darker, 300) << "pixels of the table in shadow";
}

TEST(Renderer, TooLargeFrameForTheModelsOffscreenBufferIsASceneError) {
  const LineMotion m;
  TableDecor d;
  d.offscreen = {320, 240};
  try {
    SceneRenderer sr(horizontal_arm_scene(m.chain, d), "small", RenderSettings{});
    FAIL() << "no exception";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("offwidth"), std::string::npos) << e.what();
  }
}

TEST(OsmesaContext, FailureSuggestsNoRender) {
  try {
    OsmesaContext ctx(64, 64, 0x7777 /* no such OSMesa format */);
    FAIL() << "no exception";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("--no-render"), std::string::npos) << e.what();
  }
}

TEST(OsmesaContext, RunsLlvmpipeNeverSoftpipe) {
  OsmesaContext ctx(16, 16);
  EXPECT_NE(ctx.renderer().find("llvmpipe"), std::string::npos) << ctx.renderer();
}

}  // namespace
}  // namespace armstudy::scene
