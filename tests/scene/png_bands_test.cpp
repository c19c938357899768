// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// A large image compressed in bands is a valid PNG of the same pixels, and the same bytes on
// any number of threads.

#include <gtest/gtest.h>

#include <fstream>

#include "scene/png_writer.hpp"
#include "testing/files.hpp"

namespace armstudy::scene {
namespace {

TEST(PngBands, ALargeImageIsTheSameBytesOnAnyThreadsAndDecodesToItsPixels) {
  Image img(1000, 1500);  // 4.5 MB: banded
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      img.set(x, y,
              Rgb{static_cast<std::uint8_t>(x * 7 + y), static_cast<std::uint8_t>((x / 50) * 20),
                  static_cast<std::uint8_t>(y % 3 == 0 ? 255 : x ^ y)});
  const std::string one = encode_png(img, 1), three = encode_png(img, 3);
  EXPECT_EQ(one, three);
  EXPECT_EQ(encode_png(img, 2), one);
  EXPECT_EQ(encode_png(img, 8), one);
  const auto dir = armstudy::testing::fresh_dir("png_bands");
  for (const auto& [name, bytes] : {std::pair{"one.png", one}, std::pair{"three.png", three}}) {
    std::ofstream(dir / name, std::ios::binary) << bytes;
    const Image back = read_png(dir / name);
    ASSERT_EQ(back.width, img.width) << name;
    ASSERT_EQ(back.height, img.height) << name;
    EXPECT_TRUE(back.rgb == img.rgb) << name;
  }
}

TEST(PngBands, AFrameIsEncodedAsBefore) {
  const Image frame(640, 480, Rgb{10, 20, 30});
  EXPECT_EQ(encode_png(frame, 4), encode_png(frame, 1));
}

}  // namespace
}  // namespace armstudy::scene
