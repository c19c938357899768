// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// the throwing study of Sato et al. sec. 4 (docs/sources.md) as a constrained problem
// (docs/throwing.md): eq. 8 start, feasible reference, idp optimum (best of several seeds)
// and the gradient (slsqp) optimum side by side; one comparison table on equal terms;
// voltages, currents, torques, powers with their limits; contact force and friction needed
// over time; theta4 with the tray limits; idp seeds and convergence; release and flight
#include <cmath>

#include "report/number_format.hpp"
#include "report/results_fields.hpp"
#include "report/study_sections.hpp"
#include "report/throwing_page.hpp"
#include "studies/throwing/study_results.hpp"

namespace armstudy::report {

namespace throwing_page {

// one plot over time per motion: a scalar series, or column `col` of a series of rows (every
// column when col < 0, named by column_names)
LinePlot motion_plot(const std::vector<Motion>& ms, const std::string& title,
                     const std::string& y_label, std::vector<double> TS::Series::*scalar,
                     TS::Rows TS::Series::*rows, int col,
                     const std::vector<std::string>& column_names) {
  LinePlot plot;
  plot.title = title;
  plot.x_label = "time (s)";
  plot.y_label = y_label;
  for (const Motion& mo : ms) {
    const TS::Series& s = mo.m->series;
    const auto& t = s.t_s;
    if (t.size() < 2) continue;
    std::vector<std::pair<std::string, std::vector<double>>> cols;
    if (scalar) {
      if ((s.*scalar).empty()) continue;
      cols.push_back({"", s.*scalar});
    } else if ((s.*rows).empty()) {
      continue;
    } else if (col >= 0) {
      cols.push_back({"", column(s.*rows, static_cast<size_t>(col))});
    } else {
      for (size_t c = 0; c < column_names.size(); ++c)
        cols.push_back({column_names[c], column(s.*rows, c)});
    }
    for (size_t c = 0; c < cols.size(); ++c) {
      Series se;
      se.x = t;
      se.y = cols[c].second;
      se.colour = colour_for(mo.colour_key);
      se.style = c == 0 ? LineStyle::kSolid : c == 1 ? LineStyle::kDashed : LineStyle::kDotted;
      se.label = mo.label + (cols[c].first.empty() ? "" : ", " + cols[c].first);
      plot.series.push_back(std::move(se));
    }
  }
  return plot;
}
LinePlot motion_plot(const std::vector<Motion>& ms, const std::string& title,
                     const std::string& y_label, TS::Rows TS::Series::*rows, int col,
                     const std::vector<std::string>& column_names) {
  return motion_plot(ms, title, y_label, nullptr, rows, col, column_names);
}
LinePlot motion_plot(const std::vector<Motion>& ms, const std::string& title,
                     const std::string& y_label, std::vector<double> TS::Series::*scalar) {
  return motion_plot(ms, title, y_label, scalar, nullptr, -1, {});
}

}  // namespace throwing_page

namespace {

using nlohmann::json;

using namespace throwing_page;  // TS, Motion, Page, motion_plot: throwing_page.hpp

std::vector<Motion> motions(const TS::Optimised& th) {
  std::vector<Motion> out;
  out.push_back({"eq. 8 start", "initial", &th.initial});
  if (th.reference_motion)
    out.push_back({"IDP's repaired start", "reference", &*th.reference_motion});
  out.push_back({"IDP optimum", "idp", &th.optimum});
  if (th.nlopt.run) out.push_back({"SLSQP (gradient)", "gradient", &th.nlopt.run->motion});
  return out;
}

// "[a, b, c]" at 3 significant digits
std::string release_error(const std::vector<double>& v) {
  std::string s;
  for (double x : v) s += (s.empty() ? "" : ", ") + format_sig(x, 3);
  return "[" + s + "]";
}

// "yes" / "NOT converged"
std::string yes_no(bool b) { return b ? "yes" : "NOT converged"; }

// names, joined
std::string names(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
  return s.empty() ? "none" : s;
}

// the method: the problem, its constraints and both optimisers' settings
void add_method_paragraph(const Page& p, Section& method) {
  const bool ran = p.ran;
  const auto& lim = p.section.limits;
  const auto& idp = p.th.idp;
  const std::optional<TS::NloptRun>& nl = p.th.nlopt.run;
  if (ran)
    method.paragraph(
        "A 4-coordinate arm in a vertical plane throws a ball from a tray: links 1 and 2 are "
        "driven by DC servomotors, the tray hangs on a passive joint and the ball rolls in it. "
        "The joint-velocity profiles of the active joints over " +
        as_text(idp.stages) +
        " time stages minimise the electrical energy E = Σ ∫ e i dt of the motors (eq. 5-7) "
        "subject to constraints checked at every integration step: the tray's normal force on "
        "the ball N ≥ " +
        format_sig(lim.contact_margin_N, 3) +
        " N (an open tray cannot "
        "pull the ball), the friction rolling needs |F_t|/N ≤ μ = " +
        format_sig(lim.friction_coefficient, 3) +
        ", the ball within the tray |θ4| ≤ λ/2, "
        "the motors within " +
        format_sig(lim.voltage_max_V, 3) + " V, " + format_sig(lim.current_max_A, 3) + " A and " +
        format_sig(lim.power_max_W, 3) + " W, and the passive tray at its release angle within " +
        format_sig(lim.release_tolerance_rad * 180 / 3.14159265358979, 3) +
        "°. N and F_t come from the ball's own equation of motion, m4 a = −N n + F_t t + m4 g "
        "(docs/throwing.md). Iterative dynamic programming (Luus) compares candidates by the "
        "feasibility rules (feasible and lower energy, else lower violation): " +
        as_text(idp.candidates) + " candidates per stage node, " + as_text(idp.iterations) +
        " shrinking iterations (×" + as_text(idp.shrink) + ") per pass, the region restored ×" +
        as_text(idp.restore) +
        " between passes, "
        "until whole passes gain less than " +
        format_sig(idp.tolerance, 3) + " of the energy, " + as_text(idp.quiet_passes) +
        " in a row (budget " + as_text(idp.max_passes) + " passes), for " + as_text(idp.seeds) +
        " seeds." +
        (nl ? " The same constrained problem is solved by a gradient method (" + nl->algorithm +
                  ") from several starts: the reference, IDP's optimum, the raw eq. 8 profile and "
                  "seeded whole-profile changes of it (sums of sine modes: the global phase), "
                  "then seeded perturbations of the best local optimum so far. Each start runs "
                  "until SLSQP stops on a relative energy change of " +
                  format_sig(nl->ftol_rel, 2) + " / a relative step of " +
                  format_sig(nl->xtol_rel, 2) +
                  ", then the first-order test: the KKT residual |∇E + Σ λ ∇g| / E per rad/s "
                  "of node rate (multipliers ≥ 0 of the active constraints) at most " +
                  (nl->first_order ? format_sig(nl->first_order->kkt_tolerance, 2)
                                   : std::string("?")) +
                  ", and a fresh SLSQP restart from the point gaining no more than 1e-4 of the "
                  "energy (budget " +
                  as_text(nl->max_evaluations) +
                  " gradient evaluations per start). The answer is the lowest start that "
                  "passes both and is feasible in the finer re-check."
            : std::string(" The case runs IDP only.")) +
        " Both optimisers keep every normalised constraint " + format_sig(lim.backoff, 2) +
        " inside its limit.");
}

// the method, the model's sources, the assumptions and the parameters
Section method_section(const Page& p) {
  const TS& section = p.section;
  const auto& par = p.section.parameters;
  Section method;
  method.id = "method";
  method.heading = "Method";
  method.new_page = false;
  add_method_paragraph(p, method);
  method.note(
      "Several printed coefficients of the equations of motion of Sato et al. are inconsistent "
      "with its "
      "kinematics (a3's m4 term, two lines labelled A45, a5's inverted ratio, the ball spin "
      "of eq. 3, S234 in eq. 4); the model here is derived from first principles instead "
      "(docs/defects.md, docs/derivations/throwing.md). The paper prints no throw energies, so "
      "there is no printed energy to compare with.");
  for (const std::string& c : par.choices)
    method.note("What Sato et al. leave open (docs/assumptions.md): " + c);
  {
    Table at;
    at.caption =
        "Assumptions: values the paper leaves open, chosen here (case keys); they are "
        "settings, not facts, and the optimum depends on them.";
    at.header = {"assumption", "value", "case key"};
    for (const auto& a : section.assumptions)
      at.rows.push_back({a.name, format_sig(a.value, 4) + " " + a.unit, a.key});
    if (!at.rows.empty()) method.table(std::move(at));
  }
  method.table(json_table(to_json(par), "Parameters used (SI; _deg in degrees)."));
  return method;
}

// what the saving is measured against, and how far the raw eq. 8 start breaks the limits
void add_saving(const Page& p, Section& res) {
  const TS& section = p.section;
  const auto& ref = p.th.reference;
  const std::string& kind = ref.kind;
  const TS::Repair repair = ref.repair.value_or(TS::Repair{});
  std::string text = "The saving is measured against the eq. 8 start (" +
                     format_sig(section.energy_initial_J, 5) + " J), the paper's comparison";
  if (kind == "eq8")
    text += ", which meets every constraint.";
  else if (!kind.empty())
    text +=
        ", which breaks the limits in the table below: a saving against it includes "
        "what meeting them costs or saves.";
  if (std::isfinite(section.saving_percent))
    text += " The answer, " + format_sig(section.energy_optimised_J, 5) + " J, saves " +
            format_sig(section.saving_percent, 3) + " %.";
  else
    text += " There is no feasible answer, so no saving is quoted.";
  if (kind == "repaired")
    text += " IDP starts from a feasible repair of eq. 8 (" + repair.method + "; " +
            repair.return_code + " after " + as_text(repair.iterations) + " iterations), " +
            format_sig(section.energy_reference_J, 5) +
            " J: the first point of that descent, not an optimum, which moves with the last "
            "digit of an input, so no saving is quoted against it.";
  else if (kind == "none")
    text += " The repair of eq. 8 found no feasible profile (" + repair.return_code +
            "), so IDP starts from the infeasible eq. 8.";
  res.paragraph(text);
  Table br;
  br.caption =
      "How far the raw eq. 8 trajectory breaks each limit it breaks (margin < 0; "
      "normalised: the excess as a fraction of the limit, for the contact and "
      "friction of the ball's weight m4 g).";
  br.header = {"constraint", "margin", "normalised excess"};
  for (const auto& b : ref.raw_breaks)
    br.rows.push_back(
        {b.constraint, format_sig(b.margin, 4) + " " + b.unit, format_sig(b.worst_normalised, 3)});
  if (!br.rows.empty()) res.table(std::move(br));
}

// SLSQP's starts and the local optima they reach
void add_starts(const Page& p, Section& res) {
  const TS& section = p.section;
  const std::optional<TS::NloptRun>& nl = p.th.nlopt.run;
  if (nl && nl->starts) {
    Table st;
    st.caption =
        "SLSQP's starts and the local optima they reach: the answer is the lowest converged one "
        "(" +
        nl->best_start.value_or("?") +
        "). The spread shows the nearby local optima of the problem; a single start can end "
        "in any of them under a last-digit change of an input, the lowest of several does not.";
    st.header = {
        "start",    "energy (J)",          "above the answer", "converged", "first-order residual",
        "restarts", "gradient evaluations"};
    const double best = section.energy_optimised_J;
    for (const auto& x : *nl->starts)
      st.rows.push_back({x.name, format_sig(x.energy_J, 6),
                         x.feasible ? format_sig(100 * (x.energy_J / best - 1), 2) + " %"
                                    : std::string("infeasible"),
                         yes_no(x.converged), format_sig(x.kkt_residual, 2), as_text(x.restarts),
                         as_text(x.iterations)});
    res.table(std::move(st));
  }
}

// the optimisers on equal terms: one column each
Table comparison_table(const Page& p) {
  const TS::Optimised& th = p.th;
  const bool ran = p.ran;
  Table ct;
  ct.caption =
      "The optimisers on equal terms: the same constrained problem, the same start. "
      "Margins (> 0: met) come from re-simulating each optimum with " +
      (ran ? as_text(th.verification.refinement) : std::string()) +
      "x the steps, independently of the optimiser; friction margin = μ − max |F_t|/N. "
      "Binding: the constraint kinds with a positive multiplier at the optimum (first order; "
      "the sensitivity part's binding list).";
  // one column per optimiser (the rows are the quantities, so the table fits the page)
  const auto& cmp = th.comparison;
  ct.header = {"quantity"};
  for (const auto& row : cmp) ct.header.push_back(row.optimiser);
  auto add = [&](const std::string& label, auto value) {
    std::vector<std::string> cells = {label};
    for (const auto& row : cmp) cells.push_back(value(row));
    ct.rows.push_back(std::move(cells));
  };
  auto field = [](double TS::Comparison::*key, int digits) {
    return [key, digits](const TS::Comparison& row) { return format_sig(row.*key, digits); };
  };
  auto margin = [](double TS::Margins::*key) {
    return [key](const TS::Comparison& row) { return format_sig(row.margins.*key, 3); };
  };
  if (!cmp.empty()) {
    add("energy E = ∫ e i dt (J)", field(&TS::Comparison::energy_J, 5));
    add("  mechanical work (J)", field(&TS::Comparison::mechanical_J, 4));
    add("  copper loss Ra i² (J)", field(&TS::Comparison::copper_J, 4));
    add("  motor friction (J)", field(&TS::Comparison::friction_J, 3));
    add("converged", [](const TS::Comparison& row) { return yes_no(row.converged); });
    add("simulations", [](const TS::Comparison& row) { return as_text(row.simulations); });
    add("time (s)", field(&TS::Comparison::run_time_s, 3));
    add("margin: contact N − margin (N)", margin(&TS::Margins::contact_N));
    add("margin: μ − friction needed |F_t|/N", margin(&TS::Margins::friction));
    add("margin: tray angle λ/2 − |θ4| (rad)", margin(&TS::Margins::tray_rad));
    add("margin: release tolerance − |θ3 error| (rad)", margin(&TS::Margins::release_rad));
    add("margin: voltage (V)", margin(&TS::Margins::voltage_V));
    add("margin: current (A)", margin(&TS::Margins::current_A));
    add("margin: power (W)", margin(&TS::Margins::power_W));
    add("binding constraints", [](const TS::Comparison& row) { return names(row.binding); });
    add("binding motor rating", [](const TS::Comparison& row) { return row.binding_rating; });
  }
  return ct;
}

// the answer's control grids: each grid's energy and time, and the verdict on the sequence
void add_grids(const Page& p, Section& res) {
  if (!p.ran || !p.th.control_grids) return;
  const TS::ControlGrids& cg = *p.th.control_grids;
  Table t;
  t.caption =
      "The answer on finer control grids (docs/throwing.md): each grid's SLSQP starts from the "
      "coarser grid's answer prolonged (the same throw, feasible, the same energy), the RK4 "
      "step kept. " +
      std::string(cg.status == "converged"
                      ? "Converged: the last doubling changed the energy by " +
                            format_sig(std::abs(cg.change_per_doubling_J), 3) +
                            " J, within the tolerance " + format_sig(cg.tolerance, 3) +
                            " of it; estimated error " + format_sig(cg.error_J, 3) + " J."
                  : cg.status == "not_converged"
                      ? "NOT converged: still falling by " +
                            format_sig(std::abs(cg.change_per_doubling_J), 3) +
                            " J per doubling at the finest grid (tolerance " +
                            format_sig(cg.tolerance, 3) +
                            " of the energy). The optimum of the continuous problem is at most "
                            "the finest grid's energy; how far below it lies is not estimated: "
                            "while the energy falls by more than the tolerance, a geometric fit "
                            "of the changes per doubling is a guess (docs/throwing.md)."
                      : "Not refined: one grid, the control grid's error is not measured.");
  t.header = {"stages",
              "RK4 steps per stage",
              "energy (J)",
              "feasible",
              "converged (first order)",
              "first-order residual",
              "from",
              "simulations",
              "time (s)"};
  for (const auto& g : cg.grids)
    t.rows.push_back({as_text(g.stages), as_text(g.steps_per_stage), format_sig(g.energy_J, 5),
                      as_text(g.feasible), yes_no(g.converged), format_sig(g.kkt_residual, 2),
                      g.from, as_text(g.simulations), format_sig(g.run_time_s, 3)});
  res.table(std::move(t));
}

// whether each optimiser converged, and a note when the two disagree
void add_verdict(const Page& p, Section& res) {
  const TS::Optimised& th = p.th;
  const bool ran = p.ran;
  const auto& idp = p.th.idp;
  const std::optional<TS::NloptRun>& nl = p.th.nlopt.run;
  const double idp_kkt = idp.first_order ? idp.first_order->kkt_residual : NAN;
  const double kkt_tol = idp.first_order ? idp.first_order->kkt_tolerance : NAN;
  std::string conv =
      "IDP: " +
      std::string(idp.converged ? "converged (every seed stopped on its tolerance, its optimum "
                                  "first-order stationary)"
                                : "NOT converged: a stall, not an optimum") +
      "; best seed " + as_text(idp.best_seed) + " ran " + as_text(idp.passes) +
      " passes, last pass gain " + format_sig(idp.last_gain, 2) + ", first-order residual " +
      format_sig(idp_kkt, 2) + " per rad/s (tolerance " + format_sig(kkt_tol, 2) + ").";
  if (nl) {
    conv += " SLSQP's answer: " + nl->return_code + ", first-order residual " +
            (nl->first_order ? format_sig(nl->first_order->kkt_residual, 2) : std::string("?")) +
            ", " + (nl->converged ? "converged." : "NOT converged: not an optimum.");
    if (nl->first_order && !nl->first_order->binding.empty())
      conv += " What bounds it: the " + names(nl->first_order->binding) +
              " constraints (positive multipliers).";
  }
  if (ran) res.paragraph(conv);
  // the optimisers on the same problem should agree; say so when they do not
  const auto& cm = th.comparison;
  // IDP against SLSQP's answer on IDP's own grid too (the third row, with control grids)
  if (cm.size() >= 3 && std::isfinite(cm[0].energy_J) && std::isfinite(cm[2].energy_J))
    res.paragraph("IDP's gap: its throw (" + format_sig(cm[0].energy_J, 4) + " J) is " +
                  format_sig(100 * (cm[0].energy_J / cm[1].energy_J - 1), 3) +
                  " % above the answer (" + cm[1].optimiser + ", " + format_sig(cm[1].energy_J, 4) +
                  " J) and " + format_sig(100 * (cm[0].energy_J / cm[2].energy_J - 1), 3) +
                  " % above " + cm[2].optimiser + " (" + format_sig(cm[2].energy_J, 4) + " J).");
  if (cm.size() >= 2) {
    const double ei = cm[0].energy_J, eg = cm[1].energy_J;
    if (std::isfinite(ei) && std::isfinite(eg) && std::abs(ei - eg) > 0.01 * std::min(ei, eg)) {
      const bool idp_higher = ei > eg;
      res.note(std::string(idp_higher ? "IDP" : "SLSQP") + "'s answer is " +
               format_sig(100 * (std::max(ei, eg) / std::min(ei, eg) - 1), 3) + " % above " +
               (idp_higher ? "SLSQP" : "IDP") + "'s for the same constrained problem." +
               (idp_higher
                    ? " IDP (the paper's method, Luus's random search with region "
                      "restoration) stops when whole passes gain under its tolerance, but its "
                      "first-order residual (" +
                          format_sig(idp_kkt, 2) +
                          ") shows a descent direction left: the optimum lies on several "
                          "constraint boundaries at once (the binding constraints above), "
                          "where nearly every random candidate of a shrinking region is "
                          "infeasible. More seeds, passes or candidates "
                          "per node move it little (docs/throwing.md has the measurements), "
                          "and an IDP started at SLSQP's answer stays there. So SLSQP's "
                          "answer is the study's; IDP's is reported as the paper's method."
                    : " Neither is proven global."));
    }
  }
}

// each motion's energy and extremes
Table motions_table(const Page& p) {
  const std::vector<Motion>& ms = p.ms;
  const auto& lim = p.section.limits;
  Table t;
  t.caption =
      "Each motion's energy and extremes (at the optimisers' own steps). Limits: " +
      format_sig(lim.voltage_max_V, 4) + " V, " + format_sig(lim.current_max_A, 4) + " A, " +
      format_sig(lim.power_max_W, 4) + " W, N ≥ " + format_sig(lim.contact_margin_N, 3) +
      " N, |F_t|/N ≤ " + format_sig(lim.friction_coefficient, 3) + ", |θ4| ≤ " +
      format_sig(std::abs(lim.theta4_limit_rad.empty() ? NAN : lim.theta4_limit_rad.back()), 4) +
      " rad.";
  t.header = {"motion",          "energy (J)",
              "feasible",        "electrical (J)",
              "mechanical (J)",  "copper (J)",
              "friction (J)",    "min N (N)",
              "max |F_t|/N",     "max |θ4| (rad)",
              "max voltage (V)", "max current (A)",
              "max power (W)",   "release angle error θ1..θ3 (rad)"};
  for (const Motion& mo : ms) {
    const TS::Motion& m = *mo.m;
    const auto& es = m.energy_split;
    t.rows.push_back({mo.label, format_sig(m.energy_J, 6), as_text(m.feasible),
                      format_sig(es.electrical_J, 5), format_sig(es.mechanical_J, 4),
                      format_sig(es.copper_J, 5), format_sig(es.friction_J, 3),
                      format_sig(m.min_normal_force_N, 3), format_sig(m.max_friction_ratio, 3),
                      format_sig(m.max_abs_theta4_rad, 4), format_sig(m.max_voltage_V, 4),
                      format_sig(m.max_current_A, 4), format_sig(m.max_power_W, 4),
                      release_error(m.release_error.angle_rad)});
    t.swatches.push_back(css_colour(colour_for(mo.colour_key)));
  }
  return t;
}

// the saving and the optimisers compared
Section results_section(const Page& p) {
  Section res;
  res.id = "results";
  res.heading = "Saving, optimisers compared";
  add_saving(p, res);
  add_starts(p, res);
  add_grids(p, res);
  if (Table ct = comparison_table(p); !ct.rows.empty()) res.table(std::move(ct));
  add_verdict(p, res);
  if (Table t = motions_table(p); !t.rows.empty()) res.table(std::move(t));
  return res;
}

// the IDP seeds' spread and each seed's run
Section seeds_section(const Page& p) {
  const bool ran = p.ran;
  const auto& idp = p.th.idp;
  Section seeds;
  seeds.id = "idp-seeds";
  seeds.heading = "IDP seeds";
  seeds.new_page = false;
  {
    const auto& sp = idp.spread;
    if (ran)
      seeds.paragraph("IDP ran " + as_text(idp.seeds) +
                      " seeds from the same reference: "
                      "energies best " +
                      format_sig(sp.best_J, 5) + " J, median " + format_sig(sp.median_J, 5) +
                      " J, worst " + format_sig(sp.worst_J, 5) +
                      " J. The spread is what a single IDP run is uncertain by; the best seed is "
                      "the reported optimum.");
    const double lo = ran ? sp.best_J : NAN, hi = ran ? sp.worst_J : NAN;
    const double tol = idp.tolerance;
    if (std::isfinite(lo) && std::isfinite(hi) && std::isfinite(tol) &&
        hi - lo > 10 * tol * std::abs(lo))
      seeds.note("The seeds disagree by " + format_sig(100 * (hi - lo) / std::abs(lo), 3) +
                 " %, far more than the convergence tolerance: each seed's convergence is local "
                 "(its search stopped gaining), not a proof of the optimum. The spread, not the "
                 "tolerance, bounds how well IDP has solved the problem.");
    Table st;
    st.caption =
        "Each IDP seed: energy, whether it converged (whole passes gained less than the "
        "tolerance, " +
        as_text(idp.quiet_passes) + " in a row) and what it cost.";
    st.header = {"seed",   "energy (J)",     "feasible",    "converged",
                 "passes", "last pass gain", "simulations", "time (s)"};
    for (const auto& r : idp.seed_runs)
      st.rows.push_back({as_text(r.seed), format_sig(r.energy_J, 6), as_text(r.feasible),
                         yes_no(r.converged), as_text(r.passes), format_sig(r.last_gain, 2),
                         as_text(r.evaluations), format_sig(r.run_time_s, 3)});
    if (!st.rows.empty()) seeds.table(std::move(st));
  }
  return seeds;
}

// the paper's main output (Sato et al. Figs 5 and 9): the active joints' rate profiles, all
// motions together, then each optimiser's alone beside the eq. 8 start
void add_joint_velocities(const Page& p, FigureWriter& figures, Section& mot) {
  const std::vector<Motion>& ms = p.ms;
  // the paper's main output (Sato et al. Figs 5 and 9): the active joints' rate profiles
  LinePlot jv = motion_plot(ms, "joint velocities", "rate (rad/s)", &TS::Series::qd_rad_s, -1,
                            {"θ1'", "θ2'"});
  if (!jv.series.empty())
    mot.figure(figures.line(
        "joint_velocities", jv,
        std::string("The optimised joint-velocity profiles θ1'(t) (solid) and θ2'(t) (dashed), "
                    "linear within each stage, beside the eq. 8 start: the decision variables "
                    "of both optimisers (the paper's Figs 5 and 9 show its IDP profiles).") +
            " Colours: grey the eq. 8 start, blue the IDP optimum, vermillion the gradient "
            "optimum (IDP's repaired start, if any, in its own colour)."));
  // each optimiser's profile alone beside the eq. 8 start, two to a row
  for (const Motion& mo : ms) {
    if (mo.colour_key == "initial" || mo.colour_key == "reference") continue;
    const std::vector<Motion> pair = {ms.front(), mo};
    LinePlot one = motion_plot(pair, mo.label + ": joint velocities", "rate (rad/s)",
                               &TS::Series::qd_rad_s, -1, {"θ1'", "θ2'"});
    if (!one.series.empty())
      mot.figure(half(figures.line("joint_velocities_" + mo.colour_key, half_size(one),
                                   mo.label + ": the joint-velocity profiles θ1' (solid) and "
                                              "θ2' (dashed) beside the eq. 8 start (grey).")));
  }
}

// the joint rates, voltages, currents, torques and powers over time
Section motors_section(const Page& p, FigureWriter& figures) {
  const std::vector<Motion>& ms = p.ms;
  const auto& lim = p.section.limits;
  Section mot;
  mot.id = "motors";
  mot.heading = "Motors over time";
  const double vmax = lim.voltage_max_V, imax = lim.current_max_A, pmax = lim.power_max_W;
  const char* joints_note =
      " Solid: motor 1; dashed: motor 2. Colours: grey the eq. 8 start, "
      "blue the IDP optimum, vermillion the gradient optimum (IDP's repaired "
      "start, if any, in its own colour).";
  add_joint_velocities(p, figures, mot);
  LinePlot v = motion_plot(ms, "motor voltages", "voltage (V)", &TS::Series::voltage_V, -1,
                           {"motor 1", "motor 2"});
  if (std::isfinite(vmax))
    v.references = {{vmax, "±" + format_sig(vmax, 3) + " V limit"}, {-vmax, ""}};
  if (!v.series.empty())
    mot.figure(figures.line(
        "voltages", v,
        std::string("Motor voltages e (eq. 5) with the voltage limit.") + joints_note));
  LinePlot c = motion_plot(ms, "motor currents", "current (A)", &TS::Series::current_A, -1,
                           {"motor 1", "motor 2"});
  if (std::isfinite(imax))
    c.references = {{imax, "±" + format_sig(imax, 3) + " A limit"}, {-imax, ""}};
  if (!c.series.empty())
    mot.figure(figures.line(
        "currents", c,
        std::string("Motor currents i = (e - kv θ')/Ra (eq. 6) with the current limit.") +
            joints_note));
  LinePlot tq = motion_plot(ms, "joint torques", "torque (N m)", &TS::Series::torque_Nm, -1,
                            {"joint 1", "joint 2"});
  if (!tq.series.empty())
    mot.figure(figures.line(
        "torques", tq, std::string("Torques the motors apply at joints 1 and 2.") + joints_note));
  LinePlot pw = motion_plot(ms, "electrical power", "power (W)", &TS::Series::power_W, -1,
                            {"motor 1", "motor 2"});
  if (std::isfinite(pmax))
    pw.references = {{pmax, "±" + format_sig(pmax, 3) + " W rating"}, {-pmax, ""}};
  if (!pw.series.empty())
    mot.figure(figures.line("powers", pw,
                            std::string("Electrical power e i drawn by the motors with the power "
                                        "rating; its integral is the energy in the table.") +
                                joints_note));
  return mot;
}

// the tray's normal force on the ball and the friction rolling needs
Section contact_section(const Page& p, FigureWriter& figures) {
  const std::vector<Motion>& ms = p.ms;
  const auto& lim = p.section.limits;
  Section contact;
  contact.id = "contact";
  contact.heading = "Contact of the ball with the tray";
  {
    LinePlot nf = motion_plot(ms, "normal force of the tray on the ball", "normal force N (N)",
                              &TS::Series::normal_force_N);
    const double margin = lim.contact_margin_N;
    if (std::isfinite(margin))
      nf.references = {{margin, "margin " + format_sig(margin, 3) + " N"},
                       {0.0, "0 N: the ball lifts off"}};
    if (!nf.series.empty())
      contact.figure(
          figures.line("normal_force", nf,
                       "The tray's normal force on the ball, N = m4 (g − a)·n, at every "
                       "integration step; below 0 the tray would have to pull the ball."));
    LinePlot fr = motion_plot(ms, "friction needed to roll", "friction needed |F_t|/N (ratio)",
                              &TS::Series::friction_needed);
    const double mu = lim.friction_coefficient;
    if (std::isfinite(mu)) fr.references = {{mu, "μ = " + format_sig(mu, 3)}};
    // keep the axis readable: the raw start may need far more than μ where N is near 0
    for (auto& se : fr.series)
      for (double& y : se.y)
        if (std::isfinite(y) && y > 4 * (std::isfinite(mu) ? mu : 1.0)) y = NAN;
    if (!fr.series.empty())
      contact.figure(
          figures.line("friction_needed", fr,
                       "The friction coefficient rolling without slip needs, |F_t|/N "
                       "(F_t = m4 (a − g)·t), with the assumed μ; values above 4μ and "
                       "where N ≤ 0 are left out of the plot (the table gives the maxima)."));
  }
  return contact;
}

}  // namespace

void throwing_sections(const TS& section, const ResultsRecord&, FigureWriter& figures,
                       CasePage& page) {
  static const TS::Optimised kNotRun{};
  // the optimisers' part: empty when the study stopped before them (nothing below is drawn)
  const bool ran = section.run.has_value();
  const TS::Optimised& th = ran ? *section.run : kNotRun;
  const Page p{section, th, ran, ran ? motions(th) : std::vector<Motion>{}};
  page.sections.push_back(method_section(p));
  page.sections.push_back(results_section(p));
  if (Section seeds = seeds_section(p); !seeds.blocks.empty())
    page.sections.push_back(std::move(seeds));
  page.sections.push_back(motors_section(p, figures));
  page.sections.push_back(contact_section(p, figures));
  page.sections.push_back(ball_section(p, figures));
  page.sections.push_back(convergence_section(p, figures));
}

}  // namespace armstudy::report
