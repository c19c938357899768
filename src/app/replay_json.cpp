#include "app/replay_json.hpp"

#include "app/json_numbers.hpp"

namespace armstudy::app {

nlohmann::json replay_json(const scene::DynamicReplay& r) {
  using nlohmann::json;
  const auto rows = [&](auto&& value) {
    json out = json::array();
    const int n = r.q_plan.empty() ? 0 : static_cast<int>(r.q_plan.front().size());
    for (int j = 0; j < n; ++j) {
      json row = json::array();
      for (size_t k = 0; k < r.t.size(); ++k) row.push_back(json_number(value(k, j)));
      out.push_back(row);
    }
    return out;
  };
  json t = json::array();
  for (double v : r.t) t.push_back(json_number(v));
  json series = {{"t_s", t},
                 {"deviation_rad", rows([&](size_t k, int j) { return std::abs(r.q_sim[k][j] - r.q_plan[k][j]); })},
                 {"q_plan_rad", rows([&](size_t k, int j) { return r.q_plan[k][j]; })},
                 {"q_sim_rad", rows([&](size_t k, int j) { return r.q_sim[k][j]; })}};
  return {{"integrator", r.integrator},
          {"timestep_s", json_number(r.timestep)},
          {"steps", r.steps},
          {"duration_s", json_number(r.duration)},
          {"torque_hold", "each step holds the plan's mean torque over that step (its impulse exact)"},
          {"torque_scale", r.torque_scale},
          {"max_deviation_rad", json_number(r.max_deviation)},
          {"max_deviation_t_s", json_number(r.max_deviation_t)},
          {"max_deviation_joint", r.max_deviation_joint + 1},
          {"tolerance_rad", json_number(r.tolerance)},
          {"tolerance_rule", scene::replay_tolerance_rule()},
          {"variation_rad_s2", json_number(r.variation)},
          {"excursion_rad", json_number(r.excursion)},
          {"coarse_timestep_s", json_number(r.coarse_timestep)},
          {"coarse_max_deviation_rad", json_number(r.coarse_max_deviation)},
          {"observed_order", json_number(r.observed_order)},
          {"passed", r.max_deviation <= r.tolerance},
          {"simulates", scene::replay_simulates()},
          {"does_not_simulate", scene::replay_does_not_simulate()},
          {"series", series}};
}

}  // namespace armstudy::app
