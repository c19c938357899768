// the throwing study of Sato et al. sec. 4: eq. 8 start, idp optimum and the
// gradient (slsqp) optimum side by side; voltages, currents, torques, powers, theta4 with the
// tray limits, idp convergence, release and flight
#include <cmath>

#include "report/number_format.hpp"
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

struct Motion {
  std::string label, colour_key;
  const json* m;  // {energy_J, ..., series}
};

std::vector<Motion> motions(const json& th) {
  std::vector<Motion> out;
  if (jsonv::has(th, "initial")) out.push_back({"eq. 8 start", "initial", &th["initial"]});
  if (jsonv::has(th, "optimum")) out.push_back({"IDP optimum", "idp", &th["optimum"]});
  const json& nl = obj(th, "nlopt");
  if (jsonv::has(nl, "motion") && nl["motion"].is_object())
    out.push_back({"SLSQP (gradient)", "gradient", &nl["motion"]});
  return out;
}

// one plot over time: column `col` of series[key] (or every column when col < 0) per motion
LinePlot motion_plot(const std::vector<Motion>& ms, const std::string& title,
                     const std::string& y_label, const char* key, int col,
                     const std::vector<std::string>& column_names) {
  LinePlot plot;
  plot.title = title;
  plot.x_label = "time (s)";
  plot.y_label = y_label;
  for (const Motion& mo : ms) {
    const json& s = obj(*mo.m, "series");
    const auto t = jsonv::vec(s, "t_s");
    if (t.size() < 2 || !jsonv::has(s, key)) continue;
    std::vector<std::pair<std::string, std::vector<double>>> cols;
    if (s[key].size() == t.size() && !s[key].empty() && s[key][0].is_number()) {
      cols.push_back({"", jsonv::vec(s, key)});
    } else if (col >= 0) {
      cols.push_back({"", jsonv::column(s, key, static_cast<size_t>(col), t.size())});
    } else {
      for (size_t c = 0; c < column_names.size(); ++c)
        cols.push_back({column_names[c], jsonv::column(s, key, c, t.size())});
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

// "[a, b, c]" of release_error[key] at 3 significant digits
std::string release_error(const json& m, const char* key) {
  std::string s;
  for (double v : jsonv::vec(obj(m, "release_error"), key)) s += (s.empty() ? "" : ", ") + format_sig(v, 3);
  return "[" + s + "]";
}

}  // namespace

void throwing_sections(const json& results, FigureWriter& figures, CasePage& page) {
  const json& th = results.contains("throwing") ? results["throwing"] : json::object();
  const json& par = obj(th, "parameters");
  const json& lim = obj(th, "limits");
  const json& idp = obj(th, "idp");
  const json& nl = obj(th, "nlopt");
  const auto ms = motions(th);

  Section method;
  method.id = "method";
  method.heading = "Method";
  method.new_page = false;
  method.paragraph(
      "A 4-coordinate arm in a vertical plane throws a ball from a tray: links 1 and 2 are "
      "driven by DC servomotors, the tray hangs on a passive joint and the ball rolls in it. "
      "The joint-velocity profiles of the active joints over " + jsonv::str(idp, "stages") +
      " time stages are optimised by iterative dynamic programming (Luus): " +
      jsonv::str(idp, "candidates") + " candidates per stage in a region around the best "
      "trajectory, the region shifted to the best and shrunk by " + jsonv::str(idp, "shrink") +
      " each iteration, " + jsonv::str(idp, "iterations") + " iterations per pass, " +
      jsonv::str(idp, "passes") + " passes, starting from the trajectory of eq. 8 (in its "
      "corrected form). The criterion is the electrical energy E = Σ ∫ e i dt of the motors "
      "(eq. 5-7) plus the penalties of eq. 9 that keep the ball in the tray (|θ4| ≤ λ/2) and "
      "meet the release state; the tray's release angle follows from the passive dynamics, it "
      "is not commanded." +
      (jsonv::has(nl, "motion") ? " The same problem is also solved by a gradient method (" +
                                      jsonv::str(nl, "algorithm") +
                                      ") on the same parameterisation."
                                : std::string(" The case runs IDP only.")));
  method.note(
      "Several printed coefficients of the equations of motion of Sato et al. are inconsistent "
      "with its "
      "kinematics (a3's m4 term, two lines labelled A45, a5's inverted ratio, the ball spin "
      "of eq. 3, S234 in eq. 4); the model here is derived from first principles instead, so "
      "energies and angles differ from the paper's figures by design (docs/defects.md, "
      "docs/derivations/throwing.md).");
  for (const json& c : arr(par, "choices"))
    if (c.is_string())
      method.note("What Sato et al. leave open (docs/assumptions.md): " + c.get<std::string>());
  if (!par.empty()) method.table(json_table(par, "Parameters used (SI; _deg in degrees)."));
  page.sections.push_back(std::move(method));

  Section res;
  res.id = "results";
  res.heading = "Energy and limits";
  Table t;
  t.caption = "The eq. 8 start, the IDP optimum and the gradient optimum side by side. Limits: " +
              jsonv::sig(lim, "voltage_max_V", 4) + " V, " + jsonv::sig(lim, "current_max_A", 4) +
              " A, |θ4| ≤ " + format_sig(std::abs(jsonv::vec(lim, "theta4_limit_rad").empty()
                                                      ? NAN
                                                      : jsonv::vec(lim, "theta4_limit_rad").back()),
                                         4) +
              " rad.";
  t.header = {"motion", "energy (J)", "criterion (J)", "electrical (J)", "mechanical (J)",
              "copper (J)", "friction (J)", "max |θ4| (rad)", "max voltage (V)", "max current (A)",
              "release angle error θ1..θ3 (rad)", "release rate error θ1', θ2' (rad/s)"};
  for (const Motion& mo : ms) {
    const json& m = *mo.m;
    const json& es = obj(m, "energy_split");
    t.rows.push_back({mo.label, jsonv::sig(m, "energy_J", 6), jsonv::sig(m, "criterion_J", 6),
                      jsonv::sig(es, "electrical_J", 5), jsonv::sig(es, "mechanical_J", 4),
                      jsonv::sig(es, "copper_J", 5), jsonv::sig(es, "friction_J", 3),
                      jsonv::sig(m, "max_abs_theta4_rad", 4), jsonv::sig(m, "max_voltage_V", 4),
                      jsonv::sig(m, "max_current_A", 4), release_error(m, "angle_rad"),
                      release_error(m, "rate_rad_s")});
    t.swatches.push_back(css_colour(colour_for(mo.colour_key)));
  }
  if (!t.rows.empty()) res.table(std::move(t));
  res.paragraph("IDP saves " + jsonv::sig(th, "saving_percent", 3) +
                " % of the eq. 8 trajectory's energy (" + jsonv::sig(th, "energy_initial_J", 5) +
                " J → " + jsonv::sig(th, "energy_optimised_J", 5) + " J) in " +
                jsonv::sig(idp, "run_time_s", 3) + " s of search (" +
                jsonv::str(idp, "evaluations") + " simulations on " + jsonv::str(idp, "threads") +
                " threads)." +
                (jsonv::has(nl, "motion")
                     ? " The gradient method ran " + jsonv::sig(nl, "run_time_s", 3) + " s (" +
                           jsonv::str(nl, "simulations") + " simulations, stop: " +
                           jsonv::str(nl, "return_code") + ", feasible: " +
                           jsonv::str(nl, "feasible") + ")."
                     : std::string()));
  page.sections.push_back(std::move(res));

  Section mot;
  mot.id = "motors";
  mot.heading = "Motors over time";
  const double vmax = jsonv::num(lim, "voltage_max_V"), imax = jsonv::num(lim, "current_max_A");
  const char* joints_note = " Solid: motor 1; dashed: motor 2. Colours: grey the eq. 8 start, "
                            "blue the IDP optimum, vermillion the gradient optimum.";
  LinePlot v = motion_plot(ms, "motor voltages", "voltage (V)", "voltage_V", -1, {"motor 1", "motor 2"});
  if (std::isfinite(vmax)) v.references = {{vmax, "±" + format_sig(vmax, 3) + " V limit"}, {-vmax, ""}};
  if (!v.series.empty()) mot.figure(figures.line("voltages", v, std::string("Motor voltages e (eq. 5) with the voltage limit.") + joints_note));
  LinePlot c = motion_plot(ms, "motor currents", "current (A)", "current_A", -1, {"motor 1", "motor 2"});
  if (std::isfinite(imax)) c.references = {{imax, "±" + format_sig(imax, 3) + " A limit"}, {-imax, ""}};
  if (!c.series.empty()) mot.figure(figures.line("currents", c, std::string("Motor currents i = (e - kv θ')/Ra (eq. 6) with the current limit.") + joints_note));
  LinePlot tq = motion_plot(ms, "joint torques", "torque (N m)", "torque_Nm", -1, {"joint 1", "joint 2"});
  if (!tq.series.empty()) mot.figure(figures.line("torques", tq, std::string("Torques the motors apply at joints 1 and 2.") + joints_note));
  LinePlot pw = motion_plot(ms, "electrical power", "power (W)", "power_W", -1, {"motor 1", "motor 2"});
  if (!pw.series.empty()) mot.figure(figures.line("powers", pw, std::string("Electrical power e i drawn by the motors; its integral is the energy in the table.") + joints_note));
  page.sections.push_back(std::move(mot));

  Section ball;
  ball.id = "ball";
  ball.heading = "The ball in the tray, release and flight";
  LinePlot t4 = motion_plot(ms, "ball angle θ4 in the tray", "θ4 (rad)", "q_rad", 3, {});
  const auto tl = jsonv::vec(lim, "theta4_limit_rad");
  if (tl.size() == 2) t4.references = {{tl[1], "tray limits ±λ/2"}, {tl[0], ""}};
  if (!t4.series.empty())
    ball.figure(figures.line("theta4", t4,
                             "The ball's angle relative to the tray with the tray's limits: "
                             "outside them the ball leaves the tray (eq. 9's penalty)."));
  LinePlot q3 = motion_plot(ms, "tray angle θ3 (passive)", "θ3 (rad)", "q_rad", 2, {});
  if (!q3.series.empty())
    ball.figure(figures.line("theta3", q3, "The passive tray joint, moved only by the dynamics."));
  const json& rel = obj(th, "release");
  const json& fl = obj(th, "flight");
  Table r;
  r.caption = "Release and flight of the ball (IDP optimum).";
  r.header = {"quantity", "value"};
  auto pair = [](const json& j, const char* k) {
    const auto v = jsonv::vec(j, k);
    return v.size() == 2 ? "(" + format_sig(v[0], 4) + ", " + format_sig(v[1], 4) + ")" : std::string("n/a");
  };
  r.rows = {{"release time", jsonv::sig(rel, "time_s", 4) + " s"},
            {"ball at release (x, y)", pair(rel, "ball_xy_m") + " m"},
            {"ball velocity at release", pair(rel, "ball_velocity_m_s") + " m/s"},
            {"reaches the landing height", jsonv::str(fl, "reaches")},
            {"landing height", jsonv::sig(fl, "landing_height_m", 4) + " m"},
            {"landing point (x, y)", pair(fl, "landing_xy_m") + " m"},
            {"flight time", jsonv::sig(fl, "duration_s", 4) + " s"},
            {"apex height", jsonv::sig(fl, "apex_m", 4) + " m"}};
  ball.table(std::move(r));
  // the locus of the throw (003 figure 7) and the flight, in the vertical plane
  {
    ShadedMap locus;
    locus.title = "ball path: throw and flight (cf. Figure 7 of Sato et al.)";
    locus.x_label = "x (m)";
    locus.y_label = "y (m)";
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
      const json& s = obj(*mo.m, "series");
      const size_t n = arr(s, "t_s").size();
      add({mo.label + ": ball in the tray", jsonv::column(s, "ball_xy_m", 0, n),
           jsonv::column(s, "ball_xy_m", 1, n), colour_for(mo.colour_key)});
    }
    const size_t nf = arr(fl, "t_s").size();
    add({"flight after release", jsonv::column(fl, "path_xy_m", 0, nf),
         jsonv::column(fl, "path_xy_m", 1, nf), colour_for("idp"), LineStyle::kDashed});
    const auto land = jsonv::vec(fl, "landing_xy_m");
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
                              "origin) during each motion, and its flight after the IDP "
                              "optimum's release."));
    }
  }
  page.sections.push_back(std::move(ball));

  Section conv;
  conv.id = "convergence";
  conv.heading = "Convergence of the optimisers";
  LinePlot cp;
  cp.title = "IDP convergence";
  cp.x_label = "iteration (all passes)";
  cp.y_label = "best value (J)";
  Series crit{"criterion (energy + penalties)", {}, {}, colour_for("idp"), LineStyle::kSolid, true};
  Series en{"energy of the best", {}, {}, colour_for("idp"), LineStyle::kDashed, true};
  Table ct;
  ct.caption = "IDP: the best criterion at the end of iterations (all of them when few; "
               "else each pass's first and last and every fifth).";
  ct.header = {"pass", "iteration", "criterion (J)", "energy (J)", "region (rad/s)", "improvements", "simulations"};
  int k = 0;
  const json& rows = arr(idp, "convergence");
  for (size_t i = 0; i < rows.size(); ++i) {
    const json& row = rows[i];
    ++k;
    crit.x.push_back(k);
    crit.y.push_back(jsonv::num(row, "criterion_J"));
    en.x.push_back(k);
    en.y.push_back(jsonv::num(row, "energy_J"));
    // the table keeps each pass's first and last iteration and every fifth (the plot has all)
    const bool last_of_pass = i + 1 == rows.size() || jsonv::str(rows[i + 1], "pass") != jsonv::str(row, "pass");
    const double it = jsonv::num(row, "iteration");
    if (rows.size() > 25 && !(it == 1 || last_of_pass || std::fmod(it, 5) == 0)) continue;
    const auto reg = jsonv::vec(row, "region_rad_s");
    ct.rows.push_back({jsonv::str(row, "pass"), jsonv::str(row, "iteration"),
                       jsonv::sig(row, "criterion_J", 6), jsonv::sig(row, "energy_J", 6),
                       reg.size() == 2 ? format_sig(reg[0], 3) + ", " + format_sig(reg[1], 3) : "n/a",
                       jsonv::str(row, "improvements"), jsonv::str(row, "evaluations")});
  }
  crit.markers = en.markers = k <= 80;
  if (k > 0) {
    cp.series = {crit, en};
    conv.figure(figures.line("idp_convergence", cp,
                             "Best criterion and its energy after each IDP iteration, passes one "
                             "after the other (the region is restored between passes)."));
  }
  const auto hist = jsonv::vec(nl, "history_J");
  if (hist.size() >= 2) {
    LinePlot hp;
    hp.title = "gradient method history";
    hp.x_label = "iteration";
    hp.y_label = "criterion (J)";
    Series h{"SLSQP criterion", {}, hist, colour_for("gradient")};
    for (size_t i = 0; i < hist.size(); ++i) h.x.push_back(static_cast<double>(i + 1));
    hp.series = {h};
    conv.figure(figures.line("slsqp_history", hp, "The gradient method's criterion per iteration."));
  }
  if (!ct.rows.empty()) conv.table(std::move(ct));
  const json& rep = obj(th, "replay");
  const json& integ = obj(th, "integration");
  const std::string fine = jsonv::str(integ, "fine_steps_factor") + "x";
  Table acc;
  acc.caption = "Accuracy of the simulation behind every number above.";
  acc.header = {"check", "value"};
  acc.rows = {{"integration", jsonv::str(integ, "method")},
              {"step", jsonv::sig(integ, "step_s", 3) + " s"},
              {"energy error against " + fine + " the steps", jsonv::sig(integ, "energy_error_vs_fine_steps", 3)},
              {"θ3 error against " + fine + " the steps", jsonv::sig(integ, "theta3_error_vs_fine_steps_rad", 3) + " rad"},
              {"open-loop voltage replay", jsonv::str(rep, "integrator")},
              {"largest replay error", jsonv::sig(rep, "max_error_rad", 3) + " rad (tolerance " +
                                           jsonv::sig(rep, "tolerance_rad", 3) + " rad)"}};
  conv.table(std::move(acc));
  page.sections.push_back(std::move(conv));
}

}  // namespace armstudy::report
