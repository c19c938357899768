// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// the time-optimal study of Ozkipcak (1994): solvers side by side, the phase plane
// with the maximum velocity curve, joint torques and velocities with their limits, the dp
// convergence table
#include <algorithm>
#include <cmath>

#include "report/arm_model_paragraphs.hpp"
#include "report/number_format.hpp"
#include "report/replay_section.hpp"
#include "report/results_fields.hpp"
#include "report/results_record.hpp"
#include "report/study_sections.hpp"
#include "studies/time_optimal/result.hpp"
#include "studies/time_optimal/study_results.hpp"

namespace armstudy::report {
namespace {

using nlohmann::json;
using Results_ = studies::time_optimal::StudyResults;

// row j of per-joint rows, empty when there is none
std::vector<double> row(const Results_::Rows& rows, size_t j) {
  return j < rows.size() ? rows[j] : std::vector<double>{};
}
double at(const std::vector<double>& v, size_t j) { return j < v.size() ? v[j] : NAN; }
// colour key of a solver: "dp_joint1" shares DP's family but not its colour
std::string solver_key(const std::string& name) {
  if (name == "exact" || name == "reachability") return "reachability";
  return name;
}
}  // namespace
// the unit of the path position s: rad for a path given in joint space (its joint-space
// chord length), else the tip path's
std::string path_unit(const Results_& to) { return to.path.s_unit.empty() ? "m" : to.path.s_unit; }

// joints: one limit per joint
size_t joint_count(const Results_& to) {
  return std::max<size_t>(2, to.limits.velocity_rad_s.size());
}

// the method: the path, the three solvers and the limits
Section method_section(const Results_& to) {
  const auto& limits = to.limits;
  const bool joint_space = to.path.space == "joint";
  const size_t joints = joint_count(to);
  Section method;
  method.id = "method";
  method.heading = "Method";
  method.new_page = false;
  if (joint_space)
    method.paragraph(
        "The arm, a chain of " + std::to_string(joints) +
        " joints, follows a path given in joint "
        "space: q(s) through the case's waypoints, s its chord length in joint space (rad). A "
        "tip path would not fix the joint motion of a redundant arm, so the joint motion itself "
        "is the path; the solvers see only q(s), q'(s) and q''(s), exactly as for a tip path "
        "(whose joint path comes from the inverse kinematics of a 2-link arm), and every limit "
        "is per joint. Path speed s' is then in rad/s.");
  method.paragraph(
      std::string(joint_space ? "The speed along the path "
                              : "The tip of a 2-link arm in a horizontal plane follows a given "
                                "path; the speed along it ") +
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
  method.table(json_table(to_json(limits), "Limits used (per joint)."));
  arm_model_paragraphs(to.arm_model, method);
  return method;
}

// each solver's duration, run time and largest limit use
Table solvers_table(const Results_& to) {
  const auto& solvers = to.solvers;
  Table t;
  t.caption =
      "Duration of the motion found by each solver, its run time, and the largest use "
      "of any limit found by resampling the solution finely (≤ 1 meets every limit).";
  t.header = {"solver",    "solved", "duration (s)",      "run time (s)",
              "intervals", "levels", "largest limit use", "where"};
  for (const auto& s : solvers) {
    const double worst = s.violation ? s.violation->worst : NAN;
    t.rows.push_back({studies::time_optimal::solver_words(s.name), as_text(s.solved),
                      format_sig(s.duration_s, 7), format_sig(s.run_time_s, 3),
                      as_text(s.intervals), as_text(s.levels),
                      std::isfinite(worst) ? format_sig(1 + worst, 6)
                      : s.violation        ? to_json(s.violation->ratio).dump()
                                           : std::string(),
                      s.violation ? s.violation->text : s.message});
    t.swatches.push_back(css_colour(colour_for(solver_key(s.name))));
  }
  return t;
}

// the phase plane: s' over s, the maximum velocity curve and each solver's profile
void add_phase_plane(const Results_& to, FigureWriter& figures, Section& res) {
  const auto& solvers = to.solvers;
  const std::string u = path_unit(to);
  LinePlot phase;
  phase.title = "phase plane: path speed over path position";
  phase.x_label = "path position s (" + u + ")";
  phase.y_label = "path speed s' (" + u + "/s)";
  const auto& mvc_s = to.mvc.s;
  const auto& mvc_sd = to.mvc.sd;
  const auto& mvc_v = to.mvc.velocity_sd;
  if (mvc_s.size() == mvc_sd.size() && !mvc_s.empty())
    phase.series.push_back({"maximum velocity curve", mvc_s, mvc_sd, colour_for("mvc")});
  if (mvc_s.size() == mvc_v.size() && !mvc_s.empty())
    phase.series.push_back(
        {"velocity limits alone", mvc_s, mvc_v, colour_for("limit"), LineStyle::kDotted});
  for (const auto& s : solvers) {
    auto x = s.samples ? s.samples->s : std::vector<double>{};
    auto y = s.samples ? s.samples->sd : std::vector<double>{};
    bool nodes = false;
    if (x.empty() || x.size() != y.size()) {
      x = s.node_s.value_or(std::vector<double>{});
      y = s.node_sd.value_or(std::vector<double>{});
      nodes = true;
    }
    if (x.empty() || x.size() != y.size()) continue;
    Series se{studies::time_optimal::solver_words(s.name), x, y, colour_for(solver_key(s.name))};
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
}

// s(t): where each solver's motion is on the path over time
void add_path_position(const Results_& to, FigureWriter& figures, Section& res) {
  const auto& solvers = to.solvers;
  const std::string u = path_unit(to);
  LinePlot st;
  st.title = "path position over time";
  st.x_label = "time t (s)";
  st.y_label = "path position s (" + u + ")";
  for (const auto& s : solvers) {
    if (!s.samples) continue;
    const auto& t = s.samples->t_s;
    const auto& x = s.samples->s;
    if (t.size() >= 2 && t.size() == x.size())
      st.series.push_back(
          {studies::time_optimal::solver_words(s.name), t, x, colour_for(solver_key(s.name))});
  }
  if (!st.series.empty())
    res.figure(figures.line("path_position", st,
                            "Path position over time: each solver's motion starts and ends at "
                            "rest; the exact one arrives first."));
}

// the solvers side by side
Section solvers_section(const Results_& to, FigureWriter& figures) {
  const auto& solvers = to.solvers;
  Section res;
  res.id = "solvers";
  res.heading = "Solvers side by side";
  if (Table t = solvers_table(to); !t.rows.empty()) res.table(std::move(t));
  for (const auto& s : solvers)
    res.paragraph(studies::time_optimal::solver_words(s.name) + ": " + s.method);

  add_phase_plane(to, figures, res);
  add_path_position(to, figures, res);
  return res;
}

// each joint's torque and velocity over time against its limit
Section limits_section(const Results_& to, FigureWriter& figures) {
  const auto& solvers = to.solvers;
  const auto& limits = to.limits;
  const size_t joints = joint_count(to);
  Section lim;
  lim.id = "limits";
  lim.heading = "Joint torques and velocities against their limits";
  struct Kind {
    const char* key;  ///< the figure's name
    Results_::Rows Results_::Samples::*rows;
    const std::vector<double>* limit;
    const char* what;
    const char* unit;
  };
  const Kind kinds[] = {
      {"tau_Nm", &Results_::Samples::tau_Nm, &limits.torque_Nm, "torque", "N m"},
      {"qd_rad_s", &Results_::Samples::qd_rad_s, &limits.velocity_rad_s, "velocity", "rad/s"}};
  for (const Kind& k : kinds)
    for (size_t j = 0; j < joints; ++j) {
      LinePlot p;
      p.title = "joint " + std::to_string(j + 1) + " " + k.what;
      p.x_label = "time (s)";
      p.y_label = std::string(k.what) + " (" + k.unit + ")";
      for (const auto& s : solvers) {
        if (!s.samples || s.samples->t_s.size() < 2) continue;
        const auto& ts = s.samples->t_s;
        p.series.push_back({studies::time_optimal::solver_words(s.name), ts,
                            row((*s.samples).*k.rows, j), colour_for(solver_key(s.name))});
        if (p.series.back().y.empty()) p.series.pop_back();
      }
      const double l = at(*k.limit, j);
      if (std::isfinite(l))
        p.references = {{l, "±" + format_sig(l, 3) + " " + k.unit + " limit"}, {-l, ""}};
      if (!p.series.empty())
        lim.figure(figures.line(std::string(k.key) + "_joint" + std::to_string(j + 1), p,
                                "Joint " + std::to_string(j + 1) + " " + k.what +
                                    " over time for each solver, with its limit."));
    }
  if (lim.blocks.empty()) lim.paragraph("The result holds no sampled motion.");
  return lim;
}

// DP (path-speed state) as the number of segments N grows
Table dp_convergence_table(const Results_& to) {
  Table ct;
  ct.caption =
      "DP (path-speed state) as the number of segments N grows: its duration "
      "approaches the exact solver's from above (its excess is over the converged exact "
      "duration where the grids were extrapolated, else over the exact solver's on its grid).";
  ct.header = {"N",
               "levels",
               "solved",
               "duration (s)",
               "excess over exact",
               "run time (s)",
               "largest limit use"};
  for (const auto& r : to.convergence) {
    const double worst = r.worst_violation;
    ct.rows.push_back({as_text(r.segments), as_text(r.levels), as_text(r.solved),
                       format_sig(r.duration_s, 7), format_sig(r.excess, 3),
                       format_sig(r.run_time_s, 3),
                       std::isfinite(worst) ? format_sig(1 + worst, 6)
                       : r.message.empty()  ? "n/a"
                                            : r.message});
  }
  return ct;
}

// how the exact solver graded its grid (a case whose uniform grid did not converge)
std::string graded_grid_text(const Results_::GridConvergence& g) {
  const auto& gr = *g.graded;
  return "Graded grid: the case's " + as_text(gr.uniform_points) +
         " uniform points did not give the converged duration within exact.tolerance_rel = " +
         format_sig(gr.tolerance_rel, 3) +
         " (the spread of their extrapolations was larger; they changed by " +
         format_sig(gr.uniform_change, 3) +
         " with every interval halved), so the exact solver refined the grid where the "
         "change arose (near a singular pose the maximum velocity curve falls over a stretch "
         "far shorter than an interval, and a uniform grid converges only like N^-1/2): " +
         as_text(gr.rounds) + " round(s) of bisecting the intervals holding half the change, to " +
         as_text(g.grid_points) + " points" +
         (gr.capped ? ", stopped by the node cap exact.max_grid_points = " +
                          as_text(gr.max_grid_points) + " before reaching the tolerance."
                    : ".") +
         " The table's grid is the graded one, and the coarser grid of the extrapolation is "
         "every other node of it.";
}

// the grids' durations and their extrapolations one and two grids down, in words
std::string extrapolation_spread_words(const Results_::Extrapolation& x) {
  std::string w = "The same one grid down, over a coarser grid of " + as_text(x.coarse_points) +
                  " points (" + format_to_error(x.coarse_duration_s, x.error_s, 8) +
                  " s) and the case's, gives " + format_to_error(x.one_grid_down_s, x.error_s, 8) +
                  " s";
  if (x.quarter_points > 0)
    w += ", and two grids down, over a quarter grid of " + as_text(x.quarter_points) + " points (" +
         format_to_error(x.quarter_duration_s, x.error_s, 8) + " s) and the coarser one, " +
         format_to_error(x.two_grids_down_s, x.error_s, 8) + " s";
  w += x.quarter_points > 0
           ? "; the error estimate is 4 times the larger of the first difference and half the "
             "second."
           : "; the error estimate is 4 times their difference.";
  return w;
}

// the converged duration: Richardson-extrapolated at the scheme's order 1, its error from
// the spread of the extrapolations
std::string extrapolation_text(const Results_::GridConvergence& g) {
  const auto& x = *g.extrapolation;
  return "Converged duration: " + format_to_error(x.duration_s, x.error_s, 8) + " s ± " +
         format_sig(x.error_s, 2) +
         " s, Richardson's extrapolation at the solver's order 1 over the case's grid and the "
         "refined one. " +
         extrapolation_spread_words(x) + " Observed order over the three finest grids: " +
         (x.asymptotic
              ? format_sig(x.order, 3)
              : std::string("none (their changes differ in sign or it is outside 0.5-4)")) +
         ". The page's headline is this duration; the case's grid value is a detail.";
}

// the exact solver's own grid convergence
void add_grid_convergence(const Results_& to, Section& conv) {
  if (!to.grid_convergence) return;
  const auto& g = *to.grid_convergence;
  const bool passed = g.passed;
  Table gt;
  gt.caption =
      "The exact solver's own grid convergence: the same problem with every grid "
      "interval halved. Its error is first order in the interval, so the change "
      "estimates the refined duration's error; beyond the tolerance "
      "(exact.grid_tolerance) the case fails its check exact_grid_converged.";
  gt.header = {"grid points",
               "duration (s)",
               "refined grid points",
               "refined duration (s)",
               "relative change",
               "tolerance",
               "check"};
  gt.rows.push_back({as_text(g.grid_points), format_sig(g.duration_s, 7), as_text(g.refined_points),
                     format_sig(g.refined_duration_s, 7), format_sig(g.change, 3),
                     format_sig(g.tolerance, 3), passed ? "passed" : "FAILED"});
  conv.table(std::move(gt));
  if (g.graded) conv.paragraph(graded_grid_text(g));
  if (g.extrapolation) conv.paragraph(extrapolation_text(g));
  if (passed)
    conv.paragraph("Exact solver grid: " + g.text + ".");
  else
    conv.note(
        "The exact duration is NOT converged in its grid, so it is no ordinary "
        "optimum and every comparison with it inherits the error: " +
        g.text + ".");
}

// DP over its segments, the exact solver over its grid
Section convergence_section(const Results_& to) {
  Section conv;
  conv.id = "convergence";
  conv.heading = "Convergence: DP over its segments, the exact solver over its grid";
  Table ct = dp_convergence_table(to);
  if (ct.rows.empty())
    conv.paragraph("The case asked for no convergence table.");
  else
    conv.table(std::move(ct));
  add_grid_convergence(to, conv);
  return conv;
}

void time_optimal_sections(const Results_& to, const ResultsRecord& record, FigureWriter& figures,
                           CasePage& page) {
  page.sections.push_back(method_section(to));
  page.sections.push_back(solvers_section(to, figures));
  page.sections.push_back(limits_section(to, figures));
  page.sections.push_back(convergence_section(to));
  std::vector<ReplayOf> replays;
  if (to.mujoco_replay) replays.push_back({"", 0, &*to.mujoco_replay});
  mujoco_replay_section(replays, record.frames, figures, page);
}

}  // namespace armstudy::report
