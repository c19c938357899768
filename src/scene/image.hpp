// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// 8-bit RGB images (top row first) and the few operations the frame strips need.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace armstudy::scene {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  ///< width * height * 3, row-major, top row first

  Image() = default;
  /// A w x h px image filled with `fill`.
  Image(int w, int h, Rgb fill = {255, 255, 255});
  /// Pixel (x right, y down), px; no bounds check.
  Rgb at(int x, int y) const {
    const size_t i = (static_cast<size_t>(y) * width + x) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
  /// Sets pixel (x, y); no bounds check.
  void set(int x, int y, Rgb c) {
    const size_t i = (static_cast<size_t>(y) * width + x) * 3;
    rgb[i] = c.r;
    rgb[i + 1] = c.g;
    rgb[i + 2] = c.b;
  }
};

/// Copies `src` into `dst` with its top-left corner at (x, y) px (clipped).
void blit(const Image& src, Image* dst, int x, int y);

/// Where tile() puts n images of w x h px: a grid of `columns` (1 to n) with `gap` px
/// between them and an outer margin of `gap` px.
struct TileGrid {
  int w = 0, h = 0, columns = 1, rows = 0, gap = 0;
  TileGrid(int w, int h, size_t n, int columns, int gap);
  /// The grid's image, all `background`.
  Image canvas(Rgb background) const;
  /// Copies image k into its place on `canvas`; images of different k may be placed from
  /// different threads at once. @throws SceneError if `image` is not w x h px.
  void place(const Image& image, size_t k, Image* canvas) const;
};

/// Tiles images of equal size in a grid of `columns` with `gap` px between them and an
/// outer margin of `gap` px, on `background`. @throws SceneError if sizes differ.
Image tile(const std::vector<Image>& tiles, int columns, int gap, Rgb background);

/// `image` at w x h px (not larger than it), each pixel the mean of the block of source pixels
/// it covers, rounded down (a box filter; block columns x * image.width / w to
/// (x + 1) * image.width / w, at least one pixel, rows likewise).
Image downscale(const Image& image, int w, int h);

/// Pixel statistics of an image: mean and standard deviation of the luminance (0-255)
/// and the fraction of pixels that differ from the most common colour.
struct PixelStats {
  double mean = 0;
  double stddev = 0;
  double non_background = 0;
};
/// The statistics of `image` (zeros for an empty image).
PixelStats pixel_stats(const Image& image);

}  // namespace armstudy::scene
