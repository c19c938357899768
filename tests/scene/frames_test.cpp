// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The helpers behind strips: sample times, resampling of a motion, tiling, PNG round trip.

#include <gtest/gtest.h>

#include <filesystem>

#include "scene/frames.hpp"
#include "scene/png_writer.hpp"
#include "scene/scene_error.hpp"
#include "testing/files.hpp"

namespace armstudy::scene {
namespace {

TEST(Frames, EvenTimesIncludeBothEnds) {
  const auto t = even_times(0.2, 1.0, 5);
  ASSERT_EQ(t.size(), 5u);
  EXPECT_DOUBLE_EQ(t.front(), 0.2);
  EXPECT_DOUBLE_EQ(t.back(), 1.0);
  EXPECT_DOUBLE_EQ(t[2], 0.6);
  EXPECT_EQ(even_times(0.3, 1.0, 1), std::vector<double>{0.3});
}

TEST(Frames, ResampleInterpolatesLinearlyAndClampsToTheMotion) {
  std::vector<double> t{0.0, 1.0, 3.0};
  std::vector<core::JointVector> q, qd;
  for (double v : {0.0, 2.0, 6.0}) {
    core::JointVector x(2);
    x << v, -v;
    q.push_back(x);
    qd.push_back(2 * x);
  }
  const auto s = resample(t, q, qd, std::vector<double>{-1.0, 0.5, 2.0, 3.0, 9.0});
  ASSERT_EQ(s.size(), 5u);
  EXPECT_DOUBLE_EQ(s[0].q[0], 0.0);  // clamped before the start
  EXPECT_DOUBLE_EQ(s[1].q[0], 1.0);
  EXPECT_DOUBLE_EQ(s[1].qd[1], -2.0);
  EXPECT_DOUBLE_EQ(s[2].q[1], -4.0);
  EXPECT_DOUBLE_EQ(s[3].q[0], 6.0);
  EXPECT_DOUBLE_EQ(s[4].q[0], 6.0);  // clamped after the end
  EXPECT_DOUBLE_EQ(s[4].t, 9.0);     // the label keeps the asked time
}

TEST(Frames, TilePlacesFramesInRowsWithGaps) {
  std::vector<Image> tiles{Image(4, 3, {255, 0, 0}), Image(4, 3, {0, 255, 0}),
                           Image(4, 3, {0, 0, 255}), Image(4, 3, {9, 9, 9})};
  const Image out = tile(tiles, 3, 2, {255, 255, 255});
  EXPECT_EQ(out.width, 3 * 4 + 4 * 2);
  EXPECT_EQ(out.height, 2 * 3 + 3 * 2);
  EXPECT_EQ(out.at(2, 2).r, 255);          // first tile
  EXPECT_EQ(out.at(2 + 4 + 2, 2).g, 255);  // second
  EXPECT_EQ(out.at(2, 2 + 3 + 2).r, 9);    // fourth, second row
  EXPECT_EQ(out.at(0, 0).g, 255);          // background gap
  EXPECT_THROW(tile({Image(4, 3), Image(5, 3)}, 2, 1, {}), SceneError);
}

TEST(Frames, PngRoundTripIsLossless) {
  Image img(7, 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 7; ++x)
      img.set(x, y, {static_cast<std::uint8_t>(30 * x), static_cast<std::uint8_t>(40 * y), 77});
  const auto p = testing::temp_path("png_roundtrip.png");
  write_png(p, img);
  const Image back = read_png(p);
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 5);
  EXPECT_EQ(back.rgb, img.rgb);
  EXPECT_THROW(write_png("/nonexistent/dir/x.png", img), SceneError);
}

}  // namespace
}  // namespace armstudy::scene

namespace armstudy::scene {
namespace {
// a locus traces a long path through evenly spaced points of it: a placement case with the
// documented samples: 20001 drew 20000 segments, more than the scene's room for geoms
TEST(Frames, LongPathsAreTracedThroughEvenlySpacedPointsBothEndsKept) {
  const std::vector<size_t> all = evenly_spaced(5, 1001);
  EXPECT_EQ(all, (std::vector<size_t>{0, 1, 2, 3, 4}));
  const std::vector<size_t> k = evenly_spaced(20001, kMaxTracedSegments + 1);
  ASSERT_EQ(k.size(), kMaxTracedSegments + 1);
  EXPECT_EQ(k.front(), 0u);
  EXPECT_EQ(k.back(), 20000u);
  for (size_t i = 1; i < k.size(); ++i) EXPECT_EQ(k[i] - k[i - 1], 20u);
  EXPECT_TRUE(evenly_spaced(0, 10).empty());
}
}  // namespace
}  // namespace armstudy::scene
