// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The order a run works through its cases in: the longest first, so that the last case to
/// finish on each core is a short one. Only the order changes; every case's output is the
/// same in any order.

#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <vector>

#include "app/pipeline.hpp"

namespace armstudy::app {

/// Frames a core renders per second, about (the bundled cases, 640 x 480 px, no shadows).
inline constexpr double kFramesPerSecond = 40.0;

/// What one re-solve of a case's sensitivity part (two a key, warm-started from the answer,
/// not rendered) costs, as a fraction of the case's own solve: measured on the bundled cases
/// 0.05-0.11 (placement and time-optimal about 0.05, throwing 0.11), rounded up.
inline constexpr double kSensitivityResolveFraction = 0.15;

/// The case's time on one core estimated from its loader's demands: the work divided by
/// the work a core does per second, plus, when `sensitivity`, its sensitivity part's
/// re-solves (2 a key, each kSensitivityResolveFraction of the work it repeats: a demand's
/// resolve_base where it names one, e.g. the throw without its global phase, else its work),
/// plus, when `render`, the frames it renders at kFramesPerSecond. 0 when no demand says.
double estimated_seconds(const LoadedCase& c, bool render, bool sensitivity = true);

/// The memory the case holds at once, estimated from its loader's demands as the budget
/// judges it (the solve's arrays, plus its strip's pixels when `render`).
double estimated_memory_bytes(const LoadedCase& c, bool render);

/// The run's memory budget shared by its jobs: acquire(bytes) waits until `bytes` fit beside
/// what the running cases hold within the budget (or nothing runs: a case beyond the
/// budget alone, allowed with --allow-large, runs alone); release(bytes) gives them back.
class MemoryGate {
 public:
  explicit MemoryGate(double budget_bytes) : budget_(budget_bytes) {}
  void acquire(double bytes);
  void release(double bytes);
  double in_use() const;

 private:
  const double budget_;
  double in_use_ = 0;
  int running_ = 0;
  mutable std::mutex mu_;
  std::condition_variable freed_;
};

/// Indices into `cases`, the longest estimate first; cases of equal estimate keep their
/// order.
std::vector<size_t> longest_first(const std::vector<LoadedCase>& cases, bool render,
                                  bool sensitivity = true);

}  // namespace armstudy::app
