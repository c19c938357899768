// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The placement study's one way of spreading a sweep over threads: the energy sweep
/// (solve.cpp) and the cycle-time map (cycle_time.cpp).

#include <algorithm>
#include <atomic>
#include <string_view>
#include <thread>
#include <vector>

#include "studies/common.hpp"

namespace armstudy::studies::placement {

/// Runs body(i) for i in [0, n) on `threads` threads in chunks of `chunk`; the calling
/// thread works too and is the only one that reports progress (from p0 to p1).
template <typename Body>
void parallel_for(long n, int threads, const ProgressFn& progress, double p0, double p1,
                  std::string_view stage, Body body, long chunk = 32) {
  std::atomic<long> next{0};
  std::atomic<long> done{0};
  const auto work = [&](bool report) {
    for (;;) {
      const long b = next.fetch_add(chunk);
      if (b >= n) break;
      const long e = std::min(n, b + chunk);
      for (long i = b; i < e; ++i) body(i);
      const long d = done.fetch_add(e - b) + (e - b);
      if (report && progress) progress(p0 + (p1 - p0) * double(d) / double(n), stage);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, false);
  work(true);
  for (auto& t : pool) t.join();
}

/// The threads a sweep runs on: `requested`, or every hardware thread when it is 0.
inline int sweep_threads(int requested) {
  return requested > 0 ? requested : std::max(1, int(std::thread::hardware_concurrency()));
}

}  // namespace armstudy::studies::placement
