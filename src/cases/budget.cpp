// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/budget.hpp"

#include <algorithm>
#include <cstdio>

#include "cases/yaml_reader.hpp"

namespace armstudy::cases {
namespace {
std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, v < 1e5 ? "%.0f" : "%.2g", v);
  return buf;
}
}  // namespace

std::string bytes_text(double b) {
  char buf[32];
  if (b >= 1e9)
    std::snprintf(buf, sizeof buf, "%.1f GB", b / 1e9);
  else if (b >= 1e6)
    std::snprintf(buf, sizeof buf, "%.0f MB", b / 1e6);
  else
    std::snprintf(buf, sizeof buf, "%.0f kB", b / 1e3);
  return buf;
}

std::vector<OverBudget> over_budget(const Demand& d, int frames, int width, int height,
                                    const Resolves& resolves) {
  std::vector<OverBudget> out;
  const std::string raise = "; reduce them, or pass --allow-large to run it anyway";
  const double base = d.resolve_base > 0 ? d.resolve_base : d.work;
  const double resolve_work = base * resolves.share();
  if (d.work > d.work_budget) {
    out.push_back({false, d.what + " asks for about " + sci(d.work) + " " + d.unit + " (" +
                              d.detail + "), more than the budget of " + sci(d.work_budget) + " " +
                              d.unit + ", set by " + d.keys + raise});
  } else if (resolve_work > d.work_budget) {
    // each key of `sensitivity:` re-solves the case twice: the part has the study's budget
    const std::string n = std::to_string(resolves.keys);
    char share[32], factor[32];
    std::snprintf(share, sizeof share, "%g", resolves.fraction);
    std::snprintf(factor, sizeof factor, "%.3g", resolves.share());
    out.push_back({false, "the sensitivity part of " + d.what + " asks for about " +
                              sci(resolve_work) + " " + d.unit + " (the 2 x " + n +
                              " re-solves of its " + n + " sensitivity keys, each about " + share +
                              " of the solve's " + sci(base) + ": x " + factor +
                              "), more than the budget of " + sci(d.work_budget) + " " + d.unit +
                              " it has besides the solve's, set by the length of 'sensitivity' "
                              "and " +
                              d.keys +
                              "; list fewer keys, reduce them, or pass "
                              "--allow-large to run it anyway"});
  }
  const int strip = std::max(frames, d.strip_frames);
  const double pixels = double(strip) * width * height;
  // a strip image and its PNG rows, RGB
  const double frame_bytes = 2.0 * 3.0 * pixels;
  if (pixels > kPixelBudget) {
    out.push_back(
        {true, "the frames ask for a strip of " + std::to_string(strip) + " frames of " +
                   std::to_string(width) + " x " + std::to_string(height) + " px = " + sci(pixels) +
                   " px (about " + bytes_text(frame_bytes) + "), more than the budget of " +
                   sci(kPixelBudget) + " px, set by render.frames, render.width, render.height" +
                   (d.strip_frames > frames ? " and " + d.what + "'s snapshots" : std::string()) +
                   raise});
  }
  const double memory = d.memory_bytes + frame_bytes;
  if (memory > kMemoryBudgetBytes) {
    out.push_back({false, d.what + " needs about " + bytes_text(memory) + " of memory (" +
                              bytes_text(d.memory_bytes) + " to solve: " + d.detail + "; " +
                              bytes_text(frame_bytes) + " for frames), more than the budget of " +
                              bytes_text(kMemoryBudgetBytes) + ", set by " + d.keys + raise});
  }
  return out;
}

}  // namespace armstudy::cases
