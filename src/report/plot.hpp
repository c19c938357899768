// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Plots as SVG files through PLplot's cairo driver (svgcairo): line plots with axes,
/// units and legends, and shaded maps with a colour bar, masked regions and markers.
///
/// PLplot keeps global state, so every call here holds one process-wide lock; plots of
/// parallel cases are drawn one after the other. Numbers are written in the C locale
/// whatever the process locale is. The background is white (PLplot's default is black).
/// PLplot/cairo SVGs use fixed element ids: embed each file as <img>, never inline.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace armstudy::report {

/// An sRGB colour.
struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

/// The colour of a configuration, program, solver or joint, the same in every plot of
/// every report. Known keys: "<program>/<configuration>" of the placement study (e.g.
/// "cycloidal/1", "poly345/2"), solver names ("dp", "complex", "reachability",
/// "initial", "idp", "gradient"), "joint1".."joint4", "limit", "energy". Other keys get a
/// stable colour from a colour-blind-safe palette (hash of the key).
Rgb colour_for(std::string_view key);

/// Every colour colour_for can return (for the stylesheet's swatch classes).
std::vector<Rgb> palette_colours();

/// "#rrggbb" of a colour (for HTML swatches).
std::string css_colour(const Rgb& c);

enum class LineStyle { kSolid, kDashed, kDotted };

/// One curve of a line plot. Points with a NaN coordinate split the curve.
struct Series {
  std::string label;  ///< legend text; empty: not in the legend
  std::vector<double> x, y;
  Rgb colour;
  LineStyle style = LineStyle::kSolid;
  bool markers = false;  ///< draw a symbol at each point (few points, e.g. convergence)
  double width = 1.6;    ///< line width (PLplot units)
};

/// A horizontal reference line (a limit), drawn dashed in grey with its label.
struct Reference {
  double y = 0;
  std::string label;
};

/// A line plot. Labels carry their units, e.g. "time (s)".
struct LinePlot {
  std::string title;
  std::string x_label, y_label;
  std::vector<Series> series;
  std::vector<Reference> references;
  bool log_y = false;  ///< logarithmic y axis (all y must be > 0)
  int width_pt = 560;  ///< page size of the SVG (points)
  int height_pt = 320;
};

/// Writes `plot` as an SVG file.
/// @throws std::invalid_argument if a series' x and y sizes differ or nothing is finite;
/// std::runtime_error if the file cannot be written.
void write_line_plot(const LinePlot& plot, const std::filesystem::path& svg);

/// A point marked on a map (e.g. the optimum), with a label written beside it.
struct Marker {
  double x = 0, y = 0;
  std::string label;
  Rgb colour;
  bool primary = true;  ///< a large circled cross (an optimum), else a small square
  /// a point a source document prints (e.g. a thesis's optimum): a triangle, whatever
  /// `primary` says, drawn above the squares and below the circled crosses
  bool printed = false;
};

/// A region of a map drawn in one flat colour (e.g. infeasible, singular), with a legend.
struct MapRegion {
  std::string label;
  Rgb colour;
  std::vector<std::uint8_t> mask;  ///< nx*ny, index j*nx + i (row j along y); 1 = inside
};

/// A shaded map z(x, y) over a uniform grid, with colour bar, regions and markers.
struct ShadedMap {
  std::string title;
  std::string x_label, y_label, z_label;
  int nx = 0, ny = 0;
  /// centres of the first/last cells; with no z values and no regions (a drawing of curves
  /// and markers), the plotted range itself
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;
  std::vector<double> z;  ///< nx*ny, index j*nx + i; NaN = no value (left to the regions)
  std::vector<MapRegion> regions;
  std::vector<Series> overlays;  ///< curves drawn over the map (e.g. the task line)
  std::vector<Marker> markers;
  int levels = 16;  ///< colour bands
  bool equal_aspect = true;
  int width_pt = 560;
  int height_pt = 460;  ///< the most it takes; see fit_height
  /// with equal_aspect: the drawing is only as tall as the data's aspect needs (a wide
  /// region gives a short figure rather than white space above and below it)
  bool fit_height = false;
};

/// Writes `map` as an SVG file.
/// @throws std::invalid_argument on inconsistent sizes; std::runtime_error on write failure.
void write_shaded_map(const ShadedMap& map, const std::filesystem::path& svg);

}  // namespace armstudy::report
