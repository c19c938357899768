// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// MuJoCo's dynamic replay of a planned motion (scene/dynamic_replay.hpp) as results.json
/// writes it, shared by the placement and time-optimal sections. See results_fields.hpp
/// (src/report) for how `fields` becomes the writer, the reader and the schema.

#include <string>
#include <vector>

namespace armstudy::studies {

struct ReplayResults {
  struct Series {
    std::vector<double> t_s;
    std::vector<std::vector<double>> deviation_rad, q_plan_rad, q_sim_rad;  ///< per joint rows
  };
  std::string integrator;
  double timestep_s = 0;
  int steps = 0;
  double duration_s = 0;
  std::string torque_hold;
  double torque_scale = 1;
  double max_deviation_rad = 0, max_deviation_t_s = 0;
  int max_deviation_joint = 1;
  double tolerance_rad = 0;
  std::string tolerance_rule;
  double variation_rad_s2 = 0, excursion_rad = 0, coarse_timestep_s = 0,
         coarse_max_deviation_rad = 0, observed_order = 0;
  bool passed = false;
  std::string simulates, does_not_simulate;
  Series series;
};

template <class V>
void fields(V& v, ReplayResults::Series& x) {
  v("t_s", x.t_s, "recorded times");
  v("deviation_rad", x.deviation_rad, "|q_sim - q_plan|, one row per joint");
  v("q_plan_rad", x.q_plan_rad, "planned joint angles, one row per joint");
  v("q_sim_rad", x.q_sim_rad, "simulated joint angles, one row per joint");
}

template <class V>
void fields(V& v, ReplayResults& x) {
  v("integrator", x.integrator, "MuJoCo integrator");
  v("timestep_s", x.timestep_s, "MuJoCo step h");
  v("steps", x.steps, "MuJoCo steps over the motion");
  v("duration_s", x.duration_s, "duration of the motion");
  v("torque_hold", x.torque_hold, "how the plan's torque is held over a step");
  v("torque_scale", x.torque_scale, "factor on every applied torque (1: the plan's)");
  v("max_deviation_rad", x.max_deviation_rad, "max over steps and joints of |q_sim - q_plan|");
  v("max_deviation_t_s", x.max_deviation_t_s, "time of the largest deviation");
  v("max_deviation_joint", x.max_deviation_joint, "joint of the largest deviation (1-based)");
  v("tolerance_rad", x.tolerance_rad,
    "allowed deviation, the larger of h^2 V and the step's error measured at 2 h");
  v("tolerance_rule", x.tolerance_rule, "the tolerance as a sentence");
  v("variation_rad_s2", x.variation_rad_s2,
    "V: total variation of M(q)^-1 tau over the step means");
  v("excursion_rad", x.excursion_rad, "the plan's largest joint excursion (max - min)");
  v("coarse_timestep_s", x.coarse_timestep_s, "2 h");
  v("coarse_max_deviation_rad", x.coarse_max_deviation_rad, "the same replay at 2 h");
  v("observed_order", x.observed_order, "log2(coarse / fine deviation)");
  v("passed", x.passed, "max_deviation_rad <= tolerance_rad");
  v("simulates", x.simulates, "what the replay simulates");
  v("does_not_simulate", x.does_not_simulate, "what it does not");
  v("series", x.series, "the recorded motion");
}

}  // namespace armstudy::studies
