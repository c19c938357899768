// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/diff_tolerances.hpp"

#include <algorithm>
#include <filesystem>
#include <string_view>

#include "app/pipeline.hpp"
#include "cases/yaml_reader.hpp"

namespace armstudy::cli {
namespace {

using report::FigureTolerance;

std::string where(const std::string& file, const YAML::Node& node) {
  const YAML::Mark m = node.Mark();
  if (m.is_null()) return file;
  return file + ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1);
}

// {abs: x, rel: y, ignore: bool}: at least one of them
std::optional<FigureTolerance> read_tolerance(cases::Map& parent, const std::string& key,
                                              const std::string& file) {
  auto m = parent.map(key);
  if (!m) return std::nullopt;
  FigureTolerance t;
  const auto abs = m->number("abs", cases::NumberRule::non_negative("in the figure's unit"));
  const auto rel = m->number("rel", cases::NumberRule::non_negative("relative, 0.01 = 1 %"));
  const auto ignore = m->boolean("ignore");
  m->finish();
  if (!m->has("abs") && !m->has("rel") && !m->has("ignore")) {
    m->error_here("'" + m->context() + "' sets nothing; expected abs, rel and/or ignore");
    return std::nullopt;
  }
  t.abs = abs.value_or(0);
  t.rel = rel.value_or(0);
  t.ignore = ignore.value_or(false);
  t.source = where(file, m->node());
  return t;
}

// '*' any run of characters, '?' one character; everything else literal (key figure names
// hold brackets and commas, e.g. "energy_J[cycloidal,1]")
bool matches(std::string_view pattern, std::string_view name) {
  size_t p = 0, n = 0, star = std::string_view::npos, mark = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p;
      ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      mark = n;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      n = ++mark;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

}  // namespace

FigureTolerance DiffTolerances::lookup(const std::string& study, const std::string& figure) const {
  for (const auto& s : studies) {
    if (s.name != study) continue;
    for (const auto& e : s.figures)
      if (e.pattern == figure) return e.tolerance;
    for (const auto& e : s.figures)
      if (matches(e.pattern, figure)) return e.tolerance;
    if (figure.find("run_time") != std::string::npos) break;
    if (s.fallback) return *s.fallback;
  }
  FigureTolerance t;
  if (figure.find("run_time") != std::string::npos) {
    t.ignore = true;
    t.source = "built-in: a wall-clock run time";
    return t;
  }
  if (fallback) return *fallback;
  t.source = "built-in: exact";
  return t;
}

DiffTolerances load_diff_tolerances(const std::string& path) {
  cases::Diagnostics diag(path);
  DiffTolerances out;
  out.file = path;
  // a missing file, a FIFO, a device or a link loop: refused by parse_file, never waited on
  const auto root_node = cases::parse_file(
      path, diag, nullptr,
      "a YAML mapping of tolerances ('default:', 'studies:' and/or 'frames:'; docs/ci.md)");
  if (!root_node) diag.throw_if_any();
  cases::Map root(*root_node, diag, "");
  out.fallback = read_tolerance(root, "default", path);
  if (auto frames = root.map("frames")) {
    out.pixel_channel = frames->integer("channel", 0, 255);
    if (const auto n = frames->integer("pixels", 0, 1 << 30)) out.pixels = static_cast<size_t>(*n);
    frames->finish();
  }
  std::vector<std::string> known;
  for (const auto& e : app::study_registry()) known.emplace_back(e.study);
  if (auto studies = root.map("studies")) {
    for (const auto& kv : studies->node()) {
      if (!kv.first.IsScalar()) continue;  // reported by Map
      const std::string name = kv.first.Scalar();
      if (std::find(known.begin(), known.end(), name) == known.end()) {
        const auto c = cases::closest(name, known);
        studies->diag().error(
            kv.first.Mark(),
            "unknown study '" + name + "'" +
                (c ? "; did you mean '" + *c + "'?"
                   : "; expected one of placement, pendulum, throwing, time_optimal"));
        studies->get(name);
        continue;
      }
      auto sm = studies->map(name);
      if (!sm) continue;
      DiffTolerances::Study st;
      st.name = name;
      st.fallback = read_tolerance(*sm, "default", path);
      if (auto figs = sm->map("figures")) {
        for (const auto& f : figs->node()) {
          if (!f.first.IsScalar()) continue;
          const std::string pattern = f.first.Scalar();
          if (auto t = read_tolerance(*figs, pattern, path)) st.figures.push_back({pattern, *t});
        }
        figs->finish();
      }
      sm->finish();
      out.studies.push_back(std::move(st));
    }
    studies->finish();
  }
  root.finish();
  diag.throw_if_any();
  return out;
}

}  // namespace armstudy::cli
