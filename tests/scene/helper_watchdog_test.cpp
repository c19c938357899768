// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Every helper process is watched (sys::helper_timeout_seconds, ARMSTUDY_HELPER_TIMEOUT_S):
// a frame helper or an ffmpeg that stops taking input, answering or ending is killed within
// the timeout. A stuck frame helper ends the strip with an error naming it (the run: exit
// 3); a stuck or silent ffmpeg leaves the video out with a note saying why. Before, the run
// waited on them for ever ("31 % placement sweep" for hours) or failed with "cannot rename
// ...mp4.tmp.mp4".

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <thread>

#include "scene/animation.hpp"
#include "scene/arm_scene.hpp"
#include "scene/frames.hpp"
#include "scene/png_writer.hpp"
#include "scene/scene_error.hpp"
#include "scene/study_frames.hpp"
#include "testing/files.hpp"
#include "testing/tray_poses.hpp"

namespace armstudy::scene {
namespace {
namespace fs = std::filesystem;

// an environment variable set for the scope, then as it was
class EnvFor {
 public:
  EnvFor(const char* name, const std::string& value) : name_(name) {
    if (const char* v = std::getenv(name)) old_ = v;
    ::setenv(name, value.c_str(), 1);
  }
  ~EnvFor() {
    if (old_)
      ::setenv(name_, old_->c_str(), 1);
    else
      ::unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

fs::path fresh(const std::string& name) {
  const fs::path d = testing::temp_path("watchdog_test") / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// an executable shell script `body` at dir/name
std::string script(const fs::path& dir, const std::string& name, const std::string& body) {
  const fs::path p = dir / name;
  std::ofstream(p) << "#!/bin/sh\n" << body << "\n";
  ::chmod(p.c_str(), 0755);
  return p.string();
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(HelperWatchdog, AFrameHelperThatNeverAnswersIsEndedWithAnErrorNamingIt) {
  const fs::path d = fresh("frame_helper");
  const EnvFor helper("ARMSTUDY_FRAME_WORKER", script(d, "stuck.sh", "exec sleep 600"));
  const EnvFor timeout("ARMSTUDY_HELPER_TIMEOUT_S", "1");
  std::vector<PoseSample> poses;
  for (int k = 0; k < 6; ++k) poses.push_back(testing::tray_arm_pose(0.1 * k));
  std::string error;
  const auto t0 = std::chrono::steady_clock::now();
  // a thread of its own: its pool of helpers is empty, so the stuck one is started
  std::thread([&] {
    RenderSettings rs;
    rs.frame = {160, 120};
    SceneRenderer two(default_tray_scene(), "tray", rs);
    two.set_strip_threads(2);
    try {
      two.strip(poses, "title", 3);
    } catch (const HelperStuck& e) {
      error = e.what();
    }
  }).join();
  EXPECT_NE(error.find("the frame helper (armstudy-frames"), std::string::npos) << error;
  EXPECT_NE(error.find("made no progress for 1 s (ARMSTUDY_HELPER_TIMEOUT_S) and was ended"),
            std::string::npos)
      << error;
  EXPECT_LT(seconds_since(t0), 60) << "ended at its timeout, not the 120 s default";
  fs::remove_all(d);
}

// the animation of a short motion with ffmpeg played by `program`; its note
std::string video_note(const fs::path& dir, const std::string& program) {
  const EnvFor ffmpeg("ARMSTUDY_FFMPEG", program);
  const EnvFor timeout("ARMSTUDY_HELPER_TIMEOUT_S", "1");
  RenderSettings rs;
  rs.frame = {160, 120};  // 8 frames of 57 kB: more than a pipe holds
  SceneRenderer sr(default_tray_scene(), "tray", rs);
  SampledMotion m;
  for (int k = 0; k < 3; ++k) {
    m.t.push_back(0.1 * k);
    m.q.push_back(testing::tray_arm_pose(0.1 * k).q);
  }
  PendingAnimation pending = write_animation(sr, m, "motion", dir, "anim");
  const Animation a = pending.get();
  EXPECT_TRUE(a.video.empty()) << program;
  EXPECT_FALSE(fs::exists(dir / "anim.mp4")) << program;
  EXPECT_FALSE(fs::exists(dir / "anim.mp4.tmp.mp4"))
      << program << ": its temporary file is removed";
  return a.note;
}

TEST(HelperWatchdog, AnFfmpegThatIsStuckOrWritesNothingLeavesTheVideoOutSayingWhy) {
  const fs::path d = fresh("ffmpeg");
  const auto t0 = std::chrono::steady_clock::now();
  // takes no input
  std::string note = video_note(d, script(d, "stuck.sh", "exec sleep 600"));
  EXPECT_NE(note.find("no video: ffmpeg (" + (d / "stuck.sh").string() +
                      ") made no progress for 1 s (ARMSTUDY_HELPER_TIMEOUT_S) and was ended"),
            std::string::npos)
      << note;
  // takes every frame, then never ends
  note = video_note(d, script(d, "reads.sh", "cat > /dev/null\nexec sleep 600"));
  EXPECT_NE(note.find("made no progress for 1 s"), std::string::npos) << note;
  // ends at once, successfully, without a file
  note = video_note(d, script(d, "silent.sh", "exit 0"));
  EXPECT_NE(note.find("ended without taking every frame or writing the video"), std::string::npos)
      << note;
  // takes every frame, ends successfully, writes nothing
  note = video_note(d, script(d, "nofile.sh", "cat > /dev/null"));
  EXPECT_NE(
      note.find("ffmpeg (" + (d / "nofile.sh").string() + ") ended without writing the video"),
      std::string::npos)
      << note;
  // fails, saying why
  note = video_note(d, script(d, "fails.sh", "echo 'Unknown encoder libx264' >&2\nexit 1"));
  EXPECT_NE(note.find("ffmpeg failed (exit status 1: Unknown encoder libx264)"), std::string::npos)
      << note;
  EXPECT_LT(seconds_since(t0), 60);
  fs::remove_all(d);
}

}  // namespace
}  // namespace armstudy::scene

namespace armstudy::scene {
namespace {

// a full disk said "cannot write ..._anim.png" without the reason
TEST(FrameFiles, AWriteThatFailsSaysWhy) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  try {
    write_bytes("/dev/full", std::string(100000, 'x'));
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write /dev/full: No space left on device");
  }
  EXPECT_TRUE(fs::exists("/dev/full"));
}

}  // namespace
}  // namespace armstudy::scene
