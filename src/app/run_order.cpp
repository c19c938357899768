#include "app/run_order.hpp"

#include <algorithm>
#include <numeric>

namespace armstudy::app {

double estimated_seconds(const LoadedCase& c, bool render) {
  double seconds = 0;
  for (const cases::Demand& d : c.demands) {
    if (d.work_per_second > 0) seconds += d.work / d.work_per_second;
    if (render) seconds += d.frames_rendered / kFramesPerSecond;
  }
  return seconds;
}

std::vector<size_t> longest_first(const std::vector<LoadedCase>& cases, bool render) {
  std::vector<double> seconds(cases.size());
  for (size_t i = 0; i < cases.size(); ++i) seconds[i] = estimated_seconds(cases[i], render);
  std::vector<size_t> order(cases.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return seconds[a] > seconds[b]; });
  return order;
}

}  // namespace armstudy::app
