// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Frame labels wrapped to the frame's width: MuJoCo's overlay cuts a line off at the edge
// (the pendulum's title read "... locked; e"), so a long label is broken at spaces.
#include "scene/overlay_wrap.hpp"

#include <gtest/gtest.h>

#include <array>

namespace armstudy::scene {
namespace {

std::array<int, 127> ten_px() {
  std::array<int, 127> w{};
  w.fill(10);
  return w;
}

TEST(OverlayWrap, ALineThatFitsIsUnchanged) {
  const auto w = ten_px();
  EXPECT_EQ(wrap_overlay_text("t = 0.200 s", w, 110), "t = 0.200 s");
  EXPECT_EQ(wrap_overlay_text("one\ntwo", w, 30), "one\ntwo");
  EXPECT_EQ(wrap_overlay_text("", w, 30), "");
}

TEST(OverlayWrap, ALongLineBreaksAtSpacesAndEveryLineFits) {
  const auto w = ten_px();
  const std::string text = "pendulum, joints 1, 2 locked; energy conserved\nball path traced";
  const std::string wrapped = wrap_overlay_text(text, w, 200);
  EXPECT_EQ(wrapped, "pendulum, joints 1,\n2 locked; energy\nconserved\nball path traced");
  EXPECT_LE(overlay_text_width(wrapped, w), 200);
  EXPECT_EQ(overlay_text_width(text, w), 460);
}

TEST(OverlayWrap, AWordWiderThanTheFrameStaysWhole) {
  const auto w = ten_px();
  EXPECT_EQ(wrap_overlay_text("a verylongword b", w, 50), "a\nverylongword\nb");
}

}  // namespace
}  // namespace armstudy::scene
