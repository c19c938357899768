// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/diff_frames.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <utility>

#include "cases/input_file.hpp"
#include "cli/confined_path.hpp"
#include "scene/image.hpp"
#include "scene/png_writer.hpp"
#include "scene/scene_error.hpp"

namespace armstudy::cli {
namespace fs = std::filesystem;

namespace {

// false when the frame is missing (a difference); @throws cases::InputFileError when it
// is there but no regular file of at most kMaxFrameBytes (a FIFO, a device, a link)
bool read_bytes(const fs::path& p, std::string* out) {
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(p, ec))) return false;
  *out = cases::read_input_file(p.string(), {cases::kMaxFrameBytes, "PNG frame", false});
  return true;
}

// outlines the box [x0, x1] x [y0, y1] grown by `pad` px with a `width` px line
void outline(scene::Image* img, int x0, int y0, int x1, int y1, int pad, int width, scene::Rgb c) {
  x0 = std::max(0, x0 - pad);
  y0 = std::max(0, y0 - pad);
  x1 = std::min(img->width - 1, x1 + pad);
  y1 = std::min(img->height - 1, y1 + pad);
  for (int w = 0; w < width; ++w) {
    for (int x = x0; x <= x1; ++x) {
      if (y0 + w <= y1) img->set(x, y0 + w, c);
      if (y1 - w >= y0) img->set(x, y1 - w, c);
    }
    for (int y = y0; y <= y1; ++y) {
      if (x0 + w <= x1) img->set(x0 + w, y, c);
      if (x1 - w >= x0) img->set(x1 - w, y, c);
    }
  }
}

// why the PNG at p is not decoded ("" if it may be): not a PNG, or more pixels than a frame
// may have (read from its header before decoding)
std::string png_header_problem(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  unsigned char h[24] = {};
  in.read(reinterpret_cast<char*>(h), sizeof h);
  static const unsigned char kSig[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (in.gcount() != sizeof h || !std::equal(kSig, kSig + 8, h) ||
      std::string(reinterpret_cast<char*>(h + 12), 4) != "IHDR")
    return p.string() + ": not a PNG image; expected a frame armstudy rendered";
  const auto be32 = [](const unsigned char* b) {
    return (std::uint64_t(b[0]) << 24) | (std::uint64_t(b[1]) << 16) | (std::uint64_t(b[2]) << 8) |
           std::uint64_t(b[3]);
  };
  const std::uint64_t w = be32(h + 16), hgt = be32(h + 20);
  if (double(w) * double(hgt) > kMaxFramePixels)
    return p.string() + ": a PNG of " + std::to_string(w) + " x " + std::to_string(hgt) +
           " px; expected a frame of at most " + std::to_string(std::uint64_t(kMaxFramePixels)) +
           " px (docs/budgets.md), not decoded";
  return "";
}

}  // namespace

// (over 60 lines, kept whole: the steps of one frame comparison (read, size check, pixel
// statistics, verdict) share their images)
report::FrameDiff compare_frame(const fs::path& base, const fs::path& now, const std::string& file,
                                int channel_tolerance, std::size_t pixels_allowed,
                                const fs::path& out_dir, const std::string& copy_prefix) {
  report::FrameDiff d;
  d.file = file;
  const fs::path a = base / file, b = now / file;
  // a path from results.json is read only inside its case folder, and only a regular file
  for (const auto& [folder, p] : {std::pair{base, a}, std::pair{now, b}}) {
    // (a FIFO, device or link inside the folder is refused by read_bytes: bad input)
    const std::string why = confined_problem(folder, file);
    if (!why.empty()) {
      d.error = (folder / "results.json").string() + ": frame '" + file + "' is " + why;
      d.beyond = true;
      return d;
    }
  }
  std::string ab, bb;
  if (!read_bytes(a, &ab)) {
    d.error = a.string() + ": cannot read the frame";
    d.beyond = true;
    return d;
  }
  if (!read_bytes(b, &bb)) {
    d.error = b.string() + ": cannot read the frame";
    d.beyond = true;
    return d;
  }
  if (ab == bb) {
    d.identical = true;
    return d;
  }
  for (const auto& p : {a, b})
    if (std::string why = png_header_problem(p); !why.empty()) {
      d.error = why;
      d.beyond = true;
      return d;
    }
  scene::Image ia, ib;
  try {
    ia = scene::read_png(a);
    ib = scene::read_png(b);
  } catch (const scene::SceneError& e) {
    d.error = e.what();
    d.beyond = true;
    return d;
  }
  d.width = ib.width;
  d.height = ib.height;
  const fs::path stem = fs::path(copy_prefix);
  const std::string name = fs::path(file).filename().string();
  d.base_copy = (stem / ("base_" + name)).generic_string();
  d.new_copy = (stem / ("new_" + name)).generic_string();
  fs::create_directories(out_dir / stem);
  fs::copy_file(a, out_dir / d.base_copy, fs::copy_options::overwrite_existing);
  fs::copy_file(b, out_dir / d.new_copy, fs::copy_options::overwrite_existing);
  if (ia.width != ib.width || ia.height != ib.height) {
    d.size_differs = true;
    d.pixels_beyond =
        static_cast<std::size_t>(std::max(ia.width * ia.height, ib.width * ib.height));
    d.beyond = true;
    return d;
  }
  // the base in light grey, the pixels beyond the tolerance in red
  scene::Image diff(ia.width, ia.height);
  int x0 = ia.width, y0 = ia.height, x1 = -1, y1 = -1;
  const size_t n = static_cast<size_t>(ia.width) * ia.height;
  for (size_t i = 0; i < n; ++i) {
    const uint8_t* p = &ia.rgb[3 * i];
    const uint8_t* q = &ib.rgb[3 * i];
    int delta = 0;
    for (int c = 0; c < 3; ++c) delta = std::max(delta, std::abs(int(p[c]) - int(q[c])));
    d.max_channel_delta = std::max(d.max_channel_delta, delta);
    const int x = static_cast<int>(i % ia.width), y = static_cast<int>(i / ia.width);
    if (delta > channel_tolerance) {
      ++d.pixels_beyond;
      diff.set(x, y, {220, 0, 0});
      x0 = std::min(x0, x);
      y0 = std::min(y0, y);
      x1 = std::max(x1, x);
      y1 = std::max(y1, y);
    } else {
      const int lum = (299 * p[0] + 587 * p[1] + 114 * p[2]) / 1000;
      const auto g = static_cast<uint8_t>(200 + lum * 55 / 255);
      diff.set(x, y, {g, g, g});
    }
  }
  // a few pixels vanish when the page scales the image down: box them
  if (x1 >= 0) outline(&diff, x0, y0, x1, y1, 8, 3, {200, 0, 200});
  d.diff_image = (stem / ("diff_" + name)).generic_string();
  scene::write_png(out_dir / d.diff_image, diff);
  d.beyond = d.pixels_beyond > pixels_allowed;
  return d;
}

}  // namespace armstudy::cli
