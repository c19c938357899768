// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Image operations the animations and strips rely on: the sprite sheet's box-filter downscale
// gives the pixels of the plain per-block mean (each rounded down), bit for bit.

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "scene/image.hpp"

namespace armstudy::scene {
namespace {

// the definition, written plainly: each pixel the integer mean of the source block it covers
Image downscale_by_definition(const Image& in, int w, int h) {
  Image out(w, h);
  for (int y = 0; y < h; ++y) {
    const int y0 = y * in.height / h, y1 = std::max(y0 + 1, (y + 1) * in.height / h);
    for (int x = 0; x < w; ++x) {
      const int x0 = x * in.width / w, x1 = std::max(x0 + 1, (x + 1) * in.width / w);
      unsigned sum[3] = {0, 0, 0};
      for (int yy = y0; yy < y1; ++yy)
        for (int xx = x0; xx < x1; ++xx) {
          const Rgb p = in.at(xx, yy);
          sum[0] += p.r;
          sum[1] += p.g;
          sum[2] += p.b;
        }
      const unsigned n = static_cast<unsigned>((y1 - y0) * (x1 - x0));
      out.set(x, y,
              {static_cast<std::uint8_t>(sum[0] / n), static_cast<std::uint8_t>(sum[1] / n),
               static_cast<std::uint8_t>(sum[2] / n)});
    }
  }
  return out;
}

Image noise(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  Image img(w, h);
  for (auto& v : img.rgb) v = static_cast<std::uint8_t>(rng());
  return img;
}

TEST(Image, DownscaleIsTheBlockMeanRoundedDown) {
  struct Size {
    int w0, h0, w, h;
  };
  // the sprite's 3/4, odd sizes, no change, large blocks (divided, not multiplied) and
  // a saturated image (every sum at its largest); 64 x 64 is the largest block multiplied
  for (const Size s :
       {Size{640, 480, 480, 360}, Size{641, 479, 100, 37}, Size{7, 5, 7, 5}, Size{300, 200, 1, 1},
        Size{90, 90, 2, 3}, Size{64, 64, 1, 1}, Size{65, 64, 1, 1}, Size{64, 48, 63, 47}}) {
    for (const unsigned seed : {1u, 2u}) {
      const Image in = noise(s.w0, s.h0, seed);
      const Image got = downscale(in, s.w, s.h);
      ASSERT_EQ(got.width, s.w);
      ASSERT_EQ(got.height, s.h);
      EXPECT_TRUE(got.rgb == downscale_by_definition(in, s.w, s.h).rgb)
          << s.w0 << "x" << s.h0 << " -> " << s.w << "x" << s.h << ", seed " << seed;
    }
    const Image white(s.w0, s.h0, Rgb{255, 255, 255});
    EXPECT_TRUE(downscale(white, s.w, s.h).rgb == Image(s.w, s.h, Rgb{255, 255, 255}).rgb);
  }
}

TEST(Image, FilledWithItsColour) {
  const Image img(5, 3, Rgb{10, 20, 30});
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) {
      EXPECT_EQ(img.at(x, y).r, 10);
      EXPECT_EQ(img.at(x, y).g, 20);
      EXPECT_EQ(img.at(x, y).b, 30);
    }
  EXPECT_EQ(Image(4, 2, Rgb{7, 7, 7}).rgb, std::vector<std::uint8_t>(24, 7));
}

}  // namespace
}  // namespace armstudy::scene
