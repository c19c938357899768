// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/image.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "scene/scene_error.hpp"

namespace armstudy::scene {

Image::Image(int w, int h, Rgb fill)
    : width(w), height(h), rgb(static_cast<size_t>(w) * h * 3, fill.r) {
  if (fill.r == fill.g && fill.g == fill.b) return;
  for (size_t i = 0; i < rgb.size(); i += 3) {
    rgb[i] = fill.r;
    rgb[i + 1] = fill.g;
    rgb[i + 2] = fill.b;
  }
}

void blit(const Image& src, Image* dst, int x, int y) {
  const int x0 = std::max(0, x), x1 = std::min(dst->width, x + src.width);
  if (x1 <= x0) return;
  for (int row = std::max(0, y); row < std::min(dst->height, y + src.height); ++row) {
    const size_t s = (static_cast<size_t>(row - y) * src.width + (x0 - x)) * 3;
    const size_t d = (static_cast<size_t>(row) * dst->width + x0) * 3;
    std::memcpy(&dst->rgb[d], &src.rgb[s], static_cast<size_t>(x1 - x0) * 3);
  }
}

TileGrid::TileGrid(int w_, int h_, size_t n, int columns_, int gap_)
    : w(w_), h(h_), columns(std::clamp(columns_, 1, std::max(1, static_cast<int>(n)))), gap(gap_) {
  rows = (static_cast<int>(n) + columns - 1) / columns;
}

Image TileGrid::canvas(Rgb background) const {
  return Image(columns * w + (columns + 1) * gap, rows * h + (rows + 1) * gap, background);
}

void TileGrid::place(const Image& image, size_t k, Image* canvas) const {
  if (image.width != w || image.height != h) throw SceneError("frame strip tiles differ in size");
  const int c = static_cast<int>(k) % columns, r = static_cast<int>(k) / columns;
  blit(image, canvas, gap + c * (w + gap), gap + r * (h + gap));
}

Image tile(const std::vector<Image>& tiles, int columns, int gap, Rgb background) {
  if (tiles.empty()) return {};
  const TileGrid grid(tiles[0].width, tiles[0].height, tiles.size(), columns, gap);
  Image out = grid.canvas(background);
  for (size_t k = 0; k < tiles.size(); ++k) grid.place(tiles[k], k, &out);
  return out;
}

Image downscale(const Image& in, int w, int h) {
  Image out(w, h);
  std::vector<int> xs0(static_cast<size_t>(w)), xs1(static_cast<size_t>(w));
  int widest = 1;
  for (int x = 0; x < w; ++x) {
    xs0[x] = x * in.width / w;
    xs1[x] = std::max(xs0[x] + 1, (x + 1) * in.width / w);
    widest = std::max(widest, xs1[x] - xs0[x]);
  }
  // sums of each block's columns, row by row, then each block's mean: the sum times a
  // reciprocal ceil(2^32 / n), exact for sums below 2^32 / n (every block of fewer than ~4000
  // pixels: 255 n^2 < 2^32); larger blocks divide
  const size_t stride = static_cast<size_t>(in.width) * 3;
  std::vector<std::uint32_t> sums(static_cast<size_t>(w) * 3);
  std::vector<std::uint64_t> magic(static_cast<size_t>(widest) + 1);
  for (int y = 0; y < h; ++y) {
    const int y0 = y * in.height / h, y1 = std::max(y0 + 1, (y + 1) * in.height / h);
    std::fill(sums.begin(), sums.end(), 0u);
    for (int yy = y0; yy < y1; ++yy) {
      const std::uint8_t* row = &in.rgb[yy * stride];
      std::uint32_t* s = sums.data();
      for (int x = 0; x < w; ++x, s += 3) {
        const std::uint8_t* p = row + static_cast<size_t>(xs0[x]) * 3;
        const std::uint8_t* end = row + static_cast<size_t>(xs1[x]) * 3;
        for (; p < end; p += 3) {
          s[0] += p[0];
          s[1] += p[1];
          s[2] += p[2];
        }
      }
    }
    // the reciprocal of each block width's pixel count in this row of blocks
    const std::uint64_t rows = static_cast<std::uint64_t>(y1 - y0);
    for (int c = 1; c <= widest; ++c) {
      const std::uint64_t n = rows * static_cast<std::uint64_t>(c);
      magic[c] =
          255 * n * n < (std::uint64_t{1} << 32) ? ((std::uint64_t{1} << 32) + n - 1) / n : 0;
    }
    std::uint8_t* o = &out.rgb[static_cast<size_t>(y) * w * 3];
    const std::uint32_t* s = sums.data();
    for (int x = 0; x < w; ++x, o += 3, s += 3) {
      const int c = xs1[x] - xs0[x];
      if (const std::uint64_t m = magic[c]; m != 0) {
        for (int k = 0; k < 3; ++k) o[k] = static_cast<std::uint8_t>((s[k] * m) >> 32);
      } else {
        const std::uint64_t n = rows * static_cast<std::uint64_t>(c);
        for (int k = 0; k < 3; ++k) o[k] = static_cast<std::uint8_t>(s[k] / n);
      }
    }
  }
  return out;
}

PixelStats pixel_stats(const Image& image) {
  PixelStats s;
  const size_t n = static_cast<size_t>(image.width) * image.height;
  if (n == 0) return s;
  double sum = 0, sum2 = 0;
  std::unordered_map<std::uint32_t, size_t> counts;
  for (size_t i = 0; i < n; ++i) {
    const std::uint8_t* p = &image.rgb[3 * i];
    const double y = 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
    sum += y;
    sum2 += y * y;
    ++counts[(std::uint32_t(p[0]) << 16) | (std::uint32_t(p[1]) << 8) | p[2]];
  }
  size_t most = 0;
  for (const auto& kv : counts) most = std::max(most, kv.second);
  s.mean = sum / n;
  s.stddev = std::sqrt(std::max(0.0, sum2 / n - s.mean * s.mean));
  s.non_background = 1.0 - static_cast<double>(most) / n;
  return s;
}

}  // namespace armstudy::scene
