// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// MuJoCo's dynamic replay of a plan (scene/dynamic_replay.hpp, results.json "mujoco_replay")
#include "report/replay_section.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "report/number_format.hpp"
#include "report/results_fields.hpp"

namespace armstudy::report {
namespace {
using nlohmann::json;

// "cycloidal, configuration 1" or "the plan" for a single replay
std::string motion_label(const ReplayOf& r) {
  if (r.program.empty()) return "the plan";
  return r.program + ", configuration " + as_text(r.configuration);
}
std::string colour_key(const ReplayOf& r) { return r.program + "/" + as_text(r.configuration); }
// row j of per-joint rows
std::vector<double> joint_row(const std::vector<std::vector<double>>& rows, size_t j) {
  return j < rows.size() ? rows[j] : std::vector<double>{};
}
}  // namespace

// (over 60 lines, kept whole: the section's paragraphs, table and figures in page order)
void mujoco_replay_section(const std::vector<ReplayOf>& rs, const std::vector<std::string>& frames,
                           FigureWriter& figures, CasePage& page) {
  if (rs.empty()) return;

  Section s;
  s.id = "mujoco-replay";
  s.heading = "MuJoCo dynamic replay";
  const studies::ReplayResults& first = *rs.front().replay;
  s.paragraph(
      "The frames elsewhere on this page are kinematic: the planned joint angles are set and "
      "MuJoCo only draws them. Here MuJoCo's own physics runs the plan: the planned joint "
      "torques are applied open loop, through mj_step, to the model generated from the case's "
      "arm, starting from the plan's initial state, and the joint angles MuJoCo computes are "
      "compared with the planned ones at every step. " +
      first.simulates + "; " + first.does_not_simulate + ".");
  s.paragraph(
      "Each step holds the plan's mean torque over that step, so every step's impulse "
      "is the plan's; the check's " +
      first.tolerance_rule +
      ". A second replay at twice the step shows the deviation shrink with the step: "
      "the order log2(deviation at 2h / deviation at h) is about 2 (second order; "
      "torque jumps falling at different places within a step scatter it), where a "
      "model mismatch or a wrong torque would not shrink at all.");
  Table t;
  t.caption = "Open-loop replay in MuJoCo (" + first.integrator +
              "): the largest deviation of any joint from the plan over the motion, against "
              "the tolerance (the larger of h² V and the step's error measured at 2h).";
  t.header = {"motion",   "step h (s)", "steps",           "largest deviation (rad)",
              "at t (s)", "joint",      "tolerance (rad)", "at 2h (rad)",
              "order",    "check"};
  for (const ReplayOf& ro : rs) {
    const studies::ReplayResults& r = *ro.replay;
    t.rows.push_back({motion_label(ro), format_sig(r.timestep_s, 3), as_text(r.steps),
                      format_sig(r.max_deviation_rad, 3), format_sig(r.max_deviation_t_s, 4),
                      as_text(r.max_deviation_joint), format_sig(r.tolerance_rad, 3),
                      format_sig(r.coarse_max_deviation_rad, 3), format_sig(r.observed_order, 3),
                      r.passed ? "passed" : "FAILED"});
    if (rs.size() > 1) t.swatches.push_back(css_colour(colour_for(colour_key(ro))));
  }
  s.table(std::move(t));

  LinePlot p;
  p.title = "MuJoCo's simulated motion against the plan";
  p.x_label = "time t (s)";
  p.y_label = rs.size() == 1 ? "joint deviation |q_sim - q_plan| (rad)"
                             : "larger joint deviation |q_sim - q_plan| (rad)";
  p.log_y = true;
  double tol = 0;
  for (const ReplayOf& ro : rs) {
    const studies::ReplayResults& r = *ro.replay;
    const std::vector<double>& ts = r.series.t_s;
    tol = std::max(tol, r.tolerance_rad);
    if (ts.size() < 2) continue;
    if (rs.size() == 1) {
      for (size_t j = 0; j < 2; ++j) {
        const std::vector<double> d = joint_row(r.series.deviation_rad, j);
        if (d.size() == ts.size())
          p.series.push_back({"joint " + std::to_string(j + 1), ts, d,
                              colour_for("joint" + std::to_string(j + 1))});
      }
    } else {
      const std::vector<double> d1 = joint_row(r.series.deviation_rad, 0),
                                d2 = joint_row(r.series.deviation_rad, 1);
      if (d1.size() != ts.size() || d2.size() != ts.size()) continue;
      std::vector<double> d(ts.size());
      for (size_t k = 0; k < ts.size(); ++k) d[k] = std::max(d1[k], d2[k]);
      p.series.push_back({motion_label(ro), ts, d, colour_for(colour_key(ro))});
    }
  }
  if (std::isfinite(tol) && tol > 0)
    p.references = {{tol, "tolerance " + format_sig(tol, 3) + " rad"}};
  if (!p.series.empty())
    s.figure(figures.line("mujoco_replay_deviation", p,
                          "Deviation of MuJoCo's open-loop simulation from the planned joint "
                          "angles over time (logarithmic; zero at the start is left out), with "
                          "the check's tolerance."));

  Strip strip;
  for (const std::string& f : frames) {
    if (f.find("planned-and-simulated") == std::string::npos) continue;
    strip.files.push_back(f);
    // "placement_cycloidal_c1_planned-and-simulated_strip.png" -> "placement cycloidal c1: ..."
    std::string what = f.substr(0, f.find("_planned-and-simulated"));
    std::replace(what.begin(), what.end(), '_', ' ');
    strip.labels.push_back(what + ": planned (arm) and simulated by MuJoCo (magenta skeleton)");
    strip.wide.push_back(true);
  }
  if (!strip.files.empty()) {
    strip.caption =
        "The planned motion (the arm, posed from the plan) with the motion MuJoCo "
        "simulated from the plan's torques drawn over it as a magenta skeleton, at "
        "equal time steps; where they agree the skeleton runs along the middle of "
        "the arm.";
    s.strip(std::move(strip));
  }
  page.sections.push_back(std::move(s));
}

}  // namespace armstudy::report
