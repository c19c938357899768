// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Where a run's time goes, for diagnosis only: with ARMSTUDY_PHASE_TIMES=1 in the
/// environment, `armstudy run` prints one line per case on stderr with the wall-clock
/// seconds spent in each phase (solve, rendering and its parts, report, PDF). Phases are
/// counted on the thread that runs the case (a strip drawn on several threads counts once,
/// as its wall time); nested phases are named "outer.inner". Off (the default), a
/// PhaseScope costs one relaxed load of a flag.

#include <string>

namespace armstudy::scene {

/// True when ARMSTUDY_PHASE_TIMES is set to something other than "" or "0".
bool phase_times_enabled();

/// Adds the wall time between construction and destruction to phase `name` of this
/// thread's current case (the name must outlive the scope: a string literal).
class PhaseScope {
 public:
  explicit PhaseScope(const char* name);
  ~PhaseScope();
  PhaseScope(const PhaseScope&) = delete;
  PhaseScope& operator=(const PhaseScope&) = delete;

 private:
  const char* name_;
  long long start_ns_ = -1;
};

/// This thread's phases since the last call, as "solve 1.23 s, render 0.40 s, ..." in the
/// order first seen (nested phases after their parent), and clears them; "" when off.
std::string take_phase_times();

}  // namespace armstudy::scene
