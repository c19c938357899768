// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "app/replay_json.hpp"

#include <cmath>

namespace armstudy::app {

studies::ReplayResults replay_results(const scene::DynamicReplay& r) {
  const auto rows = [&](auto&& value) {
    std::vector<std::vector<double>> out;
    const int n = r.q_plan.empty() ? 0 : static_cast<int>(r.q_plan.front().size());
    for (int j = 0; j < n; ++j) {
      std::vector<double> row;
      for (size_t k = 0; k < r.t.size(); ++k) row.push_back(value(k, j));
      out.push_back(std::move(row));
    }
    return out;
  };
  studies::ReplayResults s;
  s.series.t_s = r.t;
  s.series.deviation_rad =
      rows([&](size_t k, int j) { return std::abs(r.q_sim[k][j] - r.q_plan[k][j]); });
  s.series.q_plan_rad = rows([&](size_t k, int j) { return r.q_plan[k][j]; });
  s.series.q_sim_rad = rows([&](size_t k, int j) { return r.q_sim[k][j]; });
  s.integrator = r.integrator;
  s.timestep_s = r.timestep;
  s.steps = r.steps;
  s.duration_s = r.duration;
  s.torque_hold = "each step holds the plan's mean torque over that step (its impulse exact)";
  s.torque_scale = r.torque_scale;
  s.max_deviation_rad = r.max_deviation;
  s.max_deviation_t_s = r.max_deviation_t;
  s.max_deviation_joint = r.max_deviation_joint + 1;
  s.tolerance_rad = r.tolerance;
  s.tolerance_rule = scene::replay_tolerance_rule();
  s.variation_rad_s2 = r.variation;
  s.excursion_rad = r.excursion;
  s.coarse_timestep_s = r.coarse_timestep;
  s.coarse_max_deviation_rad = r.coarse_max_deviation;
  s.observed_order = r.observed_order;
  s.passed = r.max_deviation <= r.tolerance;
  s.simulates = scene::replay_simulates();
  s.does_not_simulate = scene::replay_does_not_simulate();
  return s;
}

}  // namespace armstudy::app
