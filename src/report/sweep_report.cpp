// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/sweep_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "cases/case_info.hpp"
#include "report/case_report.hpp"
#include "report/page.hpp"

namespace armstudy::report {
namespace {
namespace fs = std::filesystem;

using Value = std::optional<std::string>;

// a parameter value as a number, NaN when it is not one
double as_number(const Value& v) {
  if (!v) return NAN;
  const std::string& s = *v;
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  return (!s.empty() && end == s.c_str() + s.size()) ? x : NAN;
}

std::string value_text(const Value& v) { return v.value_or("null"); }

}  // namespace

namespace {

// the x axis: the first parameter with a number in every row; -1 when none has
int x_axis_of(const std::vector<SweepRow>& rows, const std::vector<std::string>& params) {
  int x_axis = -1;
  for (size_t a = 0; a < params.size() && x_axis < 0; ++a) {
    bool numeric = !rows.empty();
    for (const auto& r : rows)
      numeric = numeric && r.parameters.count(params[a]) &&
                std::isfinite(as_number(r.parameters.at(params[a])));
    if (numeric) x_axis = static_cast<int>(a);
  }
  return x_axis;
}

// the key figures with a number in a passing row, in the studies' own order of key figures
// (the first is the headline), else by name; *failed counts the rows that did not pass
std::vector<std::string> figure_names_of(const SweepTable& table, int* failed_rows) {
  int& failed = *failed_rows;
  failed = 0;
  std::set<std::string> numeric;
  for (const auto& r : table.rows) {
    if (r.status != "ok") {
      ++failed;
      continue;
    }
    for (const auto& [k, v] : r.key_figures)
      if (v) numeric.insert(k);
  }
  // in the studies' own order of key figures (the first is the headline), else by name
  std::vector<std::string> figure_names;
  for (const auto& n : table.figures)
    if (numeric.count(n)) figure_names.push_back(n);
  for (const auto& n : numeric)
    if (std::find(figure_names.begin(), figure_names.end(), n) == figure_names.end())
      figure_names.push_back(n);
  return figure_names;
}

// each parameter and its values (at most 14 named)
Table axes_table(const std::vector<SweepRow>& rows, const std::vector<std::string>& params) {
  Table axes;
  axes.header = {"parameter", "values"};
  for (const auto& p : params) {
    std::set<std::string> seen;
    std::vector<std::pair<double, std::string>> values;
    for (const auto& r : rows) {
      const auto it = r.parameters.find(p);
      if (it == r.parameters.end()) continue;
      const std::string t = value_text(it->second);
      if (seen.insert(t).second) values.emplace_back(as_number(it->second), t);
    }
    std::sort(values.begin(), values.end());
    std::string list;
    for (size_t k = 0; k < values.size(); ++k) {
      if (k == 12 && values.size() > 14) {
        list += ", ... (" + std::to_string(values.size() - 13) + " more), " + values.back().second;
        break;
      }
      list += (k ? ", " : "") + values[k].second;
    }
    axes.rows.push_back({p, list});
  }
  return axes;
}

// the key figure `name` over the parameter x_axis, one curve per combination of the other
// parameters (*curve_count of them), points sorted along x
LinePlot key_figure_plot(const SweepTable& table, int x_axis, const std::string& name,
                         size_t* curve_count) {
  const std::vector<std::string>& params = table.parameters;
  const std::string& xp = params[x_axis];
  std::map<std::string, std::vector<std::pair<double, double>>> curves;
  for (const auto& r : table.rows) {
    if (r.status != "ok" || !r.key_figures.count(name)) continue;
    std::string label;
    for (size_t a = 0; a < params.size(); ++a) {
      if (static_cast<int>(a) == x_axis || !r.parameters.count(params[a])) continue;
      label +=
          (label.empty() ? "" : ", ") + params[a] + " = " + value_text(r.parameters.at(params[a]));
    }
    const auto x = r.parameters.find(xp);
    curves[label].emplace_back(as_number(x == r.parameters.end() ? Value() : x->second),
                               r.key_figures.at(name).value_or(NAN));
  }
  LinePlot plot;
  plot.title = name;
  plot.x_label = xp;
  const auto u = table.units.find(name);
  const std::string unit = u == table.units.end() ? std::string() : u->second;
  plot.y_label = unit.empty() ? name : name + " (" + unit + ")";
  plot.height_pt = 360;
  const std::vector<Rgb> palette = palette_colours();
  for (auto& [l, pts] : curves) {  // the legend in the order of the labels' text
    std::sort(pts.begin(), pts.end());
    Series s;
    s.label = l;
    s.colour = palette[plot.series.size() % palette.size()];
    s.markers = pts.size() <= 40;
    for (const auto& [x, y] : pts) {
      s.x.push_back(x);
      s.y.push_back(y);
    }
    plot.series.push_back(std::move(s));
  }
  *curve_count = curves.size();
  return plot;
}

// the page's first section: what the sweep table holds, the parameters and their values,
// and how many cases did not pass
Section about_section(const SweepTable& table, int failed) {
  Section about;
  about.id = "sweep";
  about.heading = "The sweep";
  about.new_page = false;
  about.paragraph(
      "Each row of sweep.csv (and sweep.json) is one case: its parameter values and "
      "the key figures of its results.json. The plots below draw every key figure "
      "over the first numeric parameter, one curve per combination of the others.");
  about.table(axes_table(table.rows, table.parameters));
  if (failed > 0)
    about.note(std::to_string(failed) +
               " case(s) did not pass (unsolvable or a failed check): "
               "summary.md names them; the plots leave them out.");
  return about;
}

}  // namespace

// the sweep report: the sweep and its axes, then every key figure over the first numeric
// parameter
int write_sweep_report(const fs::path& dir, const SweepTable& table, const std::string& title) {
  fs::create_directories(dir);
  const std::vector<SweepRow>& rows = table.rows;
  const std::vector<std::string>& params = table.parameters;

  const int x_axis = x_axis_of(rows, params);

  CasePage page;
  page.title = title;
  page.study = "sweep";
  int failed = 0;
  const std::vector<std::string> figure_names = figure_names_of(table, &failed);
  page.status = failed == 0 ? "solved" : "failed";
  page.message = std::to_string(rows.size()) + " case(s) over " + std::to_string(params.size()) +
                 " parameter(s); " + std::to_string(failed) + " failed";
  page.key_figures = {{"cases", std::to_string(rows.size())}, {"failed", std::to_string(failed)}};

  page.sections.push_back(about_section(table, failed));

  int plots = 0;
  Section figs;
  figs.id = "figures";
  figs.heading = x_axis < 0 ? "Key figures" : "Key figures over " + params[x_axis];
  if (x_axis < 0) {
    figs.paragraph(
        "No parameter of this sweep takes only numbers, so there is no axis to plot "
        "over; sweep.csv holds every value.");
  } else {
    figs.paragraph(
        "Where two solutions of a case are nearly as good, the optimum can switch "
        "between them from one point to the next: a curve that jumps (a root position, "
        "say) while the energy curve stays smooth shows such a switch, not an error.");
    const std::string& xp = params[x_axis];
    FigureWriter writer(dir);
    for (const std::string& name : figure_names) {
      size_t curves = 0;
      const LinePlot plot = key_figure_plot(table, x_axis, name, &curves);
      figs.figure(writer.line(
          "sweep_" + std::to_string(plots + 1), plot,
          "The key figure " + name + " of every passing case over " + xp +
              (curves > 1 ? ", one curve per combination of the other parameters" : "")));
      ++plots;
    }
  }
  page.sections.push_back(std::move(figs));

  cases::CaseInfo info;
  info.name = title;
  info.study = "sweep";
  write_page(dir, page, info, "../sweep.csv");
  return plots;
}

}  // namespace armstudy::report
