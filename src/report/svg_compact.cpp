// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/svg_compact.hpp"

#include <cstdlib>
#include <map>
#include <optional>
#include <string_view>
#include <vector>

namespace armstudy::report {
namespace {

// how the paths of one class may be merged
enum class Merge { kNo, kStrokes, kFills };

// the declarations of a style attribute, "key:value;..." (values as written)
std::map<std::string, std::string> declarations(std::string_view style) {
  std::map<std::string, std::string> out;
  while (!style.empty()) {
    const size_t end = std::min(style.find(';'), style.size());
    const std::string_view d = style.substr(0, end);
    style.remove_prefix(std::min(style.size(), end + 1));
    const size_t colon = d.find(':');
    if (colon == std::string_view::npos) continue;
    out[std::string(d.substr(0, colon))] = std::string(d.substr(colon + 1));
  }
  return out;
}

// Painting paths of this style one after the other gives the same picture as painting
// them as one path when each paint is opaque, whole (no dashes, whose pattern would run
// on) and in one colour: strokes only, or a fill (non-zero rule) in the stroke's colour.
// Fill and stroke are needed explicitly (an inherited one is not known here); any
// declaration not listed could make the order matter, and keeps the paths apart.
Merge merge_kind(std::string_view style) {
  const auto d = declarations(style);
  static const char* kKnown[] = {"fill",
                                 "fill-rule",
                                 "fill-opacity",
                                 "stroke",
                                 "stroke-width",
                                 "stroke-linecap",
                                 "stroke-linejoin",
                                 "stroke-opacity",
                                 "stroke-miterlimit",
                                 "opacity",
                                 "stroke-dasharray"};
  for (const auto& [key, value] : d) {
    bool known = false;
    for (const char* k : kKnown) known |= key == k;
    if (!known) return Merge::kNo;
  }
  const auto get = [&](const char* key) -> std::optional<std::string> {
    const auto it = d.find(key);
    if (it == d.end()) return std::nullopt;
    return it->second;
  };
  for (const char* k : {"opacity", "fill-opacity", "stroke-opacity"})
    if (get(k) && *get(k) != "1") return Merge::kNo;
  if (get("stroke-dasharray") && *get("stroke-dasharray") != "none") return Merge::kNo;
  const auto fill = get("fill"), stroke = get("stroke");
  if (!fill || !stroke) return Merge::kNo;
  if (*fill == "none") return Merge::kStrokes;
  if (get("fill-rule") && *get("fill-rule") != "nonzero") return Merge::kNo;
  if (*stroke == "none" || *stroke == *fill) return Merge::kFills;
  return Merge::kNo;
}

// one "<path class="c" d="..." [transform="t"]/>" as compact_svg's first pass writes them
struct PathElement {
  size_t begin = 0, end = 0;  // [begin, end) in the text
  std::string_view cls, d, transform;
};

std::optional<PathElement> path_at(std::string_view text, size_t at) {
  PathElement e;
  e.begin = at;
  size_t p = at;
  const auto take = [&](std::string_view literal) {
    if (text.compare(p, literal.size(), literal) != 0) return false;
    p += literal.size();
    return true;
  };
  const auto value = [&](std::string_view* out) {
    const size_t q = text.find('"', p);
    if (q == std::string_view::npos) return false;
    *out = text.substr(p, q - p);
    p = q + 1;
    return true;
  };
  if (!take("<path class=\"") || !value(&e.cls) || !take(" d=\"") || !value(&e.d)) return {};
  if (take(" transform=\"") && !value(&e.transform)) return {};
  if (!take("/>")) return {};
  e.end = p;
  return e;
}

// the subpath of a polygon "M x y L x y ... [Z]" (cairo's tokens) turned counter-clockwise
// in the drawing's coordinates; nullopt when `d` is anything else (curves, more subpaths)
std::optional<std::string> counter_clockwise(std::string_view d) {
  std::vector<std::string_view> x, y;
  bool closed = false;
  size_t p = 0;
  const auto token = [&]() -> std::string_view {
    while (p < d.size() && d[p] == ' ') ++p;
    const size_t q = std::min(d.find(' ', p), d.size());
    const std::string_view t = d.substr(p, q - p);
    p = q;
    return t;
  };
  for (std::string_view t = token(); !t.empty(); t = token()) {
    if (closed) return std::nullopt;  // something after Z
    if (t == "Z") {
      closed = true;
      continue;
    }
    if ((t == "M") != x.empty() || (t != "M" && t != "L")) return std::nullopt;
    const std::string_view a = token(), b = token();
    if (a.empty() || b.empty()) return std::nullopt;
    x.push_back(a);
    y.push_back(b);
  }
  if (x.empty()) return std::nullopt;
  double area2 = 0;  // twice the signed area (shoelace)
  std::vector<double> xv(x.size()), yv(y.size());
  for (size_t i = 0; i < x.size(); ++i) {
    char* end = nullptr;
    const std::string xs(x[i]), ys(y[i]);
    xv[i] = std::strtod(xs.c_str(), &end);
    if (*end) return std::nullopt;
    yv[i] = std::strtod(ys.c_str(), &end);
    if (*end) return std::nullopt;
  }
  for (size_t i = 0; i < x.size(); ++i) {
    const size_t j = (i + 1) % x.size();
    area2 += xv[i] * yv[j] - xv[j] * yv[i];
  }
  std::string out;
  out.reserve(d.size() + 1);
  const auto point = [&](size_t i, const char* cmd) {
    out += cmd;
    out += x[i];
    out += ' ';
    out += y[i];
    out += ' ';
  };
  if (area2 >= 0) {
    for (size_t i = 0; i < x.size(); ++i) point(i, i == 0 ? "M " : "L ");
  } else {
    for (size_t i = x.size(); i-- > 0;) point(i, i + 1 == x.size() ? "M " : "L ");
  }
  if (closed) out += "Z ";
  return out;
}

// the class styles of the first pass, then every run of mergeable paths merged
// (over 60 lines, kept whole: one pass over the SVG's elements)
std::string merge_paths(const std::string& body, const std::map<std::string, std::string>& css) {
  std::map<std::string, Merge, std::less<>> kind;
  for (const auto& [style, name] : css) kind[name] = merge_kind(style);
  const std::string_view text(body);
  std::string out;
  out.reserve(body.size());
  size_t copied = 0;  // text before this is in out
  size_t pos = 0;
  while (true) {
    const size_t at = text.find("<path class=\"", pos);
    if (at == std::string_view::npos) break;
    std::optional<PathElement> first = path_at(text, at);
    const auto k = first ? kind.find(first->cls) : kind.end();
    if (!first || k == kind.end() || k->second == Merge::kNo) {
      pos = at + 1;
      continue;
    }
    // the run: paths of this class and transform, nothing but white space between them
    const Merge m = k->second;
    std::vector<PathElement> run = {*first};
    std::vector<std::string> polygons;
    const auto add_polygon = [&](const PathElement& e) {
      if (m != Merge::kFills) return true;
      std::optional<std::string> ccw = counter_clockwise(e.d);
      if (!ccw) return false;
      polygons.push_back(std::move(*ccw));
      return true;
    };
    if (!add_polygon(*first)) {
      pos = first->end;
      continue;
    }
    size_t next = first->end;
    while (true) {
      size_t q = next;
      while (q < text.size() && (text[q] == '\n' || text[q] == ' ')) ++q;
      const std::optional<PathElement> e = path_at(text, q);
      if (!e || e->cls != first->cls || e->transform != first->transform || !add_polygon(*e)) break;
      run.push_back(*e);
      next = e->end;
    }
    if (run.size() > 1) {
      out.append(text.substr(copied, at - copied));
      out += "<path class=\"";
      out += first->cls;
      out += "\" d=\"";
      for (size_t i = 0; i < run.size(); ++i) {
        const std::string_view d = m == Merge::kFills ? std::string_view(polygons[i]) : run[i].d;
        out += d;
        if (!d.empty() && d.back() != ' ') out += ' ';
      }
      if (!out.empty() && out.back() == ' ') out.pop_back();
      out += '"';
      if (!first->transform.empty()) {
        out += " transform=\"";
        out += first->transform;
        out += '"';
      }
      out += "/>";
      copied = next;
    }
    pos = next;
  }
  out.append(text.substr(copied));
  return out;
}

}  // namespace

std::string compact_svg(const std::string& svg) {
  static const std::string kOpen = " style=\"";
  std::map<std::string, std::string> classes;
  std::string body;
  body.reserve(svg.size() / 2);
  size_t pos = 0;
  while (true) {
    const size_t a = svg.find(kOpen, pos);
    if (a == std::string::npos) break;
    const size_t b = svg.find('"', a + kOpen.size());
    if (b == std::string::npos) break;
    const std::string style = svg.substr(a + kOpen.size(), b - a - kOpen.size());
    std::string name = "s";  // (not "s" + to_string: GCC 12 warns -Wrestrict falsely)
    name += std::to_string(classes.size());
    auto [it, fresh] = classes.try_emplace(style, std::move(name));
    body.append(svg, pos, a - pos);
    body += " class=\"" + it->second + "\"";
    pos = b + 1;
  }
  body.append(svg, pos, std::string::npos);
  body = merge_paths(body, classes);
  std::string css = "<style>";
  for (const auto& [style, name] : classes) css += "." + name + "{" + style + "}\n";
  css += "</style>\n";
  // right after the opening <svg ...> tag
  const size_t root = body.find("<svg");
  const size_t end = root == std::string::npos ? root : body.find('>', root);
  if (end == std::string::npos) return svg;
  body.insert(end + 1, "\n" + css);
  return body;
}

}  // namespace armstudy::report
