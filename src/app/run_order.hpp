#pragma once
/// The order a run works through its cases in: the longest first, so that the last case to
/// finish on each core is a short one. Only the order changes; every case's output is the
/// same in any order.

#include <cstddef>
#include <vector>

#include "app/pipeline.hpp"

namespace armstudy::app {

/// The case's solve time on one core estimated from its loader's demands (work divided by
/// the work a core does per second); 0 when no demand says.
double estimated_solve_seconds(const LoadedCase& c);

/// Indices into `cases`, the longest estimated solve first; cases of equal estimate keep
/// their order.
std::vector<size_t> longest_first(const std::vector<LoadedCase>& cases);

}  // namespace armstudy::app
