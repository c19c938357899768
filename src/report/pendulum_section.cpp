// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// the pendulum test of Sato et al. sec. 3: energy over time (fig. 3), angles
// over time, the ball's path with the snapshots (fig. 2)
#include <cmath>

#include "report/number_format.hpp"
#include "report/results_fields.hpp"
#include "report/study_sections.hpp"
#include "studies/pendulum/study_results.hpp"

namespace armstudy::report {
namespace {

using nlohmann::json;

// v - v[0], for energies whose absolute level (the potential's zero) means nothing
std::vector<double> minus_first(std::vector<double> v) {
  if (v.empty()) return v;
  const double v0 = v.front();
  for (double& x : v) x -= v0;
  return v;
}

using PR = studies::PendulumStudyResults;

// the model, the integrator and the parameters
Section method_section(const PR& p) {
  const auto& par = p.parameters;
  const auto& integ = p.integrator;
  Section method;
  method.id = "method";
  method.heading = "Method";
  method.new_page = false;
  method.paragraph(
      "The tray arm of Sato et al. (docs/sources.md) with joints 1 and 2 locked is a passive "
      "double pendulum: the tray "
      "swings on its hinge and the ball rolls without slipping on a circle in the tray "
      "(r_b φ' = -r4 θ4'). The equations of motion come from first principles (the ball's spin "
      "includes the tray's rotation) and are integrated from rest with " +
      integ.name + " at rtol = " + format_sig(integ.rtol, 2) +
      ", atol = " + format_sig(integ.atol, 2) +
      ". With no actuator and no friction the mechanical energy K + U must stay constant; its "
      "drift measures the model and the integrator together (the paper's Figure 3).");
  for (const std::string& c : par.choices)
    method.note("What Sato et al. leave open (docs/assumptions.md): " + c);
  method.note(
      "The paper's printed energy curve is not reproduced number for number: its printed "
      "coefficients are inconsistent (docs/defects.md), so the model is derived from first "
      "principles "
      "and checked by conservation, which holds for any consistent choice of the values above.");
  method.table(json_table(to_json(par), "Parameters used (SI; _deg in degrees)."));
  return method;
}

// the energy's conservation: a table and the energies over time
Section energy_section(const PR& p, FigureWriter& figures) {
  const auto& series = p.series;
  const auto& energy = p.energy;
  const auto& integ = p.integrator;
  Section res;
  res.id = "energy";
  res.heading = "Energy conservation";
  Table t;
  t.caption = "Mechanical energy over the simulation and the integrator's effort.";
  t.header = {"quantity", "value"};
  t.rows = {{"initial mechanical energy", format_sig(energy.initial_J, 10) + " J"},
            {"energy exchanged (largest kinetic energy)", format_sig(energy.scale_J, 6) + " J"},
            {"largest drift |E(t) - E(0)|", format_sig(energy.drift_J, 3) + " J"},
            {"drift relative to the energy exchanged", format_sig(energy.drift_relative, 3)},
            {"allowed relative drift", format_sig(energy.tolerance_relative, 3)},
            {"steps accepted / rejected",
             std::to_string(integ.steps_accepted) + " / " + std::to_string(integ.steps_rejected)},
            {"right-hand-side evaluations", std::to_string(integ.evaluations)},
            {"run time", format_sig(p.run_time_s, 3) + " s"}};
  res.table(std::move(t));
  const auto& ts = series.t_s;
  if (ts.size() >= 2) {
    LinePlot e;
    e.title = "energies over time (cf. Figure 3 of Sato et al.)";
    e.x_label = "time (s)";
    e.y_label = "energy relative to the start (J)";
    e.series.push_back({"kinetic K", ts, series.kinetic_J, colour_for("kinetic")});
    e.series.push_back(
        {"potential U - U(0)", ts, minus_first(series.potential_J), colour_for("potential")});
    e.series.push_back({"mechanical K + U - E(0)", ts, minus_first(series.total_J),
                        colour_for("mechanical"), LineStyle::kDashed});
    res.figure(figures.line("energies", e,
                            "Kinetic and potential energy trade places while their sum stays "
                            "flat: the pendulum is passive and frictionless."));
    LinePlot d;
    d.title = "mechanical energy drift";
    d.x_label = "time (s)";
    d.y_label = "E(t) - E(0) (J)";
    d.series.push_back({"E(t) - E(0)", ts, minus_first(series.total_J), colour_for("mechanical")});
    res.figure(figures.line("energy_drift", d,
                            "The drift of the mechanical energy at full scale: rounding and "
                            "integrator error only (largest " +
                                format_sig(energy.drift_J, 3) + " J)."));
  }
  return res;
}

// the passive coordinates' angles and rates over time, into mo
void add_angles_and_rates(const PR& p, FigureWriter& figures, Section& mo) {
  const auto& par = p.parameters;
  const auto& series = p.series;
  const auto& ts = series.t_s;
  LinePlot a;
  a.title = "tray and ball angles over time";
  a.x_label = "time (s)";
  a.y_label = "angle (rad)";
  a.series.push_back(
      {"θ3 (tray, relative to link 2)", ts, column(series.q_rad, 2), colour_for("joint3")});
  a.series.push_back(
      {"θ4 (ball, relative to the tray)", ts, column(series.q_rad, 3), colour_for("joint4")});
  mo.figure(figures.line("angles", a,
                         "The passive coordinates over time; joints 1 and 2 stay locked at " +
                             to_json(par.locked_deg).dump() + " deg."));
  LinePlot r;
  r.title = "tray and ball angular velocities";
  r.x_label = "time (s)";
  r.y_label = "angular velocity (rad/s)";
  r.series.push_back({"θ3'", ts, column(series.qd_rad_s, 2), colour_for("joint3")});
  r.series.push_back({"θ4'", ts, column(series.qd_rad_s, 3), colour_for("joint4")});
  mo.figure(figures.line("rates", r, "Angular velocities of the passive coordinates."));
}

// the ball's path in the plane with the snapshots (fig. 2 style) and their table, into mo
void add_ball_path(const PR& p, FigureWriter& figures, Section& mo) {
  const auto& series = p.series;
  ShadedMap path;
  path.title = "ball path and snapshots (cf. Figure 2 of Sato et al.)";
  path.x_label = "horizontal position x (m)";
  path.y_label = "height y (m)";
  path.nx = path.ny = 2;
  path.z.assign(4, NAN);
  Series ball{"ball centre", column(series.ball_xy_m, 0), column(series.ball_xy_m, 1),
              colour_for("joint4")};
  Series centre{"centre of the ball's circle", column(series.circle_centre_xy_m, 0),
                column(series.circle_centre_xy_m, 1), colour_for("joint3"), LineStyle::kDashed};
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const Series* s : {&ball, &centre})
    for (size_t k = 0; k < s->x.size(); ++k)
      if (std::isfinite(s->x[k]) && std::isfinite(s->y[k])) {
        x0 = std::min(x0, s->x[k]);
        x1 = std::max(x1, s->x[k]);
        y0 = std::min(y0, s->y[k]);
        y1 = std::max(y1, s->y[k]);
      }
  if (!std::isfinite(x0)) x0 = x1 = y0 = y1 = 0;
  const double pad = 0.1 * std::max(x1 - x0, y1 - y0) + 1e-3;
  path.x_min = x0 - pad;
  path.x_max = x1 + pad;
  path.y_min = y0 - pad;
  path.y_max = y1 + pad;
  path.overlays = {ball, centre};
  Table snaps;
  snaps.caption = "Snapshots of the motion (Figure 2 of Sato et al. shows one every 0.13 s).";
  snaps.header = {"t (s)", "θ3 (rad)", "θ4 (rad)", "ball (x, y) (m)"};
  for (const auto& sn : p.snapshots) {
    const auto& q = sn.q_rad;
    const auto& b = sn.ball_xy_m;
    path.markers.push_back({b[0], b[1], "", colour_for("joint4"), false});
    std::string at = "(";
    at += format_sig(b[0], 4);
    at += ", ";
    at += format_sig(b[1], 4);
    at += ")";
    snaps.rows.push_back({format_sig(sn.t_s, 3), q.size() > 2 ? format_sig(q[2], 4) : "n/a",
                          q.size() > 3 ? format_sig(q[3], 4) : "n/a", at});
  }
  if (!path.markers.empty()) path.markers.front().label = "snapshots";
  mo.figure(figures.map("ball_path", path,
                        "The ball's centre in the vertical plane (the arm's base at the "
                        "origin), its circle's centre, and the ball at every snapshot."));
  if (!snaps.rows.empty()) mo.table(std::move(snaps));
}

// the motion: angles, rates and the ball's path
Section motion_section(const PR& p, FigureWriter& figures) {
  const auto& ts = p.series.t_s;
  Section mo;
  mo.id = "motion";
  mo.heading = "The motion";
  if (ts.size() >= 2) {
    add_angles_and_rates(p, figures, mo);
    add_ball_path(p, figures, mo);
  } else {
    mo.paragraph("The result holds no time series.");
  }
  return mo;
}

}  // namespace

void pendulum_sections(const PR& p, const ResultsRecord&, FigureWriter& figures, CasePage& page) {
  page.sections.push_back(method_section(p));
  page.sections.push_back(energy_section(p, figures));
  page.sections.push_back(motion_section(p, figures));
}

}  // namespace armstudy::report
