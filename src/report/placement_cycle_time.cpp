// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// the placement page's cycle-time section: the fastest placement under the joint limits, the
// limits that bind there, the least cycle time over root locations beside the energy maps,
// and the trade-off with the energy objective (both optima, the Pareto front between them)
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "report/number_format.hpp"
#include "report/placement_page.hpp"
#include "report/results_fields.hpp"
#include "report/study_sections.hpp"

namespace armstudy::report::placement_page {
namespace {

std::string pair_text(const PS::Pair& p, const std::string& unit) {
  return "(" + format_sig(p[0], 4) + ", " + format_sig(p[1], 4) + ") " + unit;
}

std::string opt_sig(const std::optional<double>& v, int digits) {
  return v ? format_sig(*v, digits) : std::string("n/a");
}

std::string percent(double v) { return format_sig(v, 3) + " %"; }

// the energy of a fastest motion with its error, or "n/a"
std::string fast_text(const std::optional<studies::placement::FastEnergy>& f) {
  return f ? format_sig(f->energy_J, 5) + " ± " + format_sig(f->error_J, 2) : std::string("n/a");
}

// the limits the fastest motion runs on, and the largest use of the others, in words
std::string limits_words(const PS::CycleTimeAt& at) {
  std::string bind, rest;
  for (const auto& u : at.limits) {
    const std::string what = "joint " + as_text(u.joint) + "'s " + u.kind;
    if (u.binding)
      bind += (bind.empty() ? "" : ", ") + what;
    else
      rest += (rest.empty() ? "" : ", ") + what + " at " + percent(100 * u.ratio);
  }
  return (bind.empty() ? std::string("no limit binds") : "on " + bind) +
         (rest.empty() ? "" : " (" + rest + ")");
}

// the optimum of each configuration
Table optimum_table(const PS::CycleTimeSection& ct) {
  Table t;
  t.caption = "The fastest placement of each configuration.";
  t.header = {"conf.",          "least cycle time (s)",      "root (X, Y) (m)",
              "x_S (m), φ (°)", "limits the motion runs on", "its energy (J)"};
  for (const auto& c : ct.configurations) {
    const auto& o = c.optimum;
    if (!o.found || !o.duration_s || !o.root_xy_m) {
      t.rows.push_back({as_text(c.configuration), "none: " + o.reason, "", "", "", ""});
      continue;
    }
    t.rows.push_back(
        {as_text(c.configuration),
         format_to_error(*o.duration_s, o.duration_error_s.value_or(NAN)) + " ± " +
             format_sig(o.duration_error_s.value_or(NAN), 2),
         pair_text(*o.root_xy_m, "") + " ± " + format_sig(o.root_error_m.value_or(NAN), 2) +
             (o.set_by_margin.value_or(false) ? ", on the clearance margin" : ""),
         format_sig(o.x_s_m.value_or(NAN), 6) + ", " + format_sig(o.phi_deg.value_or(NAN), 7),
         o.converged ? limits_words(*o.converged) : "n/a", fast_text(o.fast_motion_energy)});
  }
  return t;
}

// both optima of each program and configuration, both objectives at each
Table comparison_table(const PS& pl, const PS::CycleTimeSection& ct) {
  Table t;
  t.caption =
      "Both objectives at both optima: the least cycle time under the limits, the "
      "program's energy in T = " +
      format_sig(pl.duration_s, 4) +
      " s (the energy objective) and the energy of the fastest motion there.";
  t.header = {"program, conf.", "placement", "least cycle time (s)", "energy in T (J)",
              "fastest motion's energy (J)"};
  for (const auto& c : ct.configurations)
    for (const auto& e : c.at_energy_optima) {
      const std::string who = e.program + ", " + as_text(c.configuration);
      t.rows.push_back({who, "energy optimum " + pair_text(e.root_xy_m, "m"),
                        opt_sig(e.cycle_time.duration_s, 7), format_sig(e.energy_J, 7),
                        fast_text(e.fast_motion_energy)});
      if (!c.optimum.found || !c.optimum.root_xy_m) continue;
      t.rows.push_back({who, "fastest placement " + pair_text(*c.optimum.root_xy_m, "m"),
                        opt_sig(c.optimum.duration_s, 7),
                        opt_sig(e.energy_at_time_optimum_J, 7) +
                            (e.status_at_time_optimum == "feasible"
                                 ? ""
                                 : " (" + status_text(e.status_at_time_optimum) + ")"),
                        fast_text(c.optimum.fast_motion_energy)});
    }
  return t;
}

// the Pareto fronts of the first configuration (the second is its mirror image): the
// program's energy in T and, grey dashed, the fastest motion's energy at the first program's
// placements; a curve is broken where no placement of the front lies (a gap of more than a
// quarter of the front's time range)
LinePlot front_plot(const PS::CycleTimeSection& ct) {
  LinePlot plot;
  plot.title = "cycle time against energy, placements between the two optima";
  plot.x_label = "least cycle time (s)";
  plot.y_label = "energy (J)";
  if (ct.configurations.empty()) return plot;
  const auto& c = ct.configurations.front();
  Series fast{"the fastest motion's energy there", {}, {}, {120, 120, 120}};
  fast.style = LineStyle::kDashed;
  for (const auto& e : c.at_energy_optima) {
    if (e.front.empty()) continue;
    Series in_t{e.program + ", conf. " + as_text(c.configuration) + ": energy in T",
                {},
                {},
                colour_for(e.program + "/" + as_text(c.configuration))};
    in_t.markers = e.front.size() <= 60;
    const double gap = 0.25 * (e.front.back().cycle_time_s - e.front.front().cycle_time_s);
    const bool first = fast.x.empty();
    for (size_t k = 0; k < e.front.size(); ++k) {
      const auto& p = e.front[k];
      if (k && p.cycle_time_s - e.front[k - 1].cycle_time_s > gap) {
        in_t.x.push_back(NAN);
        in_t.y.push_back(NAN);
        if (first) fast.x.push_back(NAN), fast.y.push_back(NAN);
      }
      in_t.x.push_back(p.cycle_time_s);
      in_t.y.push_back(p.energy_J);
      if (first) fast.x.push_back(p.cycle_time_s), fast.y.push_back(p.fast_motion_energy_J);
    }
    plot.series.push_back(std::move(in_t));
  }
  if (!fast.x.empty()) plot.series.push_back(std::move(fast));
  return plot;
}

// what either placement gives up, per program, in the first configuration (the second is its
// mirror image)
std::string trade_off_words(const PS& pl, const PS::CycleTimeSection& ct) {
  std::string out;
  for (const auto& c : ct.configurations) {
    if (&c != &ct.configurations.front()) break;
    const auto& o = c.optimum;
    if (!o.found || !o.duration_s) continue;
    for (const auto& e : c.at_energy_optima) {
      if (!e.cycle_time.duration_s || !e.energy_at_time_optimum_J) continue;
      const double slower = 100 * (*e.cycle_time.duration_s / *o.duration_s - 1);
      const double dearer = 100 * (*e.energy_at_time_optimum_J / e.energy_J - 1);
      out +=
          std::string(out.empty() ? "" : " ") + e.program + ", conf. " + as_text(c.configuration) +
          ": at the fastest placement the cycle can be " + format_sig(*o.duration_s, 6) +
          " s, and the " + e.program + " motion in T = " + format_sig(pl.duration_s, 4) +
          " s costs " + format_sig(*e.energy_at_time_optimum_J, 5) + " J there (" +
          percent(dearer) + " more than the " + format_sig(e.energy_J, 5) +
          " J at its energy optimum); at the energy optimum the fastest cycle is " +
          format_sig(*e.cycle_time.duration_s, 6) + " s (" + percent(slower) + " longer)" +
          (e.fast_motion_energy && o.fast_motion_energy
               ? ", and running flat out costs " + format_sig(e.fast_motion_energy->energy_J, 4) +
                     " J there against " + format_sig(o.fast_motion_energy->energy_J, 4) +
                     " J at the fastest placement"
               : std::string()) +
          "; " + as_text(static_cast<long long>(e.front.size())) +
          " placements on the front between them.";
    }
  }
  return out;
}

}  // namespace

std::optional<Section> cycle_time_section(const PS& pl, FigureWriter& figures) {
  if (!pl.cycle_time) return std::nullopt;
  const PS::CycleTimeSection& ct = *pl.cycle_time;
  Section s;
  s.id = "cycle-time";
  s.heading = "Cycle time: the fastest placement and its energy";
  s.paragraph(
      "Where to put the arm so that the task line is traversed fastest, rest to rest, under "
      "the joint limits |q̇| ≤ " +
      pair_text(ct.velocity_limit_rad_s, "rad/s") + " and |τ| ≤ " +
      pair_text(ct.torque_limit_Nm, "N m") +
      (ct.acceleration_limit_rad_s2
           ? " and |q̈| ≤ " + pair_text(*ct.acceleration_limit_rad_s2, "rad/s²")
           : std::string()) +
      ". At every admissible node of the energy maps' grid (the same clearance margin; the "
      "energy objective's torque and power limits do not apply) the time-optimal study's exact "
      "solver finds the least traversal time; a compass search refines the fastest node and "
      "the time-optimal study converges its duration there (extrapolated over its grids). The "
      "duration's error adds the time's change within the location's resolution. The energy "
      "of a fastest motion is the energy objective's integral of |τ1 q̇1| + |τ2 q̇2| over the "
      "time-optimal motion, on the exact solver's grid with every interval halved, the change "
      "from the unhalved grid its error.");
  s.table(optimum_table(ct));
  cycle_time_maps(pl, figures, s);
  s.table(comparison_table(pl, ct));
  const std::string words = trade_off_words(pl, ct);
  if (!words.empty())
    s.paragraph("What either placement gives up. " + words +
                (ct.configurations.size() > 1
                     ? " Configuration 2 gives the same figures at the mirror images (the table)."
                     : ""));
  const LinePlot plot = front_plot(ct);
  if (!plot.series.empty())
    s.figure(figures.line(
        "cycle_time_front", plot,
        "The Pareto front of the least cycle time and the program's energy in T over the "
        "placements admissible for both objectives (the map's nodes and both optima, each "
        "evaluated again: the time on the converged uniform grid, the energy on the sweep's " +
            as_text(pl.samples) + " samples), configuration " +
            as_text(ct.configurations.front().configuration) +
            (ct.configurations.size() > 1 ? " (configuration 2 is its mirror image)" : "") +
            "; left end the fastest placement, right end the energy optimum. Grey dashed: what the "
            "fastest motion costs at the first program's placements; a gap in a curve: no "
            "placement of the front "
            "there."));
  return s;
}

}  // namespace armstudy::report::placement_page
