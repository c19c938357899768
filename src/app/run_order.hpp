#pragma once
/// The order a run works through its cases in: the longest first, so that the last case to
/// finish on each core is a short one. Only the order changes; every case's output is the
/// same in any order.

#include <cstddef>
#include <vector>

#include "app/pipeline.hpp"

namespace armstudy::app {

/// Frames a core renders per second, about (the bundled cases, 640 x 480 px, no shadows).
inline constexpr double kFramesPerSecond = 40.0;

/// The case's time on one core estimated from its loader's demands: the work divided by
/// the work a core does per second, plus, when `render`, the frames it renders at
/// kFramesPerSecond. 0 when no demand says.
double estimated_seconds(const LoadedCase& c, bool render);

/// Indices into `cases`, the longest estimate first; cases of equal estimate keep their
/// order.
std::vector<size_t> longest_first(const std::vector<LoadedCase>& cases, bool render);

}  // namespace armstudy::app
