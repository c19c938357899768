// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The frame helper's messages (scene/frame_messages.hpp): each written and read by its one
// field list, so every field reads back as written; the scene message keeps its documented
// layout; a value past its limit is refused, not allocated.

#include <gtest/gtest.h>

#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <string>

#include "scene/frame_messages.hpp"

namespace armstudy::scene::frame_wire {
namespace {

// a connected pair of sockets, closed at the end of the scope
struct SocketPair {
  int fd[2] = {-1, -1};
  SocketPair() { EXPECT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, fd), 0); }
  ~SocketPair() {
    for (int f : fd)
      if (f >= 0) ::close(f);
  }
};

TEST(FrameMessages, EveryMessageReadsBackAsWritten) {
  SceneMessage scene;
  scene.mjcf = "<mujoco model=\"m\"/>";
  scene.source = "case.yaml";
  scene.settings.frame = {320, 200};
  scene.settings.shadows = true;
  scene.settings.margin = 0.125;
  scene.view = {-1.5, 2.25, -0.75, 1e-300};
  WorkerPose pose;
  pose.t = 0.1;
  pose.qpos = Eigen::VectorXd::LinSpaced(7, -1, 1);
  pose.qvel = Eigen::VectorXd::Constant(6, 0.3);
  pose.labels = {"top left\nline 2", "", "below"};
  Image img(3, 2);
  img.set(1, 1, {1, 2, 3});
  const ErrorMessage error{"no such body"};

  SocketPair s;
  for (const Packed& p : {pack(kScene, scene), pack(kFrame, pose), pack(kReset), pack(kImage, img),
                          pack(kError, error)})
    ASSERT_TRUE(send(s.fd[0], p));
  ::close(s.fd[0]);
  s.fd[0] = -1;

  Reader in{s.fd[1], 1000};
  SceneMessage scene_back;
  ASSERT_EQ(in.kind(), kScene);
  ASSERT_TRUE(unpack(in, scene_back));
  EXPECT_EQ(scene_back.mjcf, scene.mjcf);
  EXPECT_EQ(scene_back.source, scene.source);
  EXPECT_EQ(scene_back.settings.frame.width, 320);
  EXPECT_EQ(scene_back.settings.frame.height, 200);
  EXPECT_TRUE(scene_back.settings.shadows);
  EXPECT_EQ(scene_back.settings.margin, 0.125);
  EXPECT_EQ(scene_back.view.x_min, -1.5);
  EXPECT_EQ(scene_back.view.x_max, 2.25);
  EXPECT_EQ(scene_back.view.y_min, -0.75);
  EXPECT_EQ(scene_back.view.y_max, 1e-300);

  WorkerPose pose_back;
  ASSERT_EQ(in.kind(), kFrame);
  ASSERT_TRUE(unpack(in, pose_back));
  EXPECT_EQ(pose_back.t, 0.1);
  EXPECT_EQ(pose_back.qpos, pose.qpos);
  EXPECT_EQ(pose_back.qvel, pose.qvel);
  EXPECT_EQ(pose_back.labels.top_left, "top left\nline 2");
  EXPECT_EQ(pose_back.labels.top_right, "");
  EXPECT_EQ(pose_back.labels.bottom_left, "below");

  EXPECT_EQ(in.kind(), kReset);

  Image img_back;
  ASSERT_EQ(in.kind(), kImage);
  ASSERT_TRUE(unpack(in, img_back));
  EXPECT_EQ(img_back.width, 3);
  EXPECT_EQ(img_back.height, 2);
  EXPECT_EQ(img_back.rgb, img.rgb);

  ErrorMessage error_back;
  ASSERT_EQ(in.kind(), kError);
  ASSERT_TRUE(unpack(in, error_back));
  EXPECT_EQ(error_back.text, "no such body");

  in.kind();  // the end of the connection
  EXPECT_FALSE(in.ok);
  EXPECT_FALSE(in.timed_out);
}

// the layout both ends of a connection agree on: kind, mjcf, source (each u64 length and
// bytes), width and height (i32), shadows (one byte), margin and the view box (doubles)
TEST(FrameMessages, TheSceneMessageKeepsItsLayout) {
  SceneMessage m;
  m.mjcf = "abc";
  m.source = "de";
  m.settings.frame = {640, 480};
  const Packed p = pack(kWarm, m);
  EXPECT_EQ(p.bytes.size(), 1 + (8 + 3) + (8 + 2) + 4 + 4 + 1 + 8 + 4 * 8);
  EXPECT_EQ(p.bytes[0], 'W');
  EXPECT_EQ(p.bytes.substr(9, 3), "abc");
  std::int32_t width = 0;
  p.bytes.copy(reinterpret_cast<char*>(&width), 4, 1 + 11 + 10);
  EXPECT_EQ(width, 640);
  EXPECT_TRUE(p.raw.empty());
}

TEST(FrameMessages, AValuePastItsLimitIsRefused) {
  SocketPair s;
  Packed p = pack(kError);
  const std::uint64_t huge = kMaxTextBytes + 1;
  p.bytes.append(reinterpret_cast<const char*>(&huge), sizeof huge);
  ASSERT_TRUE(send(s.fd[0], p));
  Reader in{s.fd[1], 1000};
  ASSERT_EQ(in.kind(), kError);
  ErrorMessage e;
  EXPECT_FALSE(unpack(in, e));
  EXPECT_TRUE(e.text.empty());

  // an image wider than kMaxImageSide: its pixels are not read
  Image wide;
  wide.width = kMaxImageSide + 1;
  wide.height = 1;
  Packed q = pack(kImage);
  fields(q, wide);
  ASSERT_TRUE(send(s.fd[0], q));
  Reader in2{s.fd[1], 1000};
  ASSERT_EQ(in2.kind(), kImage);
  Image back;
  EXPECT_FALSE(unpack(in2, back));
  EXPECT_TRUE(back.rgb.empty());
}

}  // namespace
}  // namespace armstudy::scene::frame_wire
