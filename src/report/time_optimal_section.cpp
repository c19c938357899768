// the time-optimal study of Ozkipcak (1994): solvers side by side, the phase plane
// with the maximum velocity curve, joint torques and velocities with their limits, the dp
// convergence table
#include <algorithm>
#include <cmath>

#include "report/number_format.hpp"
#include "report/replay_section.hpp"
#include "report/study_sections.hpp"

namespace armstudy::report {
namespace {

using nlohmann::json;

const json& arr(const json& j, const char* key) {
  static const json empty = json::array();
  return jsonv::has(j, key) && j[key].is_array() ? j[key] : empty;
}
const json& obj(const json& j, const char* key) {
  static const json empty = json::object();
  return jsonv::has(j, key) && j[key].is_object() ? j[key] : empty;
}
// the first of `keys` that j holds as an array of numbers
std::vector<double> first_vec(const json& j, std::initializer_list<const char*> keys) {
  for (const char* k : keys)
    if (jsonv::has(j, k) && j[k].is_array()) return jsonv::vec(j, k);
  return {};
}
double first_num(const json& j, std::initializer_list<const char*> keys) {
  for (const char* k : keys)
    if (jsonv::has(j, k) && j[k].is_number()) return j[k].get<double>();
  return NAN;
}
std::string solver_name(const json& s) {
  for (const char* k : {"name", "solver"})
    if (jsonv::has(s, k) && s[k].is_string()) return s[k].get<std::string>();
  return "solver";
}
// colour key of a solver: "dp_joint1" shares DP's family but not its colour
std::string solver_key(const std::string& name) {
  if (name == "exact" || name == "reachability") return "reachability";
  return name;
}
// the dense samples of a solver (an object with t_s), else the solver itself
const json& samples_of(const json& s) {
  for (const char* k : {"samples", "series", "motion"})
    if (jsonv::has(s, k) && s[k].is_object()) return s[k];
  return s;
}
// limit of joint j (0-based) under any of `keys` (an array per joint)
double limit_of(const json& limits, std::initializer_list<const char*> keys, size_t j) {
  const auto v = first_vec(limits, keys);
  return j < v.size() ? v[j] : NAN;
}

}  // namespace

void time_optimal_sections(const json& results, FigureWriter& figures, CasePage& page) {
  const json& to = results.contains("time_optimal") ? results["time_optimal"] : json::object();
  const json& solvers = arr(to, "solvers");
  const json& limits = obj(to, "limits");
  // a path given in joint space: s in rad (joint-space chord length), keys *_rad
  const json& path = obj(to, "path");
  const bool joint_space = jsonv::str(path, "space") == "joint";
  const std::string u = joint_space ? "rad" : "m";
  const std::string s_key = "s_" + u, sd_key = "sd_" + u + "_s";
  // joints: one limit per joint
  const size_t joints = std::max<size_t>(2, first_vec(limits, {"velocity_rad_s"}).size());

  Section method;
  method.id = "method";
  method.heading = "Method";
  method.new_page = false;
  if (joint_space)
    method.paragraph(
        "The arm, a chain of " + std::to_string(joints) + " joints, follows a path given in joint "
        "space: q(s) through the case's waypoints, s its chord length in joint space (rad). A "
        "tip path would not fix the joint motion of a redundant arm, so the joint motion itself "
        "is the path; the solvers see only q(s), q'(s) and q''(s), exactly as for a tip path "
        "(whose joint path comes from the inverse kinematics of a 2-link arm), and every limit "
        "is per joint. Path speed s' is then in rad/s.");
  method.paragraph(
      std::string(joint_space ? "The speed along the path "
                              : "The tip of a 2-link arm in a horizontal plane follows a given path; the speed along it ") +
      "is chosen to reach the end in the least time under joint velocity and torque limits, "
      "at rest at both ends. Three solvers work on the same problem: dynamic programming as "
      "in the source (Ozkipcak 1994, docs/sources.md: N segments of constant acceleration, "
      "Bellman recursion over a grid of "
      "velocity states; the path speed s' is the default state because joint 1 need not move "
      "monotonically), Box's Complex method on the same discretisation, and an exact solver "
      "on a fine grid (reachability analysis: backward controllable sets, then a greedy "
      "forward pass). Every solution is re-checked by dense resampling against every limit.");
  method.note(
      "The source is an abstract: link lengths, limits and the path are not given, so the "
      "case chooses them (see its parameters and docs/assumptions.md); there are no printed "
      "numbers to compare with. "
      "The comparison that matters is between the solvers: the exact solver is never slower "
      "than DP or Complex on the same problem.");
  if (!limits.empty()) method.table(json_table(limits, "Limits used (per joint)."));
  page.sections.push_back(std::move(method));

  Section res;
  res.id = "solvers";
  res.heading = "Solvers side by side";
  Table t;
  t.caption = "Duration of the motion found by each solver, its run time, and the largest use "
              "of any limit found by resampling the solution finely (≤ 1 meets every limit).";
  t.header = {"solver", "solved", "duration (s)", "run time (s)", "intervals", "levels",
              "largest limit use", "where"};
  for (const json& s : solvers) {
    const json& v = obj(s, "violation");
    const double worst = first_num(v, {"worst", "worst_excess"});
    t.rows.push_back({solver_name(s), jsonv::str(s, "solved"),
                      format_sig(first_num(s, {"duration_s"}), 7),
                      format_sig(first_num(s, {"run_time_s"}), 3), jsonv::str(s, "intervals"),
                      jsonv::str(s, "levels"),
                      std::isfinite(worst) ? format_sig(1 + worst, 6) : jsonv::str(v, "ratio"),
                      jsonv::has(v, "text") ? jsonv::str(v, "text") : jsonv::str(s, "message")});
    t.swatches.push_back(css_colour(colour_for(solver_key(solver_name(s)))));
  }
  if (!t.rows.empty()) res.table(std::move(t));
  for (const json& s : solvers)
    if (jsonv::has(s, "method") && s["method"].is_string())
      res.paragraph(solver_name(s) + ": " + s["method"].get<std::string>());

  // phase plane: s' over s, the maximum velocity curve and each solver's profile
  LinePlot phase;
  phase.title = "phase plane: path speed over path position";
  phase.x_label = "path position s (" + u + ")";
  phase.y_label = "path speed s' (" + u + "/s)";
  const json& mvc = obj(to, "mvc");
  const std::string mvc_v_key = "velocity_sd_" + u + "_s";
  const auto mvc_s = first_vec(mvc.empty() ? to : mvc, {s_key.c_str(), "mvc_s_m"});
  const auto mvc_sd = first_vec(mvc.empty() ? to : mvc, {sd_key.c_str(), "mvc_sd_m_s"});
  const auto mvc_v = first_vec(mvc.empty() ? to : mvc, {mvc_v_key.c_str(), "mvc_velocity_sd_m_s"});
  if (mvc_s.size() == mvc_sd.size() && !mvc_s.empty())
    phase.series.push_back({"maximum velocity curve", mvc_s, mvc_sd, colour_for("mvc")});
  if (mvc_s.size() == mvc_v.size() && !mvc_s.empty())
    phase.series.push_back({"velocity limits alone", mvc_s, mvc_v, colour_for("limit"), LineStyle::kDotted});
  for (const json& s : solvers) {
    const json& sm = samples_of(s);
    auto x = first_vec(sm, {s_key.c_str()});
    auto y = first_vec(sm, {sd_key.c_str()});
    bool nodes = false;
    if (x.empty() || x.size() != y.size()) {
      x = first_vec(s, {("node_" + s_key).c_str()});
      y = first_vec(s, {("node_" + sd_key).c_str()});
      nodes = true;
    }
    if (x.empty() || x.size() != y.size()) continue;
    Series se{solver_name(s), x, y, colour_for(solver_key(solver_name(s)))};
    se.markers = nodes && x.size() <= 60;
    phase.series.push_back(std::move(se));
  }
  bool phase_ok = false;
  for (const auto& se : phase.series) phase_ok |= se.x.size() >= 2;
  if (phase_ok)
    res.figure(figures.line("phase_plane", phase,
                            "The phase plane: no motion may cross the maximum velocity curve "
                            "(above it some limit is broken whatever the acceleration). The "
                            "exact profile rides along it where it can; DP and Complex, with "
                            "fewer, coarser intervals, stay below."));
  // s(t): where each solver's motion is on the path over time
  LinePlot st;
  st.title = "path position over time";
  st.x_label = "time t (s)";
  st.y_label = "path position s (" + u + ")";
  for (const json& s : solvers) {
    const json& sm = samples_of(s);
    const auto t = first_vec(sm, {"t_s"});
    const auto x = first_vec(sm, {s_key.c_str()});
    if (t.size() >= 2 && t.size() == x.size())
      st.series.push_back({solver_name(s), t, x, colour_for(solver_key(solver_name(s)))});
  }
  if (!st.series.empty())
    res.figure(figures.line("path_position", st,
                            "Path position over time: each solver's motion starts and ends at "
                            "rest; the exact one arrives first."));
  page.sections.push_back(std::move(res));

  Section lim;
  lim.id = "limits";
  lim.heading = "Joint torques and velocities against their limits";
  struct Kind {
    const char* key;
    std::initializer_list<const char*> limit_keys;
    const char* what;
    const char* unit;
  };
  const Kind kinds[] = {{"tau_Nm", {"torque_Nm", "tau_Nm", "torque_limit_Nm"}, "torque", "N m"},
                        {"qd_rad_s", {"velocity_rad_s", "qd_rad_s", "velocity_limit_rad_s"},
                         "velocity", "rad/s"}};
  for (const Kind& k : kinds)
    for (size_t j = 0; j < joints; ++j) {
      LinePlot p;
      p.title = "joint " + std::to_string(j + 1) + " " + k.what;
      p.x_label = "time (s)";
      p.y_label = std::string(k.what) + " (" + k.unit + ")";
      for (const json& s : solvers) {
        const json& sm = samples_of(s);
        const auto ts = first_vec(sm, {"t_s"});
        if (ts.size() < 2) continue;
        p.series.push_back({solver_name(s), ts, jsonv::column(sm, k.key, j, ts.size()),
                            colour_for(solver_key(solver_name(s)))});
        if (p.series.back().y.empty()) p.series.pop_back();
      }
      const double l = limit_of(limits, k.limit_keys, j);
      if (std::isfinite(l)) p.references = {{l, "±" + format_sig(l, 3) + " " + k.unit + " limit"}, {-l, ""}};
      if (!p.series.empty())
        lim.figure(figures.line(std::string(k.key) + "_joint" + std::to_string(j + 1), p,
                                "Joint " + std::to_string(j + 1) + " " + k.what +
                                    " over time for each solver, with its limit."));
    }
  if (lim.blocks.empty()) lim.paragraph("The result holds no sampled motion.");
  page.sections.push_back(std::move(lim));

  Section conv;
  conv.id = "convergence";
  conv.heading = "Convergence: DP over its segments, the exact solver over its grid";
  Table ct;
  ct.caption = "DP (path-speed state) as the number of segments N grows: its duration "
               "approaches the exact solver's from above.";
  ct.header = {"N", "levels", "solved", "duration (s)", "excess over exact", "run time (s)",
               "largest limit use"};
  for (const json& r : arr(to, "convergence")) {
    const double worst = first_num(r, {"worst_violation"});
    ct.rows.push_back({jsonv::str(r, "segments"), jsonv::str(r, "levels"), jsonv::str(r, "solved"),
                       format_sig(first_num(r, {"duration_s"}), 7),
                       format_sig(first_num(r, {"excess", "excess_relative"}), 3),
                       format_sig(first_num(r, {"run_time_s"}), 3),
                       std::isfinite(worst) ? format_sig(1 + worst, 6)
                       : jsonv::str(r, "message").empty() ? "n/a" : jsonv::str(r, "message")});
  }
  if (ct.rows.empty())
    conv.paragraph("The case asked for no convergence table.");
  else
    conv.table(std::move(ct));
  // the exact solver's own grid convergence
  const json& g = obj(to, "grid_convergence");
  if (!g.empty()) {
    const bool passed = jsonv::has(g, "passed") && g["passed"].is_boolean() && g["passed"].get<bool>();
    Table gt;
    gt.caption = "The exact solver's own grid convergence: the same problem with every grid "
                 "interval halved. Its error is first order in the interval, so the change "
                 "estimates the refined duration's error; beyond the tolerance "
                 "(exact.grid_tolerance) the case fails its check exact_grid_converged.";
    gt.header = {"grid points", "duration (s)", "refined grid points", "refined duration (s)",
                 "relative change", "tolerance", "check"};
    gt.rows.push_back({jsonv::str(g, "grid_points"), jsonv::sig(g, "duration_s", 7),
                       jsonv::str(g, "refined_points"), jsonv::sig(g, "refined_duration_s", 7),
                       jsonv::sig(g, "change", 3), jsonv::sig(g, "tolerance", 3),
                       passed ? "passed" : "FAILED"});
    conv.table(std::move(gt));
    if (passed)
      conv.paragraph("Exact solver grid: " + jsonv::str(g, "text") + ".");
    else
      conv.note("The exact duration is NOT converged in its grid, so it is no ordinary "
                "optimum and every comparison with it inherits the error: " +
                jsonv::str(g, "text") + ".");
  }
  page.sections.push_back(std::move(conv));
  mujoco_replay_section(jsonv::has(to, "mujoco_replay") ? to["mujoco_replay"] : json(),
                        jsonv::has(results, "frames") ? results["frames"] : json(), figures, page);
}

}  // namespace armstudy::report
