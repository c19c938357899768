// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Round geoms (spheres, capsules, cylinders) are drawn with as few polygon sides as the frame
// can show: each polygon within a quarter of a pixel of its circle; a close-up keeps
// MuJoCo's own 28.

#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "scene/arm_scene.hpp"
#include "scene/model_files.hpp"
#include "studies/throwing/spec.hpp"
#include "studies/tray_arm.hpp"

namespace armstudy::scene {
namespace {

int attribute(const std::string& mjcf, const std::string& name) {
  std::smatch m;
  if (!std::regex_search(mjcf, m, std::regex(name + "=\"([0-9]+)\""))) return 0;
  return std::stoi(m[1]);
}

// the ball of the default tray scene: rb m in a view `span` m high on 480 px
double deviation_px(int sides, double radius, double span) {
  const double r_px = radius * 480 / span;
  return r_px * (1 - std::cos(3.14159265358979323846 / sides));
}

TEST(SceneQuality, TheWholeMotionViewDrawsTheBallWithFewerSidesWithinAQuarterPixel) {
  const ArmScene s = default_tray_scene();
  const int n = attribute(s.mjcf, "numslices");
  ASSERT_GT(n, 0) << "expected fewer sides than MuJoCo's 28 for a ball ~10 px across";
  EXPECT_LT(n, 28);
  const studies::ThrowingSpec spec;
  EXPECT_LE(deviation_px(n, spec.arm.rb, s.view.y_max - s.view.y_min), 0.25);
  EXPECT_GE(attribute(s.mjcf, "numstacks"), 8);
}

TEST(SceneQuality, ACloseUpKeepsMuJoCosOwnSides) {
  const studies::ThrowingSpec spec;
  TrayDecor d;
  d.ball_radius = spec.arm.rb;
  d.view = ViewBox{-0.03, 0.03, -0.02, 0.02};  // the ball ~240 px across
  const ArmScene s = tray_arm_scene(studies::make_tray_arm(spec.arm), d);
  EXPECT_EQ(attribute(s.mjcf, "numslices"), 0) << "MuJoCo's default (28)";
}

}  // namespace
}  // namespace armstudy::scene
