#pragma once
/// results.json of MuJoCo's dynamic replay (scene/dynamic_replay.hpp), shared by the
/// placement and time-optimal sections:
///   {integrator, timestep_s, steps, duration_s, torque_hold, torque_scale,
///    max_deviation_rad, max_deviation_t_s, max_deviation_joint (1-based), tolerance_rad,
///    tolerance_rule, variation_rad_s2, excursion_rad, coarse_timestep_s,
///    coarse_max_deviation_rad, observed_order, passed, simulates, does_not_simulate,
///    series {t_s, deviation_rad [[j1...], [j2...]], q_plan_rad [[j1...], [j2...]],
///            q_sim_rad [[j1...], [j2...]]}}

#include <nlohmann/json.hpp>

#include "scene/dynamic_replay.hpp"

namespace armstudy::app {

nlohmann::json replay_json(const scene::DynamicReplay& replay);

}  // namespace armstudy::app
