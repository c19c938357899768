// MuJoCo's dynamic replay of a plan (scene/dynamic_replay.hpp, results.json "mujoco_replay")
#include "report/replay_section.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "report/number_format.hpp"

namespace armstudy::report {
namespace {
using nlohmann::json;

// "cycloidal, configuration 1" or "the plan" for a single replay
std::string motion_label(const json& r) {
  if (!jsonv::has(r, "program")) return "the plan";
  return jsonv::str(r, "program") + ", configuration " + jsonv::str(r, "configuration");
}
std::string colour_key(const json& r) {
  return jsonv::str(r, "program") + "/" + jsonv::str(r, "configuration");
}
// row j of the per-joint array r["series"][key]
std::vector<double> joint_row(const json& r, const char* key, size_t j) {
  if (!jsonv::has(r, "series") || !jsonv::has(r["series"], key)) return {};
  const json& a = r["series"][key];
  if (!a.is_array() || j >= a.size() || !a[j].is_array()) return {};
  std::vector<double> out;
  for (const json& v : a[j]) out.push_back(v.is_number() ? v.get<double>() : NAN);
  return out;
}
}  // namespace

void mujoco_replay_section(const json& replay, const json& frames, FigureWriter& figures,
                           CasePage& page) {
  std::vector<const json*> rs;
  if (replay.is_object()) rs.push_back(&replay);
  if (replay.is_array())
    for (const json& r : replay)
      if (r.is_object()) rs.push_back(&r);
  if (rs.empty()) return;

  Section s;
  s.id = "mujoco-replay";
  s.heading = "MuJoCo dynamic replay";
  const json& first = *rs.front();
  s.paragraph(
      "The frames elsewhere on this page are kinematic: the planned joint angles are set and "
      "MuJoCo only draws them. Here MuJoCo's own physics runs the plan: the planned joint "
      "torques are applied open loop, through mj_step, to the model generated from the case's "
      "arm, starting from the plan's initial state, and the joint angles MuJoCo computes are "
      "compared with the planned ones at every step. " +
      jsonv::str(first, "simulates") + "; " + jsonv::str(first, "does_not_simulate") + ".");
  s.paragraph("Each step holds the plan's mean torque over that step, so every step's impulse "
              "is the plan's; the check's " + jsonv::str(first, "tolerance_rule") +
              ". A second replay at twice the step shows the deviation shrink with the step: "
              "the order log2(deviation at 2h / deviation at h) is about 2 (second order; "
              "torque jumps falling at different places within a step scatter it), where a "
              "model mismatch or a wrong torque would not shrink at all.");
  Table t;
  t.caption = "Open-loop replay in MuJoCo (" + jsonv::str(first, "integrator") +
              "): the largest deviation of any joint from the plan over the motion, against "
              "the tolerance h² V.";
  t.header = {"motion", "step h (s)", "steps", "largest deviation (rad)", "at t (s)", "joint",
              "tolerance (rad)", "at 2h (rad)", "order", "check"};
  for (const json* r : rs) {
    const bool passed = jsonv::has(*r, "passed") && (*r)["passed"].is_boolean() && (*r)["passed"].get<bool>();
    t.rows.push_back({motion_label(*r), jsonv::sig(*r, "timestep_s", 3), jsonv::str(*r, "steps"),
                      jsonv::sig(*r, "max_deviation_rad", 3), jsonv::sig(*r, "max_deviation_t_s", 4),
                      jsonv::str(*r, "max_deviation_joint"), jsonv::sig(*r, "tolerance_rad", 3),
                      jsonv::sig(*r, "coarse_max_deviation_rad", 3), jsonv::sig(*r, "observed_order", 3),
                      passed ? "passed" : "FAILED"});
    if (rs.size() > 1) t.swatches.push_back(css_colour(colour_for(colour_key(*r))));
  }
  s.table(std::move(t));

  LinePlot p;
  p.title = "MuJoCo's simulated motion against the plan";
  p.x_label = "time t (s)";
  p.y_label = rs.size() == 1 ? "joint deviation |q_sim - q_plan| (rad)"
                             : "larger joint deviation |q_sim - q_plan| (rad)";
  p.log_y = true;
  double tol = 0;
  for (const json* r : rs) {
    const std::vector<double> ts = jsonv::has(*r, "series") ? jsonv::vec((*r)["series"], "t_s") : std::vector<double>{};
    tol = std::max(tol, jsonv::num(*r, "tolerance_rad"));
    if (ts.size() < 2) continue;
    if (rs.size() == 1) {
      for (size_t j = 0; j < 2; ++j) {
        const std::vector<double> d = joint_row(*r, "deviation_rad", j);
        if (d.size() == ts.size())
          p.series.push_back({"joint " + std::to_string(j + 1), ts, d, colour_for("joint" + std::to_string(j + 1))});
      }
    } else {
      const std::vector<double> d1 = joint_row(*r, "deviation_rad", 0), d2 = joint_row(*r, "deviation_rad", 1);
      if (d1.size() != ts.size() || d2.size() != ts.size()) continue;
      std::vector<double> d(ts.size());
      for (size_t k = 0; k < ts.size(); ++k) d[k] = std::max(d1[k], d2[k]);
      p.series.push_back({motion_label(*r), ts, d, colour_for(colour_key(*r))});
    }
  }
  if (std::isfinite(tol) && tol > 0) p.references = {{tol, "tolerance " + format_sig(tol, 3) + " rad"}};
  if (!p.series.empty())
    s.figure(figures.line("mujoco_replay_deviation", p,
                          "Deviation of MuJoCo's open-loop simulation from the planned joint "
                          "angles over time (logarithmic; zero at the start is left out), with "
                          "the check's tolerance."));

  Strip strip;
  if (frames.is_array())
    for (const json& f : frames) {
      if (!f.is_string() || f.get<std::string>().find("planned-and-simulated") == std::string::npos) continue;
      strip.files.push_back(f.get<std::string>());
      // "placement_cycloidal_c1_planned-and-simulated_strip.png" -> "placement cycloidal c1: ..."
      std::string what = f.get<std::string>().substr(0, f.get<std::string>().find("_planned-and-simulated"));
      std::replace(what.begin(), what.end(), '_', ' ');
      strip.labels.push_back(what + ": planned (arm) and simulated by MuJoCo (magenta skeleton)");
      strip.wide.push_back(true);
    }
  if (!strip.files.empty()) {
    strip.caption = "The planned motion (the arm, posed from the plan) with the motion MuJoCo "
                    "simulated from the plan's torques drawn over it as a magenta skeleton, at "
                    "equal time steps; where they agree the skeleton runs along the middle of "
                    "the arm.";
    s.strip(std::move(strip));
  }
  page.sections.push_back(std::move(s));
}

}  // namespace armstudy::report
