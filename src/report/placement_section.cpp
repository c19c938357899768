// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// the placement study of Kopmaz (2016): optima, time series (figs. 9.1-9.5), the method and
// the convergence; the maps, energy over direction angle (9.11), root loci (9.30) and pareto
// front are in placement_maps.cpp
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

#include "core/types.hpp"
#include "report/arm_model_paragraphs.hpp"
#include "report/number_format.hpp"
#include "report/placement_page.hpp"
#include "report/replay_section.hpp"
#include "report/results_fields.hpp"
#include "report/results_record.hpp"
#include "report/study_sections.hpp"
#include "studies/placement/converge.hpp"
#include "studies/placement/study_results.hpp"

namespace armstudy::report {
namespace {

using nlohmann::json;

using namespace placement_page;  // PS and the helpers both files use

std::string pair_str(const PS::Pair& p, int digits) {
  return "(" + format_sig(p[0], digits) + ", " + format_sig(p[1], digits) + ")";
}
std::string pair_str(const std::optional<PS::Pair>& p, int digits) {
  return p ? pair_str(*p, digits) : "n/a";
}
// a motion whose peak torque is withheld (unbounded at a singular pose); its energy may stand
bool no_peak(const PS::Metrics& o) {
  return o.singular_trajectory.value_or(false) && !o.peak_torque_Nm.has_value();
}
constexpr const char* kSingularText = "singular: energy not converged, peak torque unbounded";
constexpr const char* kPeakText = "peak torque unbounded (singular pose)";
// the energy with its quadrature error estimate, e.g. "17.10670 ± 2.1e-09"
std::string energy_text(const PS::Metrics& o, int digits) {
  if (no_energy(o)) return kSingularText;
  std::string t = format_sig(o.energy_J, digits);
  if (o.energy_error_J) t += " ± " + format_sig(*o.energy_error_J, 2);
  return t;
}
std::string peak_text(const PS::Metrics& o, int digits) {
  if (no_energy(o)) return kSingularText;
  return no_peak(o) ? std::string(kPeakText) : pair_str(o.peak_torque_Nm, digits);
}
// "inner circle |L1 - L2|" etc. for a binding name
std::string binding_first(const PS::Optimum& o, const PS& pl) {
  const PS::Decision& d = o.decided_by;
  const std::string& b = d.binding;
  const std::string margin = format_sig(d.margin_m, 3) + " m";
  const std::string joint = d.joint ? as_text(*d.joint) : "null";
  if (b == "inner_clearance")
    return "the " + margin +
           " clearance margin to the inner circle |L1 - L2| = " + format_sig(pl.annulus_m[0], 3) +
           " m";
  if (b == "outer_clearance")
    return "the " + margin +
           " clearance margin to the outer circle L1 + L2 = " + format_sig(pl.annulus_m[1], 3) +
           " m";
  if (b == "torque_limit") return "the torque limit of joint " + joint;
  if (b == "power_limit") return "the power limit of joint " + joint;
  if (b == "interior")
    return "interior (clearances exceed the margin by " + format_sig(d.inner_slack_m, 3) +
           " m inner, " + format_sig(d.outer_slack_m, 3) + " m outer)";
  return b;
}
// ... and every other active constraint
std::string binding_text(const PS::Optimum& o, const PS& pl) {
  const PS::Decision& d = o.decided_by;
  std::vector<std::pair<std::string, std::optional<int>>> active;
  for (const auto& a : d.active) active.emplace_back(a.constraint, a.joint);
  return binding_first(o, pl) + placement_also_active(active);
}
bool set_by_margin(const PS::Optimum& o) { return o.decided_by.set_by_margin; }

// an optimum's motion in the plots over time
struct SeriesOwner {
  std::string label, colour_key;
  const PS::Series* series;
};
using Column = std::vector<double> PS::Series::*;

// one line plot over time of `columns` of every owner: colour per owner, line style per
// column (solid joint 1, dashed joint 2), legend "<owner>, <column label>"
LinePlot optima_plot(const std::string& title, const std::string& y_label,
                     const std::vector<SeriesOwner>& owners, const std::vector<Column>& columns,
                     const std::vector<std::string>& labels) {
  LinePlot plot;
  plot.title = title;
  plot.x_label = "time (s)";
  plot.y_label = y_label;
  for (const SeriesOwner& o : owners) {
    const std::vector<double>& t = o.series->t_s;
    size_t curve = 0;
    for (const Column c : columns) {
      const std::vector<double>& y = o.series->*c;
      if (y.empty() || y.size() != t.size()) continue;
      Series s;
      s.x = t;
      s.y = y;
      s.colour = colour_for(o.colour_key.empty() ? o.label : o.colour_key);
      s.style = curve == 0   ? LineStyle::kSolid
                : curve == 1 ? LineStyle::kDashed
                             : LineStyle::kDotted;
      const std::string what = curve < labels.size() ? labels[curve] : "";
      // several owners: colour names the owner, style the column (legend entries below)
      s.label = columns.size() == 1 ? o.label : owners.size() == 1 ? what : "";
      // a single owner: colour per curve reads better than style alone
      if (owners.size() == 1 && columns.size() + labels.size() > 2)
        s.colour = colour_for("joint" + std::to_string(curve + 1));
      plot.series.push_back(std::move(s));
      ++curve;
    }
  }
  // the legend of several owners' curves: one entry per owner (its colour), one per column
  // (its line style), instead of every owner-column pair
  if (owners.size() > 1 && columns.size() > 1) {
    for (const SeriesOwner& o : owners) {
      Series key;
      key.label = o.label;
      key.colour = colour_for(o.colour_key.empty() ? o.label : o.colour_key);
      plot.series.push_back(std::move(key));
    }
    for (size_t c = 0; c < columns.size() && c < labels.size(); ++c) {
      Series key;
      key.label = labels[c];
      key.colour = {60, 60, 60};
      key.style = c == 0 ? LineStyle::kSolid : c == 1 ? LineStyle::kDashed : LineStyle::kDotted;
      plot.series.push_back(std::move(key));
    }
  }
  return plot;
}

Section task_section(const PS& pl) {
  Section s;
  s.id = "task";
  s.heading = "Task and search";
  s.new_page = false;
  Table t;
  t.caption = "The task, the search and its limits (defaults filled in).";
  t.header = {"quantity", "value"};
  auto row = [&](const std::string& k, const std::string& v) { t.rows.push_back({k, v}); };
  row("Lmax = 4 sqrt(L1 L2)", format_sig(pl.lmax_m, 5) + " m");
  row("line length L",
      format_sig(pl.length_m, 5) + " m (" + format_sig(pl.length_fraction, 4) + " Lmax)");
  row("duration T", format_sig(pl.duration_s, 4) + " s");
  row("samples per trajectory", as_text(pl.samples));
  row("singularity margin", format_sig(pl.singularity_margin_m, 4) + " m");
  row("workspace annulus", pair_str(pl.annulus_m, 5) + " m");
  row("torque limits [joint 1, joint 2]",
      pl.torque_limits_Nm ? pair_str(pl.torque_limits_Nm, 5) + " N m" : "none");
  row("power limits [joint 1, joint 2]",
      pl.power_limits_W ? pair_str(pl.power_limits_W, 5) + " W" : "none");
  {
    const auto& ti = pl.thesis_intervals;
    row("thesis x_S interval (case " + as_text(ti.x_s_case) + " of 4.7-4.9)",
        "[" + format_sig(ti.x_s_init_m, 5) + ", " + format_sig(ti.x_s_fin_m, 5) + "] m");
  }
  t.narrow = true;
  s.table(std::move(t));
  arm_model_paragraphs(pl.arm_model, s);
  if (pl.geometry_counts) {
    const auto& c = *pl.geometry_counts;
    Table ct;
    ct.caption =
        "Candidates of the geometric sweep (x_S grid × φ in [0°, 180°]) and the "
        "thesis's own intervals against the exact annulus check.";
    ct.header = {"candidates", "count"};
    for (const auto& [n, label] : std::vector<std::pair<int, const char*>>{
             {c.total, "total"},
             {c.unreachable, "unreachable (part of the line outside the annulus)"},
             {c.singular, "inside the margin (closer to a boundary than the margin)"},
             {c.clear, "clear of both boundaries"},
             {c.thesis_admitted, "the thesis's own grid (its intervals 4.7-4.13)"},
             {c.thesis_rejected_by_exact_check, "of those, rejected by the exact check"},
             {c.exact_accepted_outside_thesis,
              "accepted by the exact check outside the thesis's φ interval"}})
      ct.rows.push_back({label, as_text(n)});
    ct.narrow = true;
    s.table(std::move(ct));
  }
  return s;
}

// what decides each optimum, how converged the refinement and the energy integral are
Table decision_table(const PS& pl) {
  Table t;
  t.caption =
      "What decides each optimum: the binding constraint (a clearance margin to a "
      "workspace circle, a torque or power limit) or 'interior' when none is active; "
      "the constrained refinement's final tolerance (the relative energy a last COBYLA "
      "restart still gained, target 1e-7), the relative error estimate of the optimum's "
      "energy (adaptive Gauss-Kronrod quadrature, asked for 1e-9) and its sampled peak "
      "torque's convergence (samples doubled until it changes by less than 1e-3).";
  t.header = {"program, configuration", "decided by", "inner / outer clearance − margin (m)",
              "refinement tolerance", "energy error; peak torque: samples, change on doubling"};
  for (const auto& o : pl.optima) {
    std::string tol = "not refined", conv = "n/a";
    if (o.refinement.method)
      tol = format_sig(o.refinement.final_tolerance_rel, 2) +
            (o.refinement.converged ? " (converged)" : " (NOT converged)");
    if (o.energy_convergence) {
      const auto& c = *o.energy_convergence;
      if (no_energy(o))
        conv = kSingularText;
      else
        conv = (c.quadrature
                    ? "error " + format_sig(c.quadrature->error_J / c.quadrature->energy_J, 2) +
                          " (quadrature); "
                    : std::string()) +
               (no_peak(o) ? std::string(kPeakText)
                           : "peak: " + as_text(c.samples) + " samples, " +
                                 format_sig(c.peak_torque_rel_change, 2));
    }
    // a slack within roundoff of 0 is the binding constraint itself
    const auto slack = [&](double v) {
      return std::abs(v) < 1e-12 ? std::string("0 (binds)") : format_sig(v, 3);
    };
    t.rows.push_back({id_label(o), binding_text(o, pl),
                      slack(o.decided_by.inner_slack_m) + " / " + slack(o.decided_by.outer_slack_m),
                      tol, conv});
    t.swatches.push_back(css_colour(colour_for(id_key(o))));
  }
  return t;
}

// the energy of each margin-bound optimum over the clearance margin
std::optional<Figure> margin_figure(const PS& pl, FigureWriter& figures) {
  LinePlot plot;
  plot.title = "optimum energy against the clearance margin";
  plot.x_label = "clearance margin (m)";
  plot.y_label = "least admissible energy (J)";
  std::string range;
  for (const auto& o : pl.optima) {
    if (!set_by_margin(o)) continue;
    Series se;
    se.label = id_label(o);
    se.colour = colour_for(id_key(o));
    se.markers = true;
    for (const auto& m : o.margin_sensitivity) {
      if (!m.found || !m.optimum || no_energy(*m.optimum)) continue;
      se.x.push_back(m.margin_m);
      se.y.push_back(m.optimum->energy_J);
    }
    if (se.x.size() < 2) continue;
    range += (range.empty() ? "" : "; ") + id_label(o) + " " + format_sig(se.y.front(), 5) +
             " J at " + format_sig(se.x.front(), 3) + " m to " + format_sig(se.y.back(), 5) +
             " J at " + format_sig(se.x.back(), 3) + " m";
    // the binding circle may change along the curve (a kink)
    std::string prev, changes;
    for (const auto& m : o.margin_sensitivity) {
      const std::string b = m.optimum ? m.optimum->binding : std::string();
      if (!prev.empty() && !b.empty() && b != prev)
        changes += ", " +
                   std::string(b == "outer_clearance"   ? "the outer circle"
                               : b == "inner_clearance" ? "the inner circle"
                               : b == "torque_limit"    ? "a torque limit"
                               : b == "power_limit"     ? "a power limit"
                                                        : b) +
                   " binds first from " + format_sig(m.margin_m, 3) + " m";
      if (!b.empty()) prev = b;
    }
    range += changes;
    plot.series.push_back(std::move(se));
  }
  if (plot.series.empty()) return std::nullopt;
  return figures.line(
      "margin_sensitivity", plot,
      "Margin sensitivity: each optimum set by a clearance margin, re-solved (sweep "
      "and constrained refinement) at margins from 0.005 m to 0.05 m. The energy "
      "falls as the margin shrinks: the margin, not the physics, decides these "
      "optima (" +
          range + "). The case's margin is " + format_sig(pl.singularity_margin_m, 3) + " m.");
}

// a located coordinate with its error, to the digits the error leaves, e.g. "0.4613520 ± 3e-08";
// `digits` significant digits when the error is not known
std::string located_text(double value, double error, int digits) {
  if (!(error > 0) || !std::isfinite(error) || !std::isfinite(value) || value == 0)
    return format_sig(value, digits);
  return format_to_error(value, error, digits) + " ± " + format_sig(error, 1);
}

// the refined optimum per program and configuration; `owners` gets each optimum's series
Table optima_table(const PS& pl, std::vector<SeriesOwner>* owners) {
  Table t;
  t.caption =
      "Refined optimum per motion program and configuration (the grid optimum's "
      "energy beside it). The energy's ± is its quadrature's error estimate; x_S's and φ's "
      "are their distance from the minimum of that converged energy, which the refinement "
      "minimises (a quadratic fitted around the optimum, with its truncation and the "
      "quadrature's error). Root (X, Y) in the frame fixed to the line (4.14); peaks "
      "are [joint 1, joint 2].";
  t.header = {"program, configuration",
              "energy (J)",
              "grid energy (J)",
              "x_S (m)",
              "φ (deg)",
              "root (X, Y) (m)",
              "min |sin q2|",
              "peak torque (N m)",
              "peak power (W)",
              "signed work (J)"};
  for (const auto& o : pl.optima) {
    t.rows.push_back({id_label(o), energy_text(o, 7), format_sig(o.grid_energy_J, 6),
                      located_text(o.x_s_m, o.refinement.x_s_error_m, 6),
                      located_text(o.phi_deg, o.refinement.phi_error_deg, 6),
                      pair_str(o.root_xy_m, 5), format_sig(o.min_abs_sin_elbow, 3), peak_text(o, 4),
                      no_peak(o) ? std::string("n/a") : pair_str(o.peak_power_W, 4),
                      format_sig(o.signed_work_J, 3)});
    t.swatches.push_back(css_colour(colour_for(id_key(o))));
    owners->push_back({id_label(o), id_key(o), &o.series});
  }
  return t;
}

// one note per binding constraint, naming the optima it decides
void add_binding_notes(const PS& pl, Section& s) {
  std::map<std::string, std::string> by;
  for (const auto& o : pl.optima)
    if (set_by_margin(o))
      by[binding_text(o, pl)] += (by[binding_text(o, pl)].empty() ? "" : ", ") + id_label(o);
  for (const auto& [what, who] : by)
    s.note("The optimum of " + who + " is set by " + what +
           ", not by the physics: it lies on the margin and its energy keeps falling as the "
           "margin shrinks (see the margin sensitivity below).");
}

// the note on one of the thesis's own printed placements (`label`): what the exact check
// finds there and its energies
std::string thesis_placement_note(const PS& pl, const std::string& label) {
  std::string energies, text;
  const PS::Evaluation* first = nullptr;
  for (const auto& e : pl.evaluations) {
    if (e.label != label) continue;
    if (!first) first = &e;
    energies +=
        (energies.empty() ? "" : "; ") + id_label(e) + " " +
        (no_energy(e) ? std::string(kSingularText)
                      : format_sig(e.energy_J, 5) + " J" +
                            (e.energy_error_J ? " ± " + format_sig(*e.energy_error_J, 2) : "")) +
        (std::isfinite(e.saving_percent)
             ? " (the optimum saves " + format_sig(e.saving_percent, 3) + " %)"
             : "");
  }
  const PS::Evaluation& e = *first;
  const std::string& status = e.status;
  text = "The thesis's printed placement '" + label + "' (x_S = " + format_sig(e.x_s_m, 5) +
         " m, φ = " + format_sig(e.phi_deg, 5) + "°) is " +
         (e.energy_convergence && e.energy_convergence->touches_boundary && status != "unreachable"
              ? std::string("on a workspace boundary")
              : status_text(e.status)) +
         " by the exact check";
  if (status == "unreachable")
    text += ": with its printed digits part of the line lies outside the annulus (by " +
            format_sig(-e.boundary_distance_m, 3) + " m), so no motion exists there.";
  else if (no_energy(e))
    text += " (clearance " + format_sig(e.boundary_distance_m, 3) + " m), so its motion is " +
            kSingularText + "; no energy, peak torque or saving is given for it.";
  else if (no_peak(e))
    text += " (clearance " + format_sig(e.boundary_distance_m, 3) +
            " m): its energy is finite and converged (adaptive quadrature, with its error "
            "estimate), but " +
            (e.note && *e.note == studies::placement::kFoldedElbowNote
                 ? "the elbow folds on the inner circle, where both joint rates reverse at "
                   "once: the energy holds that reversal (the limit of the lines just outside, "
                   "docs/placement.md), the peak torque is an impulse, so none is given"
                 : "its peak torque is unbounded (a singular pose), so no peak torque is given") +
            "; its energies: " + energies + ".";
  else if (status == "singular")
    text += ": it comes within " + format_sig(e.boundary_distance_m, 3) +
            " m of a workspace boundary (smallest |sin q2| " + format_sig(e.min_abs_sin_elbow, 3) +
            "), so it is not admissible; its energies (adaptive quadrature, with their error "
            "estimates): " +
            energies + ".";
  else
    text += "; its energies here: " + energies + ".";
  return text;
}

// the source's own printed placements, when the case evaluates them: one note per placement
void add_thesis_placements(const PS& pl, Section& s) {
  std::vector<std::string> labels;
  for (const auto& e : pl.evaluations) {
    const std::string& label = e.label;
    if (label.rfind("thesis", 0) == 0 &&
        std::find(labels.begin(), labels.end(), label) == labels.end())
      labels.push_back(label);
  }
  for (const std::string& label : labels) s.note(thesis_placement_note(pl, label));
}

// whose motion a row of plots over time shows: the optima, or the thesis's printed placements
struct MotionPlots {
  std::string file_prefix;  ///< "" (the optima) or "printed_"
  std::string whose;        ///< "of the optima", in titles
  std::string intro;        ///< the paragraph before the plots
  std::string energy_note;  ///< the energy figure's caption's tail
};

// the motion of each owner over time, two plots to a row
void add_motion_plots(const PS& pl, const std::vector<SeriesOwner>& owners,
                      const std::vector<SeriesOwner>& energy_owners, const MotionPlots& what,
                      FigureWriter& figures, Section& s) {
  struct Quantity {
    const char* name;
    const char* plural;
    Column key1;
    Column key2;
    const char* unit_label;
    int thesis_kind;  ///< 0..4: angles, velocities, accelerations, torques, powers
  };
  const Quantity quantities[] = {
      {"joint_angles", "joint angles", &PS::Series::q1_rad, &PS::Series::q2_rad,
       "joint angle (rad)", 0},
      {"joint_velocities", "joint velocities", &PS::Series::qd1_rad_s, &PS::Series::qd2_rad_s,
       "joint velocity (rad/s)", 1},
      {"joint_accelerations", "joint accelerations", &PS::Series::qdd1_rad_s2,
       &PS::Series::qdd2_rad_s2, "joint acceleration (rad/s²)", 2},
      {"joint_torques", "joint torques", &PS::Series::tau1_Nm, &PS::Series::tau2_Nm,
       "joint torque (N m)", 3},
      {"joint_powers", "powers", &PS::Series::power1_W, &PS::Series::power2_W, "power (W)", 4},
  };
  s.paragraph(what.intro);
  for (const Quantity& q : quantities) {
    const std::string plural = q.plural;
    LinePlot plot = optima_plot(plural + " " + what.whose, q.unit_label, owners, {q.key1, q.key2},
                                {"joint 1", "joint 2"});
    if (plot.series.empty()) continue;
    s.figure(half(figures.line(
        what.file_prefix + q.name, half_size(plot),
        plural + " over time (the thesis's " + thesis_figure(pl, q.thesis_kind) + ").")));
  }
  LinePlot energy = optima_plot("actuator energy " + what.whose, "energy used so far (J)",
                                energy_owners, {&PS::Series::energy_J}, {"energy"});
  if (!energy.series.empty())
    s.figure(half(figures.line(what.file_prefix + "energy", half_size(energy),
                               "Actuator energy used up to each instant, ∫ |M1 dθ1| + "
                               "|M2 d(θ2 - θ1)|" +
                                   what.energy_note)));
}

void add_optima_plots(const PS& pl, const std::vector<SeriesOwner>& owners, FigureWriter& figures,
                      Section& s) {
  add_motion_plots(
      pl, owners, owners,
      {"", "of the optima",
       "The motion of each optimum over time, two plots to a row: colour is the "
       "program and configuration (as in the tables), solid is joint 1 (q1, link 1 from "
       "the base), dashed joint 2 (q2, the elbow, relative to link 1).",
       "; the end value is the optimum's energy."},
      figures, s);
}

// "conf. 2 (thesis-config-2: x_S = 0.4764 m, φ = 155.18°)"
std::string printed_where(const PS::Evaluation& e) {
  return "conf. " + as_text(e.configuration) + " (" + e.label +
         ": x_S = " + format_sig(e.x_s_m, 6) + " m, φ = " + format_sig(e.phi_deg, 7) + "°)";
}

// the motion at the thesis's printed placements, beside the optima's (the thesis draws the
// cycloidal program's motion at its optima: Figures 9.1-9.5 for example 1, 9.6-9.10 for
// example 2, ...); none when the case evaluates no printed placement
std::optional<Section> printed_motion_section(const PS& pl, FigureWriter& figures) {
  const std::string program = printed_program(pl);
  std::vector<SeriesOwner> owners, energy_owners;
  std::string unreachable, meant_lines, without_energy, singular;
  const auto add = [](std::string& list, const std::string& item) {
    list += (list.empty() ? "" : "; ") + item;
  };
  for (const PS::Evaluation* e : printed_placements(pl, program)) {
    std::string label = printed_label(*e);
    if (!e->series) {
      add(unreachable, printed_where(*e));
      // the line the printed digits mean, where the case evaluates it (as the source
      // comparison does for the printed energies)
      const PS::Evaluation* meant = nullptr;
      for (const auto& t : pl.evaluations)
        if (t.label == e->label + "-tangent" && t.program == e->program &&
            t.configuration == e->configuration && t.series)
          meant = &t;
      if (!meant) continue;
      add(meant_lines, printed_where(*meant));
      e = meant;
      label += " (tangent line)";
    }
    owners.push_back({label, printed_key(*e), &*e->series});
    if (e->singular_trajectory.value_or(false)) add(singular, printed_where(*e));
    // the sampled running energy must end on the printed energy: on a folded elbow it misses
    // the reversal's jump term (docs/placement.md), so it is not drawn
    const std::vector<double>& en = e->series->energy_J;
    if (!no_energy(*e) && !en.empty() && std::isfinite(en.back()) &&
        std::abs(en.back() - e->energy_J) <= 1e-2 * std::abs(e->energy_J))
      energy_owners.push_back(owners.back());
    else
      add(without_energy,
          printed_where(*e) + ", energy " + energy_text(*e, 7) + " J" +
              (e->note && *e->note == studies::placement::kFoldedElbowNote
                   ? " (the elbow folds: the sampled integral misses the reversal's jump term, "
                     "which the printed energy holds, docs/placement.md)"
                   : " (its sampled running energy does not end on it)"));
  }
  if (owners.empty() && unreachable.empty()) return std::nullopt;
  Section s;
  s.id = "printed-motion";
  s.heading = "The motion at the thesis's printed placements";
  if (!unreachable.empty())
    s.note("No motion at " + unreachable +
           ": with the printed digits the line leaves the workspace annulus, where no motion "
           "exists" +
           (meant_lines.empty()
                ? std::string(".")
                : "; drawn instead: the line the printed digits mean, " + meant_lines + "."));
  if (owners.empty()) return s;
  std::string intro =
      "The " + program +
      " program's motion at the placements the thesis prints as its optima, as the thesis "
      "draws it (the same program, both configurations), beside the optima's motion above: "
      "colour is the configuration, solid is joint 1 (q1, link 1 from the base), dashed joint "
      "2 (q2, the elbow, relative to link 1; the thesis draws the absolute angle θ2 = q1 + q2 "
      "and its rate). Computed by armstudy's model, not read off the thesis's figures.";
  if (!singular.empty())
    intro += " Singular motions (" + singular +
             "): near the singular pose the accelerations, torques and powers grow without "
             "bound, and the plots show their samples (at most 101 points of each motion), whose "
             "peaks are the sampling's, not the motion's.";
  std::string energy_note =
      "; its end value is the placement's energy (Evaluated placements) to within the "
      "sampled integral's error.";
  add_motion_plots(pl, owners, energy_owners,
                   {"printed_", "at the printed placements", intro, energy_note}, figures, s);
  if (!without_energy.empty())
    s.note("The running energy is not drawn for " + without_energy + ".");
  return s;
}

Section optima_section(const PS& pl, FigureWriter& figures) {
  Section s;
  s.id = "optima";
  s.heading = "Optimal placements";
  std::vector<SeriesOwner> owners;
  Table t = optima_table(pl, &owners);
  if (t.rows.empty()) {
    s.paragraph("No program and configuration has an admissible placement.");
  } else {
    s.table(std::move(t));
    s.table(decision_table(pl));
    add_binding_notes(pl, s);
    if (auto fig = margin_figure(pl, figures)) s.figure(std::move(*fig));
  }
  Table u;
  u.caption = "Programs and configurations without an admissible placement.";
  u.header = {"program, configuration", "why"};
  for (const auto& o : pl.unsolved) u.rows.push_back({id_label(o), o.reason});
  if (!u.rows.empty()) s.table(std::move(u));

  add_thesis_placements(pl, s);
  if (owners.empty()) return s;
  add_optima_plots(pl, owners, figures, s);
  return s;
}

// (over 60 lines, kept whole: the section's two tables in page order)
Section convergence_and_evaluations(const PS& pl) {
  Section s;
  s.id = "convergence";
  s.heading = "Convergence and evaluated placements";
  if (pl.convergence) {
    const auto& c = *pl.convergence;
    Table t;
    t.caption = "Energy of the optimum (" + id_label(c) +
                ") as the samples per trajectory grow: the sampled integral converges.";
    t.header = {"samples", "energy (J)"};
    for (const auto& r : c.rows) t.rows.push_back({as_text(r.samples), format_sig(r.energy_J, 10)});
    t.narrow = true;
    if (!t.rows.empty()) s.table(std::move(t));
  }
  {
    Table t;
    t.caption =
        "Sampled convergence of each optimum on its own: samples doubled until the "
        "sampled energy changes by less than 1e-4 and the sampled peak torque by less than 1e-3 "
        "relative (the first row's peak torque is the printed one); the verdict gives the "
        "printed energy, by adaptive Gauss-Kronrod quadrature with its error estimate.";
    t.header = {"optimum", "samples", "energy (J)", "sampled peak torque (N m)", "verdict"};
    for (const auto& o : pl.optima) {
      if (!o.energy_convergence) continue;
      const auto& c = *o.energy_convergence;
      const std::string verdict =
          no_energy(o) ? std::string(kSingularText)
                       : "energy " + energy_text(o, 10) + " J" +
                             (no_peak(o) ? "; " + std::string(kPeakText)
                                         : "; sampled change " + format_sig(c.rel_change, 2));
      bool first = true;
      for (const auto& r : c.rows) {
        t.rows.push_back({first ? id_label(o) : "", as_text(r.samples), format_sig(r.energy_J, 10),
                          format_sig(r.peak_torque_Nm, 6), first ? verdict : ""});
        t.swatches.push_back(first ? css_colour(colour_for(id_key(o))) : "");
        first = false;
      }
    }
    if (!t.rows.empty()) s.table(std::move(t));
  }
  Table th;
  th.caption =
      "Least energy among the thesis's own candidates, whatever their status: its grid of " +
      as_text(pl.thesis_divisions + 1) + " x " + as_text(pl.thesis_divisions + 1) +
      " lines (x_S in " + as_text(pl.thesis_divisions) + " steps of its interval 4.7-4.9, φ at k/" +
      as_text(pl.thesis_divisions) +
      " of [φ_init, φ_fin] 4.10-4.13; every optimum the thesis prints lies on the 10-step "
      "grid). Where it lies inside the margin (or is singular), the thesis's method would "
      "have reported it as the optimum.";
  th.header = {
      "program, configuration", "energy (J)",  "x_S (m)", "φ (deg)", "root (X, Y) (m)", "status",
      "boundary distance (m)",  "min |sin q2|"};
  for (const auto& o : pl.thesis_search) {
    th.rows.push_back({id_label(o), energy_text(o, 6), format_sig(o.x_s_m, 5),
                       format_sig(o.phi_deg, 5), pair_str(o.root_xy_m, 4), status_text(o.status),
                       format_sig(o.boundary_distance_m, 3), format_sig(o.min_abs_sin_elbow, 3)});
    th.swatches.push_back(css_colour(colour_for(id_key(o))));
  }
  if (!th.rows.empty()) s.table(std::move(th));
  Table ev;
  ev.caption = "Placements the case asked to evaluate, and what the optimum would save.";
  ev.header = {"placement",  "program, configuration",
               "x_S (m)",    "φ (deg)",
               "energy (J)", "status",
               "saving (J)", "saving (%)"};
  for (const auto& e : pl.evaluations)
    ev.rows.push_back(
        {e.label, id_label(e), format_sig(e.x_s_m, 5), format_sig(e.phi_deg, 5), energy_text(e, 6),
         status_text(e.status),
         no_energy(e) ? std::string("none (singular)") : format_sig(e.saving_J, 4),
         no_energy(e) ? std::string("none (singular)") : format_sig(e.saving_percent, 3)});
  if (!ev.rows.empty()) s.table(std::move(ev));
  if (s.blocks.empty()) s.paragraph("No convergence table or evaluations in the result.");
  return s;
}

}  // namespace

void placement_sections(const PS& pl, const ResultsRecord& record, FigureWriter& figures,
                        CasePage& page) {
  Section method;
  method.id = "method";
  method.heading = "Method";
  method.new_page = false;
  method.paragraph(
      "A 2-link arm in a horizontal plane carries its payload along a straight line of length "
      "L in time T with a rest-to-rest motion program. The line is fixed; the arm's root "
      "location is chosen. As in Kopmaz's thesis (2016, Ch. 4; docs/sources.md), start points "
      "S = (x_S, 0) and direction "
      "angles φ are swept on a grid, the root location in the line's frame is "
      "X = -x_S cos φ, Y = x_S sin φ (4.14), and for every candidate the actuator energy "
      "E = ∫ |M1 dθ1| + |M2 d(θ2 - θ1)| (Ch. 8, no regeneration) is computed from inverse "
      "dynamics for each program and configuration. Candidates that come closer to a "
      "workspace boundary than the singularity margin, or break a torque or power limit, are "
      "excluded from the optimum; the grid optimum is then refined with the constraints as "
      "constraints (NLopt COBYLA with the clearances and limits as inequalities, Nelder-Mead "
      "inside the admissible set, a golden-section search along a nearly active constraint) "
      "first on the sampled energy, then from there on the converged (quadrature) energy, "
      "until a restart gains less than 1e-7 relative in it; x_S and φ are printed with their "
      "distance from that energy's minimum, and each optimum says which "
      "constraint decides it. Every printed energy of an optimum or an evaluated placement is "
      "computed by adaptive Gauss-Kronrod quadrature (breakpoints at the closest approach "
      "to the inner circle and at the sign changes of the joint powers) and printed with its "
      "error estimate; its peak torque is checked by doubling the samples until it changes by "
      "less than 1e-3. Near a workspace boundary the energy stays finite while the peak "
      "torque grows without bound: such a motion has its energy but no peak torque "
      "(peak torque unbounded, singular pose); a line exactly tangent to the inner circle "
      "folds the elbow, where both joint rates reverse at once: its energy is the limit of "
      "the lines just outside it (the integral on both sides plus the reversal's jump "
      "term), printed with its error, and its peak torque is an impulse.");
  method.note(
      "The thesis's printed example energies cannot be reproduced from its own model and "
      "parameters, and its eq. 7.2 is wrong (M2 is (6.35) itself and M1 = (6.29) + (6.35); "
      "(3.17b) must use sin θ1). Several of its printed optima (Y = 0.1999 or 0.2000) lie on "
      "lines tangent to the inner workspace circle, where the elbow folds completely and the "
      "arm is singular. This report computes from first principles and never presents a "
      "singular trajectory as an ordinary optimum, so its numbers differ from the thesis's "
      "(docs/defects.md, docs/derivations/placement.md).");
  page.sections.push_back(std::move(method));
  page.sections.push_back(task_section(pl));
  page.sections.push_back(optima_section(pl, figures));
  if (auto printed = printed_motion_section(pl, figures))
    page.sections.push_back(std::move(*printed));
  Section maps = maps_section(pl, figures);
  Section tradeoff = loci_and_tradeoff(pl, figures, maps);
  page.sections.push_back(std::move(maps));
  if (auto cycle = cycle_time_section(pl, figures)) page.sections.push_back(std::move(*cycle));
  page.sections.push_back(std::move(tradeoff));
  page.sections.push_back(convergence_and_evaluations(pl));
  // MuJoCo's open-loop replay of every optimum (report/replay_section.hpp)
  std::vector<ReplayOf> replays;
  for (const auto& r : pl.mujoco_replay) replays.push_back({r.program, r.configuration, &r});
  mujoco_replay_section(replays, record.frames, figures, page);
}

// (over 60 lines, kept whole: one figure's series gathered and drawn in order)
bool placement_loci_across_cases(const std::vector<std::pair<std::string, const json*>>& cases,
                                 const std::filesystem::path& svg) {
  // (length, root) per program and configuration, over the placement cases
  struct Point {
    double length, x, y;
    std::string case_name;
  };
  std::map<std::string, std::vector<Point>> loci;
  std::map<std::string, std::string> labels;
  std::vector<Marker> printed;  // the roots the thesis prints (its Fig. 9.30)
  double longest = 0;
  int placement_cases = 0;
  for (const auto& [name, results] : cases) {
    PS pl;
    try {
      pl = read_study_results<PS>(*results, "placement");
    } catch (const ResultsError&) {
      continue;  // written by another armstudy: left out of the plot
    }
    const double length = pl.length_m;
    bool any = false;
    for (const auto& o : pl.optima) {
      const double x = o.root_xy_m[0], y = o.root_xy_m[1];
      if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(length)) continue;
      loci[id_key(o)].push_back({length, x, y, name});
      labels[id_key(o)] = id_label(o);
      longest = std::max(longest, length);
      any = true;
    }
    for (Marker& mk : printed_root_markers(pl, 0)) printed.push_back(std::move(mk));
    placement_cases += any;
  }
  if (placement_cases < 2) return false;
  ShadedMap m;
  m.title = "optimal root locations across the placement cases";
  m.x_label = "root X (m), along the line";
  m.y_label = "root Y (m)";
  m.nx = m.ny = 2;
  m.z.assign(4, NAN);
  double x0 = 0, x1 = longest, y0 = 0, y1 = 0;
  Series line{"task lines (from the origin along X)", {0.0, longest}, {0.0, 0.0}, {0, 0, 0}};
  line.width = 2.5;
  m.overlays.push_back(line);
  for (auto& [key, pts] : loci) {
    std::sort(pts.begin(), pts.end(),
              [](const Point& a, const Point& b) { return a.length < b.length; });
    Series locus{labels[key], {}, {}, colour_for(key)};
    for (const Point& p : pts) {
      locus.x.push_back(p.x);
      locus.y.push_back(p.y);
      m.markers.push_back({p.x, p.y, "", colour_for(key), false});
      x0 = std::min(x0, p.x);
      x1 = std::max(x1, p.x);
      y0 = std::min(y0, p.y);
      y1 = std::max(y1, p.y);
    }
    m.overlays.push_back(std::move(locus));
  }
  // the thesis's printed roots, one legend entry per configuration
  std::vector<std::string> named;
  for (Marker& mk : printed) {
    const std::string conf = mk.label.substr(mk.label.rfind("conf."));
    mk.label = std::find(named.begin(), named.end(), conf) == named.end()
                   ? "thesis's printed roots, " + conf
                   : std::string();
    if (!mk.label.empty()) named.push_back(conf);
    x0 = std::min(x0, mk.x);
    x1 = std::max(x1, mk.x);
    y0 = std::min(y0, mk.y);
    y1 = std::max(y1, mk.y);
    m.markers.push_back(std::move(mk));
  }
  const double pad = 0.08 * std::max(x1 - x0, y1 - y0) + 0.02;
  m.x_min = x0 - pad;
  m.x_max = x1 + pad;
  m.y_min = y0 - pad;
  m.y_max = y1 + pad;
  write_shaded_map(m, svg);
  return true;
}

}  // namespace armstudy::report
