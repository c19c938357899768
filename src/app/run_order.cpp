// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "app/run_order.hpp"

#include <algorithm>
#include <numeric>

namespace armstudy::app {

double estimated_seconds(const LoadedCase& c, bool render, bool sensitivity) {
  double solve = 0, base = 0, frames = 0;
  for (const cases::Demand& d : c.demands) {
    if (d.work_per_second > 0) {
      solve += d.work / d.work_per_second;
      base += (d.resolve_base > 0 ? d.resolve_base : d.work) / d.work_per_second;
    }
    if (render) frames += d.frames_rendered / kFramesPerSecond;
  }
  const double resolves = sensitivity ? 2.0 * double(c.info.sensitivity.items.size()) : 0.0;
  return solve + base * resolves * kSensitivityResolveFraction + frames;
}

double estimated_memory_bytes(const LoadedCase& c, bool render) {
  double bytes = 0;
  for (const cases::Demand& d : c.demands) {
    bytes += d.memory_bytes;
    if (render) {
      // a strip image and its PNG rows, RGB (as cases::over_budget counts them)
      const int strip = std::max(c.info.render.frames, d.strip_frames);
      bytes += 2.0 * 3.0 * strip * c.info.render.frame.width * c.info.render.frame.height;
    }
  }
  return bytes;
}

void MemoryGate::acquire(double bytes) {
  std::unique_lock<std::mutex> lock(mu_);
  freed_.wait(lock, [&] { return running_ == 0 || in_use_ + bytes <= budget_; });
  in_use_ += bytes;
  ++running_;
}

void MemoryGate::release(double bytes) {
  {
    std::lock_guard<std::mutex> lock(mu_);
    in_use_ -= bytes;
    --running_;
    if (running_ == 0) in_use_ = 0;  // no rounding left over
  }
  freed_.notify_all();
}

double MemoryGate::in_use() const {
  std::lock_guard<std::mutex> lock(mu_);
  return in_use_;
}

std::vector<size_t> longest_first(const std::vector<LoadedCase>& cases, bool render,
                                  bool sensitivity) {
  std::vector<double> seconds(cases.size());
  for (size_t i = 0; i < cases.size(); ++i)
    seconds[i] = estimated_seconds(cases[i], render, sensitivity);
  std::vector<size_t> order(cases.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return seconds[a] > seconds[b]; });
  return order;
}

}  // namespace armstudy::app
