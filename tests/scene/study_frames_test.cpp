// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Every study's frames, rendered from the study's own (small) solution: the files are
// written, not blank, and the arm is where the kinematics says.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "core/ik2.hpp"
#include "core/kinematics.hpp"
#include "core/motion_program.hpp"
#include "scene/animation.hpp"
#include "scene/arm_scene.hpp"
#include "scene/frames.hpp"
#include "scene/pendulum_frames.hpp"
#include "scene/placement_frames.hpp"
#include "scene/png_writer.hpp"
#include "scene/study_frames.hpp"
#include "scene/throwing_frames.hpp"
#include "scene/time_optimal_frames.hpp"
#include "studies/placement/solve.hpp"
#include "testing/arms.hpp"
#include "testing/files.hpp"

namespace armstudy::scene {
namespace {

namespace fs = std::filesystem;

fs::path out_dir(const std::string& name) {
  const fs::path d = testing::temp_path("scene_test") / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void expect_images(const fs::path& dir, const std::vector<std::string>& files, size_t count) {
  ASSERT_EQ(files.size(), count);
  for (const std::string& f : files) {
    const Image img = read_png(dir / f);
    const PixelStats st = pixel_stats(img);
    EXPECT_GT(st.mean, 100.0) << f;
    EXPECT_GT(st.stddev, 8.0) << f;
    EXPECT_GT(st.non_background, 0.01) << f;
  }
}

bool reddish(Rgb c) { return c.r > 150 && c.g < 90 && c.b < 90; }

TEST(StudyFrames, PendulumSnapshotsShowTheBallWhereKinematicsPutsIt) {
  studies::PendulumSpec spec = studies::default_pendulum_spec();
  spec.rtol = spec.atol = 1e-9;
  const studies::PendulumResult r = studies::solve_pendulum(spec);
  ASSERT_EQ(r.status, studies::Status::kSolved) << r.message;
  const fs::path dir = out_dir("pendulum");
  cases::RenderOptions o;
  Rendered rendered = render_pendulum_frames(spec, r, o, dir);
  expect_images(dir, rendered.frames, 2);
  EXPECT_GE(r.snapshot_index.size(), 15u);  // 2 s every 0.13 s

  // its animation comes back as a value (the run lists it in results.json from that): the
  // folder holds the frames and the animation's sprite, still and video, nothing else
  const std::vector<Animation> anims = finish_animations(rendered.animations);
  ASSERT_EQ(anims.size(), 1u);
  const Animation& a = anims[0];
  EXPECT_EQ(a.name, "pendulum");
  EXPECT_EQ(a.sprite, "pendulum_anim.png");
  EXPECT_EQ(a.still, "pendulum_still.png");
  EXPECT_EQ(a.frames, animation_frames(a.duration_s));
  EXPECT_NEAR(a.duration_s, r.t.back() - r.t.front(), 1e-12);
  EXPECT_NE(a.video.empty(), a.note.empty());  // a video, or a note saying why there is none
  std::set<std::string> expected(rendered.frames.begin(), rendered.frames.end());
  expected.insert({a.sprite, a.still});
  if (!a.video.empty()) expected.insert(a.video);
  std::set<std::string> found;
  for (const auto& e : fs::directory_iterator(dir)) found.insert(e.path().filename().string());
  EXPECT_EQ(found, expected);
  EXPECT_EQ(read_png(dir / a.sprite).width, a.columns * a.frame_width);

  // the ball is red at its projected centre in a frame of the same scene
  const core::PlanarChain chain = studies::make_tray_arm(spec.arm);
  TrayDecor d;
  d.ball_radius = spec.arm.rb;
  SceneRenderer sr(tray_arm_scene(chain, d), "pendulum", RenderSettings{});
  for (int k : {0, 5, 10}) {
    const int i = r.snapshot_index[k];
    const Image img = sr.frame({r.t[i], r.q[i], r.qd[i]}, {});
    const Eigen::Vector2d b = r.ball[i];
    // a point of the ball beside its white stripe
    const Eigen::Vector2d px = sr.renderer().project(Eigen::Vector3d(b.x(), b.y(), 0));
    int red = 0;
    for (int dy = -6; dy <= 6; ++dy)
      for (int dx = -6; dx <= 6; ++dx)
        red += reddish(img.at(static_cast<int>(px.x()) + dx, static_cast<int>(px.y()) + dy));
    EXPECT_GT(red, 20) << "snapshot " << k;
  }
}

TEST(StudyFrames, PlacementOptimaOfBothConfigurations) {
  studies::placement::Spec spec;
  spec.chain = testing::thesis_arm();
  spec.length = 0.5 * 4 * std::sqrt(0.4 * 0.2);
  spec.programs = {core::MotionProgram::kCycloidal};
  spec.nx_s = 12;
  spec.phi_step = 6 * core::kPi / 180;
  spec.samples = 101;
  spec.map_nx = 20;
  spec.map_ny = 10;
  spec.refine = false;
  spec.threads = 1;
  const auto r = studies::placement::solve(spec);
  ASSERT_EQ(r.status, studies::Status::kSolved) << r.message;
  int found = 0;
  for (const auto& pc : r.cases) found += pc.found;
  ASSERT_EQ(found, 2);
  const fs::path dir = out_dir("placement");
  expect_images(dir, render_placement_frames(spec, r, cases::RenderOptions{}, dir).frames, 4);
}

TEST(StudyFrames, ThrowingLocusWithTheFlightAfterRelease) {
  studies::ThrowingSpec spec;
  const studies::ThrowSetup setup = studies::make_throw_setup(spec);
  studies::ThrowingResult r;
  const auto profile = studies::eq8_profile(spec.start, Eigen::Vector2d::Zero(), spec.release,
                                            spec.release_rate, spec.tf, spec.stages);
  r.idp = studies::record_motion(setup, spec, profile);
  ASSERT_GE(r.idp.series.t.size(), 10u);
  const core::PlanarChain chain = studies::make_tray_arm(spec.arm);
  const core::JointVector& q = r.idp.series.q.back();
  const core::JointVector& qd = r.idp.series.qd.back();
  r.idp_flight = studies::ballistic_flight(studies::ball_position(chain, q),
                                           studies::ball_velocity(chain, q, qd), spec.arm.gravity,
                                           spec.landing_height);
  const fs::path dir = out_dir("throwing");
  expect_images(
      dir, render_throwing_frames(spec, r, cases::RenderOptions{}, dir).frames,
      r.idp_flight.path.size() >= 2 ? 4 : 3);  // strip, locus, close-up at release, flight
}

// the renderer's input only (the solver is tested by its own engineer): a motion along the
// path at equal time steps, as Result.motion_* hold it
TEST(StudyFrames, TimeOptimalMotionAtEqualTimeSteps) {
  studies::time_optimal::Spec spec;
  spec.chain = studies::time_optimal::default_arm();
  const Eigen::Vector2d S(0.7, -0.2), F(0.2, 0.6);
  studies::time_optimal::Result r;
  r.status = studies::Status::kSolved;
  const int n = 41;
  r.motion_q.resize(2, n);
  r.motion_p.resize(2, n);
  r.path_p.resize(2, 2);
  r.path_p << S.x(), F.x(), S.y(), F.y();
  for (int k = 0; k < n; ++k) {
    const double t = 0.8 * k / (n - 1);
    const auto p = core::evaluate_program(core::MotionProgram::kCycloidal, t, 0.8, (F - S).norm());
    const Eigen::Vector2d x = S + p.s * (F - S).normalized();
    const auto q = core::ik_2link(0.5, 0.4, x, 1);
    ASSERT_TRUE(q.has_value());
    r.motion_t.push_back(t);
    r.motion_s.push_back(p.s);
    r.motion_q.col(k) = *q;
    r.motion_p.col(k) = x;
  }
  const fs::path dir = out_dir("time_optimal");
  const auto files = render_time_optimal_frames(spec, r, cases::RenderOptions{}, dir).frames;
  expect_images(dir, files, 2);
  // six frames, three per row
  const Image strip = read_png(dir / files[0]);
  EXPECT_EQ(strip.width, 3 * 640 + 4 * 8);
  EXPECT_EQ(strip.height, 2 * 480 + 3 * 8);
}

}  // namespace
}  // namespace armstudy::scene
