// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// the placement page's maps: the energy over root locations per program and configuration,
// the energy over the direction angle (the thesis's Fig. 9.11), the optimal root locations
// (9.30) and the torque trade-off (Pareto fronts)
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

#include "core/types.hpp"
#include "report/number_format.hpp"
#include "report/placement_page.hpp"
#include "report/results_fields.hpp"
#include "report/study_sections.hpp"

namespace armstudy::report::placement_page {
namespace {

constexpr Rgb kUnreachable{215, 215, 215};
constexpr Rgb kSingular{238, 120, 120};
constexpr Rgb kOverLimit{250, 200, 120};
constexpr int kMaxMapCells = 120;  // per axis, drawn (the data keeps every node)

// energy over the direction angle at each optimum's x_S (the thesis's Fig. 9.11), into s
// (over 60 lines, kept whole: one figure's series gathered and drawn in order)
void add_energy_vs_phi(const PS& pl, FigureWriter& figures, Section& s) {
  LinePlot plot;
  plot.title = "energy over the direction angle φ";
  plot.x_label = "direction angle φ (deg)";
  plot.y_label = "energy (J)";
  for (const auto& c : pl.curves) {
    const auto& phi = c.phi_deg;
    const auto& e = c.energy_J;
    const std::string& status = c.status;
    if (phi.size() != e.size() || phi.empty()) continue;
    // admissible points solid, singular or over-limit ones dotted
    Series ok, excluded;
    ok.label = id_label(c) + " (x_S = " + format_sig(c.x_s_m, 4) + " m)";
    excluded.label = "";
    ok.colour = excluded.colour = colour_for(id_key(c));
    excluded.style = LineStyle::kDotted;
    for (size_t k = 0; k < phi.size(); ++k) {
      const char st = k < status.size() ? status[k] : 'o';
      ok.x.push_back(phi[k]);
      excluded.x.push_back(phi[k]);
      ok.y.push_back(st == 'o' ? e[k] : NAN);
      excluded.y.push_back(st == 's' || st == 'x' ? e[k] : NAN);
      // join the dotted part to its solid neighbours
      if (k > 0 && (st == 'o') != (k - 1 < status.size() && status[k - 1] == 'o')) {
        if (st == 'o')
          excluded.y[k] = e[k];
        else
          excluded.y[k - 1] = e[k - 1];
      }
    }
    plot.series.push_back(std::move(ok));
    plot.series.push_back(std::move(excluded));
    // the optimum itself, on its own curve (the curve is drawn at the optimum's x_S)
    for (const auto& o : pl.optima) {
      if (id_key(o) != id_key(c) || no_energy(o)) continue;
      Series mark;
      mark.label = "";
      mark.colour = colour_for(id_key(c));
      mark.markers = true;
      mark.x = {o.phi_deg};
      mark.y = {o.energy_J};
      if (std::isfinite(mark.x[0]) && std::isfinite(mark.y[0]))
        plot.series.push_back(std::move(mark));
    }
  }
  bool any = false;
  for (const auto& se : plot.series)
    for (double y : se.y) any |= std::isfinite(y);
  if (!any) {
    s.paragraph("No energy-versus-direction curve has a reachable point.");
    return;
  }
  // (each curve's x_S is in its legend entry)
  s.figure(
      half(figures.line("energy_vs_phi", half_size(plot),
                        std::string("Energy of the motion over the direction angle φ at "
                                    "each optimum's own ") +
                            "start abscissa x_S, as the thesis's " + thesis_figure(pl, 5) +
                            "; the marker is the optimum itself (an optimum on the margin sits "
                            "where its curve turns dotted). Solid: admissible; dotted: inside "
                            "the margin or over a limit (excluded); gaps: unreachable or the "
                            "energy not converged.")));
}

// a placement map's grid as results.json holds it (rows of text): the energy and the status
// of every node ('.' unreachable, 's' inside the margin, 'x' over a limit)
struct MapGrid {
  size_t nx = 0, ny = 0;
  std::vector<double> z;
  std::vector<char> st;
};

// the grid of `m`; false when its rows do not fit its axes
bool read_map_grid(const PS::Map& m, MapGrid* g) {
  const auto& xs = m.x_m;
  const auto& ys = m.y_m;
  const auto& er = m.energy_J_rows;
  const auto& sr = m.status_rows;
  if (xs.size() < 2 || ys.size() < 2 || er.size() != ys.size() || sr.size() != ys.size())
    return false;
  const size_t nx = xs.size(), ny = ys.size();
  g->nx = nx;
  g->ny = ny;
  g->z.assign(nx * ny, NAN);
  g->st.assign(nx * ny, '.');
  std::vector<double>& z = g->z;
  std::vector<char>& st = g->st;
  for (size_t j = 0; j < ny; ++j) {
    std::istringstream in(er[j]);
    const std::string& status = sr[j];
    std::string tok;
    for (size_t i = 0; i < nx && (in >> tok); ++i) {
      if (tok != "-") z[j * nx + i] = std::strtod(tok.c_str(), nullptr);
      if (i < status.size()) st[j * nx + i] = status[i];
    }
  }
  return true;
}

// the part of the grid drawn (node index ranges, inclusive)
struct Crop {
  size_t i0 = 0, i1 = 0, j0 = 0, j1 = 0;
  bool cropped = false;
};

// drawn over the reachable part of the grid and the marked points (a few cells around them):
// the rest is unreachable, and a map of mostly grey told little at print size
Crop crop_to_reachable(const PS& pl, const PS::Map& m, const MapGrid& g) {
  const auto& xs = m.x_m;
  const auto& ys = m.y_m;
  const size_t nx = g.nx, ny = g.ny;
  const std::vector<char>& st = g.st;
  size_t i0 = nx, i1 = 0, j0 = ny, j1 = 0;
  auto include = [&](size_t i, size_t j) {
    i0 = std::min(i0, i), i1 = std::max(i1, i), j0 = std::min(j0, j), j1 = std::max(j1, j);
  };
  for (size_t j = 0; j < ny; ++j)
    for (size_t i = 0; i < nx; ++i)
      if (st[j * nx + i] != '.') include(i, j);
  auto nearest = [](const std::vector<double>& v, double x) {
    const auto at = std::lower_bound(v.begin(), v.end(), x);
    return static_cast<size_t>(
        std::min<std::ptrdiff_t>(at - v.begin(), static_cast<std::ptrdiff_t>(v.size()) - 1));
  };
  auto include_point = [&](double x, double y) {
    if (std::isfinite(x) && std::isfinite(y)) include(nearest(xs, x), nearest(ys, y));
  };
  if (m.optimum_xy_m) include_point((*m.optimum_xy_m)[0], (*m.optimum_xy_m)[1]);
  for (const auto& th : pl.thesis_search)
    if (id_key(th) == id_key(m)) include_point(th.root_xy_m[0], th.root_xy_m[1]);
  bool cropped = false;
  if (i0 > i1 || j0 > j1) {
    i0 = j0 = 0, i1 = nx - 1, j1 = ny - 1;  // nothing reachable: the whole grid
  } else {
    const size_t pad_x = std::max<size_t>(2, (i1 - i0) / 12),
                 pad_y = std::max<size_t>(2, (j1 - j0) / 12);
    i0 = i0 > pad_x ? i0 - pad_x : 0, j0 = j0 > pad_y ? j0 - pad_y : 0;
    i1 = std::min(nx - 1, i1 + pad_x), j1 = std::min(ny - 1, j1 + pad_y);
    // at least a quarter of the grid along each axis: a thin reachable band stays readable
    auto widen_to = [](size_t& lo, size_t& hi, size_t n) {
      const size_t want = std::max<size_t>(2, n / 4);
      while (hi - lo + 1 < want) {
        if (lo > 0) --lo;
        if (hi - lo + 1 < want && hi + 1 < n) ++hi;
      }
    };
    widen_to(i0, i1, nx);
    widen_to(j0, j1, ny);
    cropped = i0 > 0 || j0 > 0 || i1 < nx - 1 || j1 < ny - 1;
  }
  return {i0, i1, j0, j1, cropped};
}

// the drawn cells of `map` (mx by my, each a block of kx by ky nodes): a cell takes the most
// severe status of its block, an admissible one the energy of its first node; returns the
// note on the colours' saturation ("" when they do not saturate)
std::string fill_cells(const MapGrid& g, const Crop& crop, size_t kx, size_t ky, ShadedMap& map,
                       const std::string& unit = "J", const std::string& quantity = "energy") {
  const size_t nx = g.nx, mx = static_cast<size_t>(map.nx), my = static_cast<size_t>(map.ny);
  const size_t i0 = crop.i0, i1 = crop.i1, j0 = crop.j0, j1 = crop.j1;
  const std::vector<double>& z = g.z;
  const std::vector<char>& st = g.st;
  map.z.assign(mx * my, NAN);
  MapRegion unreachable{"unreachable", kUnreachable, std::vector<std::uint8_t>(mx * my, 0)};
  MapRegion singular{"inside the margin (inadmissible)", kSingular,
                     std::vector<std::uint8_t>(mx * my, 0)};
  MapRegion over{"over a torque/power limit", kOverLimit, std::vector<std::uint8_t>(mx * my, 0)};
  std::vector<double> feasible;
  for (size_t j = 0; j < my; ++j)
    for (size_t i = 0; i < mx; ++i) {
      int worst = 3;  // 0 unreachable, 1 singular, 2 over, 3 feasible
      for (size_t b = j0 + j * ky; b < std::min(j1 + 1, j0 + (j + 1) * ky); ++b)
        for (size_t a = i0 + i * kx; a < std::min(i1 + 1, i0 + (i + 1) * kx); ++a) {
          const char c = st[b * nx + a];
          worst = std::min(worst, c == '.' ? 0 : c == 's' ? 1 : c == 'x' ? 2 : 3);
        }
      const size_t k = j * mx + i;
      if (worst == 0)
        unreachable.mask[k] = 1;
      else if (worst == 1)
        singular.mask[k] = 1;
      else if (worst == 2)
        over.mask[k] = 1;
      else {
        map.z[k] = z[(j0 + j * ky) * nx + i0 + i * kx];
        if (std::isfinite(map.z[k])) feasible.push_back(map.z[k]);
      }
    }
  // colours saturate at the 95th percentile: near the margin the energy climbs steeply
  std::string saturation;
  if (feasible.size() > 20) {
    std::vector<double> sorted = feasible;
    std::sort(sorted.begin(), sorted.end());
    const double cap = sorted[static_cast<size_t>(0.95 * (sorted.size() - 1))];
    if (cap < sorted.back()) {
      for (double& v : map.z)
        if (std::isfinite(v)) v = std::min(v, cap);
      saturation = " Colours saturate at " + format_sig(cap, 4) + " " + unit +
                   " (95th percentile; the largest admissible " + quantity + " is " +
                   format_sig(sorted.back(), 4) + " " + unit + ").";
    }
  }
  map.regions = {unreachable, singular, over};
  return saturation;
}

// the task line, the optimum and the thesis-interval best over the map
void add_map_marks(const PS& pl, const PS::Map& m, ShadedMap& map) {
  Series line;
  line.label = "task line";
  line.colour = {0, 0, 0};
  line.width = 2.5;
  line.x = {0.0, pl.length_m};
  line.y = {0.0, 0.0};
  if (std::isfinite(line.x[1])) map.overlays.push_back(line);
  if (m.optimum_xy_m)
    map.markers.push_back(
        {(*m.optimum_xy_m)[0], (*m.optimum_xy_m)[1], "optimum", colour_for(id_key(m))});
  for (const auto& th : pl.thesis_search)
    if (id_key(th) == id_key(m))
      map.markers.push_back({th.root_xy_m[0],
                             th.root_xy_m[1],
                             "thesis-interval best (" + status_text(th.status) + ")",
                             {0, 0, 0},
                             false});
  // the root the thesis prints for this configuration (its Fig. 9.30)
  for (Marker& mk : printed_root_markers(pl, m.configuration)) map.markers.push_back(std::move(mk));
}

// the drawn frame of a map over the grid `xs` x `ys` cropped to `c`: its cells (each a block
// of *kx by *ky nodes, at most kMaxMapCells per axis), axes and range
ShadedMap map_frame(const std::vector<double>& xs, const std::vector<double>& ys, const Crop& c,
                    size_t* kx, size_t* ky) {
  const size_t cx = c.i1 - c.i0 + 1, cy = c.j1 - c.j0 + 1;
  // thinned grid for drawing; a drawn cell takes the most severe status of its block
  *kx = (cx + kMaxMapCells - 1) / kMaxMapCells;
  *ky = (cy + kMaxMapCells - 1) / kMaxMapCells;
  const size_t mx = (cx - 1) / *kx + 1, my = (cy - 1) / *ky + 1;
  ShadedMap map;
  map.x_label = "root X (m), along the line";
  map.y_label = "root Y (m)";
  map.nx = static_cast<int>(mx);
  map.ny = static_cast<int>(my);
  map.fit_height = true;
  map.x_min = xs[c.i0];
  map.x_max = xs[c.i0 + (mx - 1) * *kx];
  map.y_min = ys[c.j0];
  map.y_max = ys[c.j0 + (my - 1) * *ky];
  // a grid far longer one way than the other is drawn with axes not to scale (to scale it
  // was a sliver)
  const double span_ratio = (map.y_max - map.y_min) / (map.x_max - map.x_min);
  if (!(span_ratio < 2.5 && span_ratio > 0.4)) map.equal_aspect = false;
  return map;
}

// the caption's account of the grid and of what is drawn
std::string drawn_words(const MapGrid& g, const Crop& c, const ShadedMap& map) {
  const std::string drawn =
      c.cropped ? ", drawn where the line is reachable (X " + format_sig(map.x_min, 3) + " to " +
                      format_sig(map.x_max, 3) + " m, Y " + format_sig(map.y_min, 3) + " to " +
                      format_sig(map.y_max, 3) + " m; "
                : " (";
  return "a " + std::to_string(g.nx) + " × " + std::to_string(g.ny) + " grid" + drawn +
         std::to_string(map.nx) + " × " + std::to_string(map.ny) + " cells drawn" +
         (map.equal_aspect ? "" : "; axes not to scale") + ")";
}

// one placement map (rows of text in results.json) as a shaded map
bool map_figure(const PS& pl, const PS::Map& m, FigureWriter& figures, Section& s) {
  MapGrid g;
  if (!read_map_grid(m, &g)) return false;
  const Crop c = crop_to_reachable(pl, m, g);
  size_t kx = 1, ky = 1;
  ShadedMap map = map_frame(m.x_m, m.y_m, c, &kx, &ky);
  map.title = "energy over root locations, " + id_label(m);
  map.z_label = "energy (J)";
  const std::string saturation = fill_cells(g, c, kx, ky, map);
  add_map_marks(pl, m, map);
  const std::string name = "map_" + m.program + "_" + as_text(m.configuration);
  Figure f = figures.map(name, map, id_label(m) + ": " + drawn_words(g, c, map) + "." + saturation);
  f.half = true;  // the four maps print two by two
  s.figure(std::move(f));
  return true;
}

// the least cycle time over root locations of one configuration, drawn over the same nodes,
// crop and cells as that configuration's first energy map; the fastest root, and each energy
// optimum's, marked
bool cycle_time_map_figure(const PS& pl, const PS::CycleTime& ct, FigureWriter& figures,
                           Section& s) {
  PS::Map tm;
  tm.program = "cycle-time";
  tm.configuration = ct.configuration;
  tm.x_m = ct.map.x_m;
  tm.y_m = ct.map.y_m;
  tm.energy_J_rows = ct.map.time_s_rows;
  tm.status_rows = ct.map.status_rows;
  tm.optimum_xy_m = ct.optimum.root_xy_m;
  MapGrid g;
  if (!read_map_grid(tm, &g)) return false;
  Crop c = crop_to_reachable(pl, tm, g);
  for (const auto& em : pl.maps) {
    MapGrid eg;
    if (em.configuration != ct.configuration || !read_map_grid(em, &eg) || eg.nx != g.nx ||
        eg.ny != g.ny)
      continue;
    c = crop_to_reachable(pl, em, eg);  // the energy map's axes
    break;
  }
  size_t kx = 1, ky = 1;
  ShadedMap map = map_frame(tm.x_m, tm.y_m, c, &kx, &ky);
  map.title = "least cycle time over root locations, conf. " + as_text(ct.configuration);
  map.z_label = "cycle time (s)";
  const std::string saturation = fill_cells(g, c, kx, ky, map, "s", "cycle time");
  // (no node is over a limit: the energy objective's limits do not apply here)
  std::erase_if(map.regions, [](const MapRegion& r) {
    return std::find(r.mask.begin(), r.mask.end(), 1) == r.mask.end();
  });
  Series line{"task line", {0.0, pl.length_m}, {0.0, 0.0}, {0, 0, 0}};
  line.width = 2.5;
  if (std::isfinite(pl.length_m)) map.overlays.push_back(line);
  if (ct.optimum.root_xy_m)
    map.markers.push_back({(*ct.optimum.root_xy_m)[0], (*ct.optimum.root_xy_m)[1], "fastest cycle",
                           colour_for("cycle-time/" + as_text(ct.configuration))});
  for (const auto& e : ct.at_energy_optima)
    map.markers.push_back({e.root_xy_m[0], e.root_xy_m[1], "energy optimum, " + e.program,
                           colour_for(e.program + "/" + as_text(ct.configuration)), false});
  Figure f =
      figures.map("map_cycle_time_" + as_text(ct.configuration), map,
                  "Least cycle time, conf. " + as_text(ct.configuration) +
                      ", on the exact solver's " + as_text(ct.map.grid_points) +
                      "-point grid at each node: " + drawn_words(g, c, map) + "." + saturation);
  f.half = true;
  s.figure(std::move(f));
  return true;
}

// the workspace annulus' circle of radius r around an optimum's root (X, Y), dotted
Series workspace_circle(double X, double Y, double r, Rgb colour) {
  Series c;
  c.colour = colour;
  c.style = LineStyle::kDotted;
  c.width = 1.0;
  for (int k = 0; k <= 180; ++k) {
    c.x.push_back(X + r * std::cos(k * M_PI / 90));
    c.y.push_back(Y + r * std::sin(k * M_PI / 90));
  }
  return c;
}

// the locus of the least-energy root as the allowed peak torque of joint 1 grows (a Pareto
// front's start points, as root locations in the line frame)
template <typename Pareto>
Series pareto_locus(const Pareto& p) {
  const auto& xs = p.x_s_m;
  const auto& ph = p.phi_deg;
  Series locus;
  locus.label = id_label(p) + ", Pareto locus";
  locus.colour = colour_for(id_key(p));
  locus.width = 1.2;
  for (size_t k = 0; k < xs.size(); ++k) {
    // root location in the line frame, eq. 4.14
    locus.x.push_back(-xs[k] * std::cos(ph[k] * armstudy::core::kDeg));
    locus.y.push_back(xs[k] * std::sin(ph[k] * armstudy::core::kDeg));
  }
  return locus;
}

// the optimal root locations (the thesis's Fig. 9.30): each optimum with its workspace
// annulus and the Pareto loci, bounded to show them all; no markers when there is no optimum
ShadedMap root_loci_map(const PS& pl) {
  const double length = pl.length_m;
  const double r_in = pl.annulus_m[0], r_out = pl.annulus_m[1];
  ShadedMap loci;
  loci.title = "optimal root locations";
  loci.x_label = "root X (m), along the line";
  loci.y_label = "root Y (m)";
  loci.nx = loci.ny = 2;
  loci.z.assign(4, NAN);
  double x_lo = std::min(0.0, length), x_hi = std::max(0.0, length), y_lo = 0, y_hi = 0;
  auto grow = [&](double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y)) return;
    x_lo = std::min(x_lo, x);
    x_hi = std::max(x_hi, x);
    y_lo = std::min(y_lo, y);
    y_hi = std::max(y_hi, y);
  };
  Series line;
  line.label = "task line";
  line.colour = {0, 0, 0};
  line.width = 2.5;
  line.x = {0.0, length};
  line.y = {0.0, 0.0};
  loci.overlays.push_back(line);
  for (const auto& o : pl.optima) {
    const double X = o.root_xy_m[0], Y = o.root_xy_m[1];
    if (!std::isfinite(X) || !std::isfinite(Y)) continue;
    loci.markers.push_back({X, Y, id_label(o), colour_for(id_key(o))});
    grow(X, Y);
    // the optimum's workspace: the line must lie inside the annulus
    for (double r : {r_in, r_out}) {
      if (!std::isfinite(r)) continue;
      loci.overlays.push_back(workspace_circle(X, Y, r, colour_for(id_key(o))));
    }
  }
  for (const auto& p : pl.pareto) {
    if (p.x_s_m.size() != p.phi_deg.size() || p.x_s_m.size() < 2 || p.joint != 1) continue;
    Series locus = pareto_locus(p);
    for (size_t k = 0; k < locus.x.size(); ++k) grow(locus.x[k], locus.y[k]);
    loci.overlays.push_back(std::move(locus));
  }
  // the roots the thesis prints (its Fig. 9.30), beside armstudy's optima
  for (Marker& mk : printed_root_markers(pl, 0)) {
    grow(mk.x, mk.y);
    loci.markers.push_back(std::move(mk));
  }
  if (loci.markers.empty()) return loci;
  const double pad = std::max(0.1, std::isfinite(r_out) ? 0.0 : 0.1);
  const double reach = std::isfinite(r_out) ? r_out : 0;
  double x0 = x_lo - pad, x1 = x_hi + pad, y0 = y_lo - pad, y1 = y_hi + pad;
  for (const auto& mk : loci.markers) {
    x0 = std::min(x0, mk.x - reach);
    x1 = std::max(x1, mk.x + reach);
    y0 = std::min(y0, mk.y - reach);
    y1 = std::max(y1, mk.y + reach);
  }
  loci.x_min = x0;
  loci.x_max = x1;
  loci.y_min = y0;
  loci.y_max = y1;
  loci.fit_height = true;
  return loci;
}

// the least energy for an allowed peak torque of `joint`, per program and configuration, and
// the inadmissible candidates grey and dotted
LinePlot pareto_plot(const PS& pl, int joint) {
  LinePlot plot;
  plot.title = "least energy for an allowed peak torque of joint " + std::to_string(joint);
  plot.x_label = "peak torque of joint " + std::to_string(joint) + " (N m)";
  plot.y_label = "least energy (J)";
  bool excluded_labelled = false;
  std::vector<Series> excluded_series;
  for (const auto& p : pl.pareto) {
    if (p.joint != joint) continue;
    Series se;
    se.label = id_label(p);
    se.colour = colour_for(id_key(p));
    se.markers = p.energy_J.size() <= 40;
    for (size_t k = 0; k < p.energy_J.size(); ++k) {
      const auto& pk = p.peak_torque_Nm;
      if (k >= pk.size() || !std::isfinite(pk[k][joint - 1])) continue;
      se.x.push_back(pk[k][joint - 1]);
      se.y.push_back(p.energy_J[k]);
    }
    if (!se.x.empty()) plot.series.push_back(std::move(se));
    // inadmissible candidates (inside the margin): grey, dotted, never part of the front
    {
      const auto& ex = p.excluded;
      Series xs;
      xs.label = excluded_labelled ? "" : "inside the margin (inadmissible, not a front)";
      excluded_labelled = true;
      xs.colour = {150, 150, 150};
      xs.style = LineStyle::kDotted;
      xs.width = 1.0;
      const auto& pk = ex.peak_torque_Nm;
      for (size_t k = 0; k < ex.energy_J.size() && k < pk.size(); ++k) {
        if (!std::isfinite(pk[k][joint - 1])) continue;
        xs.x.push_back(pk[k][joint - 1]);
        xs.y.push_back(ex.energy_J[k]);
      }
      if (!xs.x.empty()) excluded_series.push_back(std::move(xs));
    }
  }
  for (auto& xs : excluded_series) plot.series.push_back(std::move(xs));
  return plot;
}

// the roots the thesis prints, in words, for a caption (empty when the case evaluates none)
std::string printed_roots_caption(const PS& pl) {
  std::string list;
  const PS::Evaluation* prev = nullptr;
  for (const PS::Evaluation* e : printed_placements(pl, printed_program(pl))) {
    // one line printed for both configurations (example 1): named once
    if (prev && prev->label == e->label) {
      list.insert(list.rfind("conf. ") + 6 + as_text(prev->configuration).size(),
                  " and " + as_text(e->configuration));
      continue;
    }
    prev = e;
    list += std::string(list.empty() ? "" : "; ") + "conf. " + as_text(e->configuration) + " (" +
            format_sig(e->root_xy_m[0], 4) + ", " + format_sig(e->root_xy_m[1], 4) +
            ") m from x_S = " + format_sig(e->x_s_m, 6) + " m, φ = " + format_sig(e->phi_deg, 7) +
            "°" +
            (e->status == "unreachable" ? " (its line leaves the annulus: no motion there)" : "");
  }
  if (list.empty()) return "";
  return " Triangles: the roots the thesis prints, by (4.14) from its printed x_S and φ: " + list +
         ".";
}

}  // namespace

int cycle_time_maps(const PS& pl, FigureWriter& figures, Section& s) {
  int n = 0;
  if (pl.cycle_time)
    for (const auto& ct : pl.cycle_time->configurations)
      n += cycle_time_map_figure(pl, ct, figures, s);
  return n;
}

Section maps_section(const PS& pl, FigureWriter& figures) {
  Section s;
  s.id = "maps";
  s.heading = "Placement maps and optimal root locations";
  int n = 0;
  for (const auto& m : pl.maps) n += map_figure(pl, m, figures, s);
  // the maps' common explanation after them: a heading followed by a paragraph was left at
  // the foot of a page when the first row of maps did not fit under them
  if (n == 0)
    s.paragraph("The result holds no placement map.");
  else
    s.paragraph(
        "The maps above: the energy of the task over root locations (X, Y) in the "
        "frame fixed to the line (the line runs from the origin along X), one map per "
        "program and configuration. Only admissible placements are shaded; unreachable, "
        "inside-the-margin and over-limit regions are flat colours; the circled cross "
        "is the optimum, the square the best of the thesis's own intervals" +
        std::string(printed_root_markers(pl, 0).empty()
                        ? ""
                        : ", the triangle the root the thesis prints for the configuration") +
        ". Y < 0 is the mirror image with the configurations swapped.");
  add_energy_vs_phi(pl, figures, s);
  return s;
}

// the optimal root locations (the thesis's Fig. 9.30) into `maps`, the torque trade-off
// (Pareto fronts) as a section of its own
Section loci_and_tradeoff(const PS& pl, FigureWriter& figures, Section& maps) {
  Section s;
  s.id = "root-loci";
  s.heading = "The torque trade-off";
  const ShadedMap loci = root_loci_map(pl);
  if (!loci.markers.empty())
    maps.figure(
        half(figures.map("root_loci", loci,
                         "Optimal root location of each program and configuration in the line's "
                         "frame (the line starts at the origin), as the thesis's Figure 9.30, "
                         "with each optimum's workspace annulus (dotted) and the locus of the "
                         "least-energy root as the allowed peak torque of joint 1 grows (the "
                         "trade-off below)." +
                             printed_roots_caption(pl))));
  for (int joint = 1; joint <= 2; ++joint) {
    const LinePlot plot = pareto_plot(pl, joint);
    bool any = false;
    for (const auto& se : plot.series) any |= se.x.size() >= 1;
    if (any)
      s.figure(half(figures.line("pareto_joint" + std::to_string(joint), half_size(plot),
                                 "Trade-off for joint " + std::to_string(joint) +
                                     ": the least admissible energy whose peak torque of joint " +
                                     std::to_string(joint) + " stays below the abscissa.")));
  }
  if (s.blocks.empty())
    s.paragraph("No admissible placement, so no trade-off between peak torque and energy.");
  else
    s.paragraph(
        "The trade-off plots show what a stronger motor buys: the least energy over the "
        "admissible placements only (clear of the margin, within every limit, energy "
        "converged) whose peak torque stays below the abscissa. Grey dotted: the same over "
        "candidates inside the margin, which are inadmissible and never part of a front.");
  return s;
}

}  // namespace armstudy::report::placement_page
