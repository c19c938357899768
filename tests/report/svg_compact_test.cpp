// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/svg_compact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "report/plot.hpp"
#include "testing/files.hpp"

namespace armstudy::report {
namespace {

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

std::string svg_of(const std::string& body) {
  return "<?xml version=\"1.0\"?>\n<svg width=\"10pt\" height=\"10pt\">\n" + body + "</svg>\n";
}

const char* kFill =
    "fill-rule:nonzero;fill:rgb(10%,20%,30%);fill-opacity:1;stroke-width:1;"
    "stroke:rgb(10%,20%,30%);stroke-opacity:1;";
const char* kLine = "fill:none;stroke-width:0.8;stroke:rgb(0%,0%,0%);stroke-opacity:1;";

std::string path(const std::string& style, const std::string& d, bool transform = true) {
  return "<path style=\"" + style + "\" d=\"" + d + "\"" +
         (transform ? " transform=\"matrix(1,0,0,-1,0,10)\"" : "") + "/>\n";
}

TEST(SvgCompact, StylesBecomeClasses) {
  const std::string out =
      compact_svg(svg_of(path(kLine, "M 0 0 L 1 1 ", false) + "<rect style=\"" + kFill + "\"/>\n"));
  EXPECT_EQ(out.find(" style=\""), std::string::npos);
  EXPECT_EQ(count(out, "<style>"), 1u);
  EXPECT_NE(out.find(std::string("{") + kLine + "}"), std::string::npos) << out;
  EXPECT_NE(out.find("<rect class=\"s"), std::string::npos) << out;
}

TEST(SvgCompact, ARunOfOneStrokeIsOnePathOfItsSubpaths) {
  const std::string out =
      compact_svg(svg_of(path(kLine, "M 0 0 L 1 1 ") + path(kLine, "M 2 2 C 3 3 4 4 5 5 ") +
                         path(kLine, "M 6 6 L 7 7 ")));
  EXPECT_EQ(count(out, "<path"), 1u) << out;
  EXPECT_NE(out.find("d=\"M 0 0 L 1 1 M 2 2 C 3 3 4 4 5 5 M 6 6 L 7 7\""), std::string::npos)
      << out;
  EXPECT_NE(out.find("transform=\"matrix(1,0,0,-1,0,10)\"/>"), std::string::npos) << out;
}

TEST(SvgCompact, FilledPolygonsAreOrientedAlikeSoThatTheirUnionIsFilled) {
  // a counter-clockwise and a clockwise triangle overlapping: under the non-zero rule, one
  // path of both as drawn would leave their overlap empty
  const std::string out = compact_svg(
      svg_of(path(kFill, "M 0 0 L 4 0 L 0 4 Z ") + path(kFill, "M 1 1 L 1 5 L 5 1 L 1 1 ")));
  EXPECT_EQ(count(out, "<path"), 1u) << out;
  EXPECT_NE(out.find("d=\"M 0 0 L 4 0 L 0 4 Z M 1 1 L 5 1 L 1 5 L 1 1\""), std::string::npos)
      << out;
}

TEST(SvgCompact, PathsWhoseOrderOrSeparationShowsStayApart) {
  const std::string two_colours =
      "fill-rule:nonzero;fill:rgb(10%,20%,30%);stroke:rgb(0%,0%,0%);stroke-opacity:1;";
  const std::string translucent = "fill:none;stroke:rgb(0%,0%,0%);stroke-opacity:0.5;";
  const std::string dashed = "fill:none;stroke:rgb(0%,0%,0%);stroke-dasharray:3,2;";
  const std::string even_odd = "fill-rule:evenodd;fill:rgb(10%,20%,30%);stroke:none;";
  const std::string inherited = "stroke:none;";  // (fill from a parent, if any)
  for (const std::string& style : {two_colours, translucent, dashed, even_odd, inherited}) {
    const std::string out =
        compact_svg(svg_of(path(style, "M 0 0 L 1 0 L 0 1 ") + path(style, "M 2 2 L 3 2 L 2 3 ")));
    EXPECT_EQ(count(out, "<path"), 2u) << style << "\n" << out;
  }
  // a filled curve (its orientation is not checked) and two subpaths (a hole) stay apart
  for (const char* d : {"M 0 0 C 1 0 1 1 0 1 Z ", "M 0 0 L 4 0 L 0 4 Z M 1 1 L 2 1 L 1 2 Z "}) {
    const std::string out = compact_svg(svg_of(path(kFill, d) + path(kFill, "M 5 5 L 6 5 L 5 6 ")));
    EXPECT_EQ(count(out, "<path"), 2u) << d << "\n" << out;
  }
  // another element, another class or another transform between them ends a run
  const std::string out =
      compact_svg(svg_of(path(kLine, "M 0 0 L 1 1 ") + "<use href=\"#g\"/>\n" +
                         path(kLine, "M 1 1 L 2 2 ") + path(kFill, "M 0 0 L 1 0 L 0 1 ") +
                         path(kLine, "M 2 2 L 3 3 ") + path(kLine, "M 3 3 L 4 4 ", false)));
  EXPECT_EQ(count(out, "<path"), 5u) << out;
}

TEST(SvgCompact, AShadedMapDrawsFewPaths) {
  // a map of a smooth field: its ~thousands of cell polygons come in runs of one colour
  ShadedMap m;
  m.title = "field";
  m.nx = 41;
  m.ny = 31;
  m.x_min = 0;
  m.x_max = 1;
  m.y_min = 0;
  m.y_max = 1;
  for (int j = 0; j < m.ny; ++j)
    for (int i = 0; i < m.nx; ++i) m.z.push_back(std::sin(0.2 * i) * std::cos(0.15 * j));
  const auto dir = armstudy::testing::fresh_dir("svg_compact_map");
  write_shaded_map(m, dir / "m.svg");
  const std::string svg = armstudy::testing::slurp(dir / "m.svg");
  // (every level's cells are one path: about as many paths as levels, plus the frame)
  EXPECT_LT(count(svg, "<path"), 400u);
  EXPECT_GT(count(svg, " M "), 1000u) << "the cells are still drawn";
}

}  // namespace
}  // namespace armstudy::report
