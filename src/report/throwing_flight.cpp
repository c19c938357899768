// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// the throwing page's ball, release and flight (cf. Figure 7 of Sato et al.) and the
// optimisers' convergence with the simulation's accuracy
#include <cmath>

#include "report/number_format.hpp"
#include "report/results_fields.hpp"
#include "report/study_sections.hpp"
#include "report/throwing_page.hpp"

namespace armstudy::report::throwing_page {
namespace {

// the ball's angle θ4 in the tray and the passive tray angle θ3 with its release target
void add_tray_angles(const Page& p, FigureWriter& figures, Section& ball) {
  const std::vector<Motion>& ms = p.ms;
  const auto& par = p.section.parameters;
  const auto& lim = p.section.limits;
  LinePlot t4 = motion_plot(ms, "ball angle θ4 in the tray", "ball angle in the tray θ4 (rad)",
                            &TS::Series::q_rad, 3, {});
  const auto& tl = lim.theta4_limit_rad;
  if (tl.size() == 2) t4.references = {{tl[1], "tray limits ±λ/2"}, {tl[0], ""}};
  if (!t4.series.empty())
    ball.figure(figures.line("theta4", t4,
                             "The ball's angle relative to the tray with the tray's limits: "
                             "outside them the ball leaves the tray (eq. 9's penalty)."));
  LinePlot q3 =
      motion_plot(ms, "tray angle θ3 (passive)", "tray angle θ3 (rad)", &TS::Series::q_rad, 2, {});
  // the release target: θ3 at the end of the throw, within the release tolerance
  const auto& rel_deg = par.task.release_deg;
  const double rel_tol = lim.release_tolerance_rad;
  std::string target_text;
  if (rel_deg.size() == 3 && std::isfinite(rel_deg[2])) {
    const double target = rel_deg[2] * 3.14159265358979 / 180;
    const double tf = par.task.duration_s;
    const double tol = std::isfinite(rel_tol) ? rel_tol : 0;
    q3.references.push_back({target, ""});
    if (std::isfinite(tf)) {
      // a bar at the release time spanning the tolerance, with a dot on the target
      q3.series.push_back({"release target θ3 = " + format_sig(rel_deg[2], 4) + "° ± " +
                               format_sig(tol * 180 / 3.14159265358979, 2) + "° at release",
                           {tf, tf, tf},
                           {target - tol, target, target + tol},
                           Rgb{0, 0, 0},
                           LineStyle::kSolid,
                           true,
                           4.0});
    }
    target_text = " Black: the release target θ3 = " + format_sig(rel_deg[2], 4) +
                  "° at the release time, the bar its tolerance (the dashed grey line the same "
                  "angle over the whole throw).";
  }
  if (!q3.series.empty())
    ball.figure(figures.line("theta3", q3,
                             "The passive tray joint, moved only by the dynamics." + target_text));
}

// release and flight of the ball (the answer's throw: throwing.flight)
void add_release(const Page& p, Section& ball) {
  const TS::Optimised& th = p.th;
  const bool ran = p.ran;
  const auto& rel = th.release;
  const auto& fl = th.flight;
  Table r;
  r.caption = std::string("Release and flight of the ball (") +
              (th.answer == "slsqp" ? "the answer: SLSQP's throw" : "the answer: IDP's throw") +
              ").";
  r.header = {"quantity", "value"};
  auto pair = [](const std::vector<double>& v) {
    return v.size() == 2 ? "(" + format_sig(v[0], 4) + ", " + format_sig(v[1], 4) + ")"
                         : std::string("n/a");
  };
  r.rows = {{"release time", format_sig(rel.time_s, 4) + " s"},
            {"ball at release (x, y)", pair(rel.ball_xy_m) + " m"},
            {"ball velocity at release", pair(rel.ball_velocity_m_s) + " m/s"},
            {"reaches the landing height", as_text(fl.reaches)},
            {"landing height", format_sig(fl.landing_height_m, 4) + " m"},
            {"landing point (x, y)", pair(fl.landing_xy_m) + " m"},
            {"flight time", format_sig(fl.duration_s, 4) + " s"},
            {"apex height", format_sig(fl.apex_m, 4) + " m"}};
  if (ran) ball.table(std::move(r));
}

// the ball's path in the vertical plane: each motion and the flight
void add_throw_locus(const Page& p, FigureWriter& figures, Section& ball) {
  const std::vector<Motion>& ms = p.ms;
  const auto& fl = p.th.flight;
  // the locus of the throw (003 figure 7) and the flight, in the vertical plane
  {
    ShadedMap locus;
    locus.title = "ball path: throw and flight (cf. Figure 7 of Sato et al.)";
    locus.x_label = "horizontal position x (m)";
    locus.y_label = "height y (m)";
    locus.nx = locus.ny = 2;
    locus.z.assign(4, NAN);
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    auto add = [&](Series s) {
      for (size_t k = 0; k < s.x.size() && k < s.y.size(); ++k)
        if (std::isfinite(s.x[k]) && std::isfinite(s.y[k])) {
          x0 = std::min(x0, s.x[k]);
          x1 = std::max(x1, s.x[k]);
          y0 = std::min(y0, s.y[k]);
          y1 = std::max(y1, s.y[k]);
        }
      locus.overlays.push_back(std::move(s));
    };
    for (const Motion& mo : ms) {
      const TS::Series& s = mo.m->series;
      add({mo.label + ": ball in the tray", column(s.ball_xy_m, 0), column(s.ball_xy_m, 1),
           colour_for(mo.colour_key)});
    }
    add({"flight after release", column(fl.path_xy_m, 0), column(fl.path_xy_m, 1),
         colour_for("idp"), LineStyle::kDashed});
    const auto& land = fl.landing_xy_m;
    if (land.size() == 2) {
      locus.markers.push_back({land[0], land[1], "landing point", colour_for("idp")});
      x0 = std::min(x0, land[0]);
      x1 = std::max(x1, land[0]);
      y0 = std::min(y0, land[1]);
      y1 = std::max(y1, land[1]);
    }
    if (x1 > x0 && y1 > y0) {
      const double pad = 0.06 * std::max(x1 - x0, y1 - y0);
      locus.x_min = x0 - pad;
      locus.x_max = x1 + pad;
      locus.y_min = y0 - pad;
      locus.y_max = y1 + pad;
      ball.figure(figures.map("throw_locus", locus,
                              "The ball's centre in the vertical plane (the arm's base at the "
                              "origin) during each motion, and its flight after the answer's "
                              "release."));
    }
  }
}

// IDP's convergence figure (added to `conv`) and table (returned: it goes after the
// SLSQP history)
Table add_idp_convergence(const Page& p, FigureWriter& figures, Section& conv) {
  const TS& section = p.section;
  const bool ran = p.ran;
  const auto& idp = p.th.idp;
  LinePlot cp;
  cp.title = "IDP convergence";
  cp.x_label = "iteration (all passes)";
  cp.y_label = "energy of the best (J)";
  Series en{"energy of the best (feasible)", {}, {}, colour_for("idp"), LineStyle::kSolid, true};
  Table ct;
  ct.caption =
      "IDP (best seed): the best at the end of iterations (all of them when few; "
      "else the last of each pass). Violation 0: feasible.";
  ct.header = {"pass",           "iteration",    "energy (J)", "violation",
               "region (rad/s)", "improvements", "simulations"};
  int k = 0;
  const auto& rows = idp.convergence;
  // the start: pass 0 is IDP's feasible start
  if (ran && std::isfinite(section.energy_reference_J)) {
    en.x.push_back(0);
    en.y.push_back(section.energy_reference_J);
  }
  for (size_t i = 0; i < rows.size(); ++i) {
    const auto& row = rows[i];
    ++k;
    en.x.push_back(k);
    en.y.push_back(row.violation > 0 ? NAN : row.energy_J);
    // the table keeps each pass's first and last iteration and every fifth (the plot has all)
    const bool last_of_pass = i + 1 == rows.size() || rows[i + 1].pass != row.pass;
    // (many rows: each pass's last only; the plot has every iteration)
    if (rows.size() > 25 && !last_of_pass) continue;
    const auto& reg = row.region_rad_s;
    ct.rows.push_back(
        {as_text(row.pass), as_text(row.iteration), format_sig(row.energy_J, 6),
         format_sig(row.violation, 3),
         reg.size() == 2 ? format_sig(reg[0], 3) + ", " + format_sig(reg[1], 3) : "n/a",
         as_text(row.improvements), as_text(row.evaluations)});
  }
  en.markers = k <= 80;
  if (k > 0) {
    cp.x_label = "iteration (all passes; 0: the reference start)";
    cp.series = {en};
    conv.figure(
        figures.line("idp_convergence", cp,
                     "Energy of the best feasible profile after each IDP iteration of the "
                     "best seed, passes one after the other (the region is restored between "
                     "passes)."));
  }
  return ct;
}

// the gradient method's energy at each evaluation
void add_slsqp_history(const Page& p, FigureWriter& figures, Section& conv) {
  const TS& section = p.section;
  const std::optional<TS::NloptRun>& nl = p.th.nlopt.run;
  const auto hist = nl ? nl->history_J : std::vector<double>{};
  if (hist.size() >= 2) {
    LinePlot hp;
    hp.title = "gradient method history";
    hp.x_label = "iteration";
    hp.y_label = "energy (J)";
    Series h{"SLSQP energy", {}, hist, colour_for("gradient")};
    for (size_t i = 0; i < hist.size(); ++i) h.x.push_back(static_cast<double>(i + 1));
    // from the start: the reference energy at evaluation 0
    if (std::isfinite(section.energy_reference_J)) {
      h.x.insert(h.x.begin(), 0.0);
      h.y.insert(h.y.begin(), section.energy_reference_J);
      hp.x_label = "iteration (0: the reference start)";
    }
    hp.series = {h};
    conv.figure(figures.line(
        "slsqp_history", hp,
        "The gradient method's energy at each of its evaluations (points may be infeasible)."));
  }
}

// the accuracy of the simulation behind every number
Table accuracy_table(const Page& p) {
  const TS::Optimised& th = p.th;
  const auto& rep = th.replay;
  const auto& integ = th.integration;
  const std::string fine = as_text(integ.fine_steps_factor) + "x";
  Table acc;
  acc.caption = "Accuracy of the simulation behind every number above.";
  acc.header = {"check", "value"};
  acc.rows = {{"integration", integ.method},
              {"step", format_sig(integ.step_s, 3) + " s"},
              {"energy error against " + fine + " the steps",
               format_sig(integ.energy_error_vs_fine_steps, 3)},
              {"θ3 error against " + fine + " the steps",
               format_sig(integ.theta3_error_vs_fine_steps_rad, 3) + " rad"},
              {"open-loop voltage replay", rep.integrator},
              {"largest replay error", format_sig(rep.max_error_rad, 3) + " rad (tolerance " +
                                           format_sig(rep.tolerance_rad, 3) + " rad)"}};
  return acc;
}

}  // namespace

// the ball in the tray, release and flight
Section ball_section(const Page& p, FigureWriter& figures) {
  Section ball;
  ball.id = "ball";
  ball.heading = "The ball in the tray, release and flight";
  add_tray_angles(p, figures, ball);
  add_release(p, ball);
  add_throw_locus(p, figures, ball);
  return ball;
}

// both optimisers' convergence and the simulation's accuracy
Section convergence_section(const Page& p, FigureWriter& figures) {
  Section conv;
  conv.id = "convergence";
  conv.heading = "Convergence of the optimisers";
  Table ct = add_idp_convergence(p, figures, conv);
  add_slsqp_history(p, figures, conv);
  if (!ct.rows.empty()) conv.table(std::move(ct));
  if (p.ran) conv.table(accuracy_table(p));
  return conv;
}

}  // namespace armstudy::report::throwing_page
