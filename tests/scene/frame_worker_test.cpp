// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The frame helper process (scene/frame_worker.hpp): it draws a scene's frames byte for byte
// as this process does, also after it is given back and loaded with another scene; a scene
// MuJoCo rejects, a missing helper program and a helper that dies leave the frames to this
// process with the same pixels; a strip on two processes is the strip on one.

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "scene/arm_scene.hpp"
#include "scene/frame_worker.hpp"
#include "scene/frames.hpp"
#include "scene/model_files.hpp"
#include "scene/png_writer.hpp"
#include "scene/scene_error.hpp"
#include "testing/tray_poses.hpp"

namespace armstudy::scene {
namespace {

// a pose of the tray arm (4 joints) at "time" t, moving
PoseSample tray_pose(double t) {
  PoseSample s = testing::tray_arm_pose(t);
  s.qd = core::JointVector::Constant(4, 0.2);
  return s;
}

std::vector<PoseSample> tray_poses(int n) {
  std::vector<PoseSample> out;
  for (int k = 0; k < n; ++k) out.push_back(tray_pose(0.07 * k));
  return out;
}

// the helper's request for pose s of renderer sr (as SceneRenderer::frames maps it)
WorkerPose worker_pose(const SceneRenderer& sr, const PoseSample& s, const std::string& label) {
  return {s.t, sr.map().jacobian() * s.q, sr.map().jacobian() * s.qd, {label, "right", "below"}};
}

// ARMSTUDY_FRAME_WORKER set for the scope, then as it was
class FrameWorkerEnv {
 public:
  explicit FrameWorkerEnv(const char* value) {
    if (const char* v = std::getenv("ARMSTUDY_FRAME_WORKER")) old_ = v;
    ::setenv("ARMSTUDY_FRAME_WORKER", value, 1);
  }
  ~FrameWorkerEnv() {
    if (old_)
      ::setenv("ARMSTUDY_FRAME_WORKER", old_->c_str(), 1);
    else
      ::unsetenv("ARMSTUDY_FRAME_WORKER");
  }

 private:
  std::optional<std::string> old_;
};

TEST(FrameWorker, TheHelperProgramOfThisBuildIsFound) {
  EXPECT_NE(frame_worker_program(), "");
  FrameWorkerEnv none("none");
  EXPECT_EQ(frame_worker_program(), "");
}

TEST(FrameWorker, DrawsThisProcesssFramesByteForByteAlsoAfterAnotherScene) {
  const RenderSettings rs;
  SceneRenderer here(default_tray_scene(), "tray", rs);
  const std::vector<PoseSample> poses = tray_poses(5);
  std::vector<WorkerPose> asks;
  std::vector<Image> ref;
  begin_replay(here.model());
  for (size_t k = 0; k < poses.size(); ++k) {
    asks.push_back(worker_pose(here, poses[k], "frame " + std::to_string(k)));
    ref.push_back(here.frame(poses[k], asks.back().labels));
  }
  std::string why;
  auto w = FrameWorker::acquire(default_tray_scene(), "tray", rs, &why);
  ASSERT_TRUE(w) << why;
  const int pid = w->pid();
  const std::vector<Image> got = w->draw(asks);
  ASSERT_EQ(got.size(), ref.size());
  for (size_t k = 0; k < ref.size(); ++k) EXPECT_TRUE(got[k].rgb == ref[k].rgb) << "frame " << k;
  // given back, loaded with another scene (the horizontal arm), then the tray again: the
  // same helper process, the same pixels
  FrameWorker::release(std::move(w));
  const ArmScene table = horizontal_arm_scene(default_tray_scene().chain, TableDecor{});
  auto other = FrameWorker::acquire(table, "table", rs, &why);
  ASSERT_TRUE(other) << why;
  EXPECT_EQ(other->pid(), pid);
  FrameWorker::release(std::move(other));
  auto again = FrameWorker::acquire(default_tray_scene(), "tray", rs, &why);
  ASSERT_TRUE(again) << why;
  const std::vector<Image> got2 = again->draw(asks);
  for (size_t k = 0; k < ref.size(); ++k) EXPECT_TRUE(got2[k].rgb == ref[k].rgb) << "frame " << k;
}

// a helper warmed with one scene (armstudy run starts its helpers so) is the one the next
// acquire takes, loaded with another scene, and draws it as this process does
TEST(FrameWorker, APrewarmedHelperIsTakenByTheNextAcquire) {
  const RenderSettings rs;
  FrameWorker::prewarm(default_horizontal_scene(), rs);
  SceneRenderer here(default_tray_scene(), "tray", rs);
  auto w = FrameWorker::acquire(default_tray_scene(), "tray", rs);
  ASSERT_TRUE(w);
  const PoseSample p = tray_pose(0.2);
  begin_replay(here.model());
  const Image ref = here.frame(p, {"t", "right", "below"});
  const std::vector<Image> got = w->draw({worker_pose(here, p, "t")});
  ASSERT_EQ(got.size(), 1u);
  EXPECT_TRUE(got[0].rgb == ref.rgb);
  FrameWorker::release(std::move(w));
}

TEST(FrameWorker, ASceneMuJoCoRejectsIsAnErrorOfTheFirstFrameAndSaysWhy) {
  ArmScene bad = default_tray_scene();
  bad.mjcf = "<mujoco><worldbody><body><geom type=\"nonsense\"/></body></worldbody></mujoco>";
  SceneRenderer here(default_tray_scene(), "tray", RenderSettings{});
  auto w = FrameWorker::acquire(bad, "bad scene", RenderSettings{});
  ASSERT_TRUE(w);
  try {
    w->draw({worker_pose(here, tray_pose(0.1), "t")});
    FAIL() << "a scene MuJoCo rejects was drawn";
  } catch (const SceneError& e) {
    const std::string why = e.what();
    EXPECT_NE(why.find("could not load the scene"), std::string::npos) << why;
    EXPECT_NE(why.find("bad scene"), std::string::npos) << why;
  }
}

TEST(FrameWorker, AHelperThatDiesIsAnErrorOfDraw) {
  SceneRenderer here(default_tray_scene(), "tray", RenderSettings{});
  auto w = FrameWorker::acquire(default_tray_scene(), "tray", RenderSettings{});
  ASSERT_TRUE(w);
  ASSERT_EQ(::kill(w->pid(), SIGKILL), 0);
  EXPECT_THROW(w->draw({worker_pose(here, tray_pose(0.1), "t")}), SceneError);
}

// a strip on two processes is the strip on one, byte for byte: with the helper, without a
// helper program (all frames here) and with a helper killed between two strips (its frames
// drawn here from then on)
TEST(FrameWorker, AStripOnTwoProcessesIsTheStripOnOne) {
  const std::vector<PoseSample> poses = tray_poses(7);
  SceneRenderer one(default_tray_scene(), "tray", RenderSettings{});
  one.set_strip_threads(1);
  const std::string ref = encode_png(one.strip(poses, "title", 3));
  {
    SceneRenderer two(default_tray_scene(), "tray", RenderSettings{});
    two.set_strip_threads(2);
    EXPECT_TRUE(encode_png(two.strip(poses, "title", 3)) == ref);
  }
  {
    FrameWorkerEnv none("none");
    SceneRenderer two(default_tray_scene(), "tray", RenderSettings{});
    two.set_strip_threads(2);
    EXPECT_TRUE(encode_png(two.strip(poses, "title", 3)) == ref);
  }
  {
    // a helper of this thread's pool (used once, given back), which the renderer takes
    auto w = FrameWorker::acquire(default_tray_scene(), "tray", RenderSettings{});
    ASSERT_TRUE(w);
    w->draw({worker_pose(one, poses[0], "t")});
    const int pid = w->pid();
    FrameWorker::release(std::move(w));
    SceneRenderer two(default_tray_scene(), "tray", RenderSettings{});
    two.set_strip_threads(2);
    EXPECT_TRUE(encode_png(two.strip(poses, "title", 3)) == ref);
    ASSERT_EQ(::kill(pid, SIGKILL), 0);
    EXPECT_TRUE(encode_png(two.strip(poses, "title", 3)) == ref);
  }
}

}  // namespace
}  // namespace armstudy::scene
