// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/plot.hpp"

#include <gtest/gtest.h>

#include "testing/files.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace armstudy::report {
namespace {
namespace fs = std::filesystem;

using armstudy::testing::slurp;

fs::path test_dir(const std::string& name) {
  return armstudy::testing::fresh_dir("plot_test_" + name);
}

LinePlot sine_plot() {
  LinePlot p;
  p.title = "joint angles";
  p.x_label = "time (s)";
  p.y_label = "angle (rad)";
  for (int k = 0; k < 2; ++k) {
    Series s;
    s.label = "joint " + std::to_string(k + 1);
    s.colour = colour_for("joint" + std::to_string(k + 1));
    for (int i = 0; i <= 100; ++i) {
      s.x.push_back(i * 0.01);
      s.y.push_back(std::sin(6.0 * i * 0.01 + k));
    }
    p.series.push_back(s);
  }
  p.references.push_back({0.75, "limit 0.75 rad"});
  return p;
}

TEST(Plot, LinePlotIsACompleteSvgOnAWhiteBackground) {
  const fs::path d = test_dir("line");
  write_line_plot(sine_plot(), d / "a.svg");
  const std::string svg = slurp(d / "a.svg");
  ASSERT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("rgb(100%,100%,100%)"), std::string::npos) << "no white fill";
  EXPECT_EQ(svg.find(".part"), std::string::npos);
  for (const auto& e : fs::directory_iterator(d))  // the temporary file was renamed
    EXPECT_EQ(e.path().filename().string().find(".part"), std::string::npos) << e.path();
  // cairo's styles are folded into classes: one <style>, no style attributes left
  EXPECT_NE(svg.find("<style>"), std::string::npos);
  EXPECT_EQ(svg.find(" style=\""), std::string::npos);
  // coordinates use a decimal point, never a comma (the C locale)
  const std::regex comma_decimal(R"(d="[^"]*\d,\d)");
  EXPECT_FALSE(std::regex_search(svg, comma_decimal));
}

TEST(Plot, EachConfigurationAndSolverKeepsOneDistinctColour) {
  EXPECT_EQ(colour_for("cycloidal/1"), colour_for("cycloidal/1"));
  const char* keys[] = {"cycloidal/1", "cycloidal/2", "poly345/1", "poly345/2"};
  for (const char* a : keys)
    for (const char* b : keys)
      if (std::string(a) != b) {
        EXPECT_FALSE(colour_for(a) == colour_for(b)) << a << " " << b;
      }
  EXPECT_FALSE(colour_for("dp") == colour_for("reachability"));
  EXPECT_FALSE(colour_for("dp") == colour_for("complex"));
  EXPECT_FALSE(colour_for("idp") == colour_for("gradient"));
  // unknown keys get a stable palette colour that the stylesheet has a swatch class for
  const auto palette = palette_colours();
  EXPECT_NE(std::find(palette.begin(), palette.end(), colour_for("some other program/1")),
            palette.end());
  EXPECT_EQ(css_colour({0, 114, 178}), "#0072b2");
}

TEST(Plot, InconsistentSeriesSizesAreRejected) {
  LinePlot p = sine_plot();
  p.series[0].y.pop_back();
  EXPECT_THROW(write_line_plot(p, test_dir("bad") / "b.svg"), std::invalid_argument);
}
}  // namespace
}  // namespace armstudy::report

namespace armstudy::report {
namespace {

ShadedMap annulus_map() {
  ShadedMap m;
  m.title = "energy over root locations";
  m.x_label = "X (m)";
  m.y_label = "Y (m)";
  m.z_label = "energy (J)";
  m.nx = 120;
  m.ny = 100;
  m.x_min = -1.2;
  m.x_max = 1.2;
  m.y_min = -1.0;
  m.y_max = 1.0;
  m.z.assign(m.nx * m.ny, NAN);
  MapRegion out{"unreachable", {215, 215, 215}, std::vector<std::uint8_t>(m.nx * m.ny, 0)};
  MapRegion sing{"singular", {240, 120, 120}, std::vector<std::uint8_t>(m.nx * m.ny, 0)};
  for (int j = 0; j < m.ny; ++j)
    for (int i = 0; i < m.nx; ++i) {
      const double x = m.x_min + (m.x_max - m.x_min) * i / (m.nx - 1);
      const double y = m.y_min + (m.y_max - m.y_min) * j / (m.ny - 1);
      const double r = std::hypot(x, y);
      const size_t k = static_cast<size_t>(j) * m.nx + i;
      if (r > 0.9 || r < 0.2)
        out.mask[k] = 1;
      else if (r < 0.3)
        sing.mask[k] = 1;
      else
        m.z[k] = 1.0 + (x - 0.4) * (x - 0.4) + y * y;
    }
  m.regions = {out, sing};
  Series line;
  line.label = "task line";
  line.colour = {0, 0, 0};
  line.x = {0.3, 0.7};
  line.y = {0.4, 0.4};
  m.overlays = {line};
  m.markers = {{0.4, 0.0, "optimum", colour_for("cycloidal/1")}};
  return m;
}

TEST(Plot, ShadedMapHasColourBarRegionsAndMarker) {
  const fs::path d = test_dir("map");
  write_shaded_map(annulus_map(), d / "m.svg");
  const std::string svg = slurp(d / "m.svg");
  ASSERT_NE(svg.find("</svg>"), std::string::npos);
  // region colours appear as fills: cairo writes percentages
  EXPECT_NE(svg.find("fill:rgb(94.117647%,47.058824%,47.058824%)"), std::string::npos)
      << "singular region not drawn";
  EXPECT_NE(svg.find("fill:rgb(84.313725%,84.313725%,84.313725%)"), std::string::npos)
      << "unreachable region not drawn";
}

}  // namespace
}  // namespace armstudy::report
