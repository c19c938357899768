// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include "app/pipeline.hpp"
#include "app/run_case.hpp"
#include "cases/case_info.hpp"
#include "cases/input_file.hpp"
#include "cases/yaml_reader.hpp"
#include "cli/confined_path.hpp"
#include "cli/sweep_manifest.hpp"

namespace armstudy::cli {
namespace fs = std::filesystem;

namespace {

constexpr size_t kMaxPathChars = 1000;
constexpr long kMaxPathIndex = 1000000;

struct Segment {
  std::string key;
  int index = 0;  // 1-based list index, 0 if none
};

// key(.key)* with an optional 1-based [index] after each key; no regex: std::regex recurses
// per character and a long hostile path would overflow the stack
bool parse_path(const std::string& path, std::vector<Segment>* out) {
  const auto is_alpha = [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
  };
  const auto is_digit = [](char c) { return c >= '0' && c <= '9'; };
  if (path.size() > kMaxPathChars) return false;
  size_t i = 0;
  for (;;) {
    Segment seg;
    if (i >= path.size() || !is_alpha(path[i])) return false;
    const size_t b = i;
    while (i < path.size() && (is_alpha(path[i]) || is_digit(path[i]))) ++i;
    seg.key = path.substr(b, i - b);
    if (i < path.size() && path[i] == '[') {
      ++i;
      long index = 0;
      const size_t d = i;
      while (i < path.size() && is_digit(path[i])) {
        index = index * 10 + (path[i] - '0');
        if (index > kMaxPathIndex) return false;
        ++i;
      }
      if (i == d || i >= path.size() || path[i] != ']' || index < 1) return false;
      ++i;
      seg.index = static_cast<int>(index);
    }
    out->push_back(seg);
    if (i == path.size()) return true;
    if (path[i] != '.') return false;
    ++i;
  }
}

// nodes of a tree (aliases counted as often as they appear); depth is bounded by the
// file checks (cases::kMaxDepth)
size_t count_nodes(const YAML::Node& n) {
  size_t c = 1;
  if (n.IsSequence() || n.IsMap())
    for (const auto& it : n)
      c += n.IsMap() ? count_nodes(it.first) + count_nodes(it.second) : count_nodes(it);
  return c;
}

std::string scalar_text(const YAML::Node& n) {
  YAML::Emitter e;
  e << YAML::Flow << n;
  return e.c_str();
}

// the base case file: `rel` taken from the sweep file's folder, which must stay, after
// resolving symlinks, inside that folder or inside one of `base_dirs` (--base-dir);
// otherwise *why says so
std::string confined_base(const std::string& sweep_path, const std::string& rel,
                          const std::vector<fs::path>& base_dirs, std::string* why) {
  const fs::path sweep_dir = fs::absolute(fs::path(sweep_path)).parent_path();
  const std::string allowed =
      "expected a path relative to the sweep file's folder, inside it" +
      std::string(base_dirs.empty() ? " (or inside a folder given with --base-dir)"
                                    : " or inside a --base-dir folder");
  if (rel.empty() || fs::path(rel).is_absolute()) {
    *why =
        "'base' is " + (rel.empty() ? std::string("empty") : "an absolute path") + "; " + allowed;
    return "";
  }
  const fs::path joined = (fs::path(sweep_path).parent_path() / rel).lexically_normal();
  bool ok = lies_inside(joined, sweep_dir);
  for (const auto& d : base_dirs) ok = ok || lies_inside(joined, d);
  if (!ok) {
    *why = "'base' names '" + cases::brief(rel, 200) +
           "', which is outside the sweep file's folder" +
           (base_dirs.empty() ? "" : " and the --base-dir folders") + " (symlinks resolved); " +
           allowed;
    return "";
  }
  return joined.string();
}

// a value's text for comparing: numbers by their value (0.5 and 0.50 are one value)
std::string value_key(const YAML::Node& v) {
  if (v.IsScalar()) {
    try {
      const double x = v.as<double>();
      if (std::isfinite(x)) {
        std::ostringstream os;
        os.imbue(std::locale::classic());
        os.precision(17);
        os << x;
        return "#" + os.str();
      }
    } catch (const YAML::Exception&) {
    }
  }
  return "=" + scalar_text(v);
}

// why an axis cannot be one ("" if it can): over the case's name or the sweep's own
// metadata (both set per point), a path of an earlier axis, or one value twice
std::string axis_problem(const SweepAxis& ax, const std::vector<SweepAxis>& earlier) {
  std::vector<Segment> segs;
  if (!ax.path.empty() && parse_path(ax.path, &segs) && !segs.empty()) {
    if (segs[0].key == "name")
      return "axis path '" + cases::brief(ax.path) +
             "' is the case's name, which sweep expand sets for every point; expected a "
             "parameter of the base case";
    if (segs[0].key == "sweep")
      return "axis path '" + cases::brief(ax.path) +
             "' is inside the 'sweep' mapping, which sweep expand writes for every point; "
             "expected a parameter of the base case";
  }
  for (const auto& e : earlier)
    if (!ax.path.empty() && e.path == ax.path)
      return "axis path '" + cases::brief(ax.path) + "' is also the axis at line " +
             std::to_string(e.mark.line + 1) + "; expected each parameter on one axis";
  std::map<std::string, size_t> seen;
  for (size_t i = 0; i < ax.values.size(); ++i) {
    const auto [it, fresh] = seen.emplace(value_key(ax.values[i]), i);
    if (!fresh)
      return "axis '" + cases::brief(ax.path) + "' has value " + std::to_string(i + 1) + " (" +
             cases::brief(scalar_text(ax.values[i])) + ") equal to value " +
             std::to_string(it->second + 1) + " (" +
             cases::brief(scalar_text(ax.values[it->second])) +
             "); expected distinct values (each would be the same case)";
  }
  return "";
}

}  // namespace

std::string set_path(YAML::Node root, const std::string& path, const YAML::Node& value) {
  std::vector<Segment> segs;
  if (!parse_path(path, &segs))
    return "'" + cases::brief(path) + "' is not a parameter path like arm.links[2].length";
  YAML::Node cur = root;
  for (size_t i = 0; i < segs.size(); ++i) {
    const Segment& s = segs[i];
    const bool last = i + 1 == segs.size();
    if (!cur.IsMap()) return "'" + s.key + "' is below a value that is not a mapping";
    if (s.index == 0) {
      if (last) {
        cur[s.key] = YAML::Clone(value);
        return "";
      }
      if (!cur[s.key]) cur[s.key] = YAML::Node(YAML::NodeType::Map);
      cur.reset(cur[s.key]);
      continue;
    }
    YAML::Node list = cur[s.key];
    if (!list || !list.IsSequence()) return "'" + s.key + "' is not a list in the base case";
    if (static_cast<size_t>(s.index) > list.size())
      return "'" + s.key + "[" + std::to_string(s.index) + "]' is past the end of a list of " +
             std::to_string(list.size());
    if (last) {
      list[s.index - 1] = YAML::Clone(value);
      return "";
    }
    cur.reset(list[s.index - 1]);
  }
  return "";
}

size_t sweep_point_count(const Sweep& sweep) {
  if (sweep.axes.empty()) return 0;
  if (sweep.zip) return sweep.axes[0].values.size();
  size_t count = 1;
  for (const auto& ax : sweep.axes) {
    const size_t n = ax.values.size();
    if (n == 0) return 0;
    if (count > SIZE_MAX / n) return SIZE_MAX;  // saturates: more than size_t holds
    count *= n;
  }
  return count;
}

namespace {

// one entry of `axes`: its path and its values, listed or a range
SweepAxis read_axis(cases::Map& map, size_t i) {
  cases::Map* a = &map;
  SweepAxis ax;
  ax.mark = a->node().Mark();
  ax.path = a->required_string("path").value_or("");
  const bool has_values = a->has("values"), has_range = a->has("range");
  if (has_values == has_range) {
    a->get("values");
    a->get("range");
    a->error_here("axis " + std::to_string(i + 1) + " needs exactly one of 'values' or 'range'");
  } else if (has_values) {
    const YAML::Node v = a->get("values");
    if (!v.IsSequence() || v.size() == 0)
      a->error("values",
               "'" + a->path_of("values") + "' is not a non-empty list; expected a list of values");
    else
      for (const auto& x : v) ax.values.push_back(x);
  } else if (auto r = a->map("range")) {
    const double from = r->required_number("from", cases::NumberRule::any(""));
    const double to = r->required_number("to", cases::NumberRule::any(""));
    const int steps = r->integer_or("steps", 2, 1, 100000);
    r->finish();
    if (std::isfinite(from) && std::isfinite(to)) {
      for (int k = 0; k < steps; ++k) {
        const double x = steps == 1 ? from : from + (to - from) * k / (steps - 1);
        std::ostringstream os;
        os.imbue(std::locale::classic());
        os.precision(12);
        os << (k == steps - 1 ? to : x);
        ax.values.push_back(YAML::Load(os.str()));
      }
    }
  }
  a->finish();
  return ax;
}

// the sweep's base case, `base` relative to the sweep file (or one of `base_dirs`): its path
// and its YAML, or an error at `base`
void read_base(const std::string& path, const std::string& base_rel,
               const std::vector<fs::path>& base_dirs, cases::Map& root, Sweep* out) {
  Sweep& sw = *out;
  std::string why;
  sw.base_path = confined_base(path, base_rel, base_dirs, &why);
  if (!why.empty()) {
    root.error("base", why);
  } else {
    // the file is named, never quoted: it may be anything the path reaches
    cases::Diagnostics bd(sw.base_path);
    std::error_code ec;
    const auto b =
        fs::exists(sw.base_path, ec) ? cases::parse_file(sw.base_path, bd, nullptr) : std::nullopt;
    if (!fs::exists(sw.base_path, ec)) {
      root.error("base", "'base' names " + cases::brief(sw.base_path, 200) +
                             ", which does not exist; expected a case file");
    } else if (!b || !b->IsMap()) {
      std::string where;
      if (!bd.errors().empty() && bd.errors()[0].line > 0)
        where = " (at line " + std::to_string(bd.errors()[0].line) + ")";
      root.error("base", "'base' names " + cases::brief(sw.base_path, 200) +
                             ", which is not a case file" + where +
                             "; expected a YAML mapping with study: and name:");
    } else {
      sw.base = *b;
    }
  }
}

// the number of points, without overflow; an error when there are too many or generating
// them would make too many YAML nodes
size_t checked_point_count(const Sweep& sw, cases::Diagnostics& diag) {
  const size_t count = sweep_point_count(sw);
  const size_t base_nodes = count_nodes(sw.base);
  if (count > kMaxSweepPoints) {
    std::string sizes;
    double approx = 1;
    for (const auto& ax : sw.axes) {
      sizes += (sizes.empty() ? "" : sw.zip ? ", " : " x ") + std::to_string(ax.values.size());
      approx *= double(ax.values.size());
    }
    diag.error(
        sw.axes[0].mark,
        "the sweep has " +
            (count == SIZE_MAX ? "about " + cases::format_number(approx) : std::to_string(count)) +
            " points (" + (sw.zip ? "zip of " : "grid of ") + sizes +
            " values); expected at most " + std::to_string(kMaxSweepPoints) +
            " (split it into several sweeps)");
  } else if (static_cast<double>(count) * static_cast<double>(base_nodes) > kMaxSweepNodes) {
    diag.error(sw.axes[0].mark,
               "the sweep's " + std::to_string(count) + " points of a base case of " +
                   std::to_string(base_nodes) + " YAML nodes would generate " +
                   cases::format_number(double(count) * double(base_nodes)) +
                   " nodes; expected at most " + cases::format_number(kMaxSweepNodes));
  }
  return count;
}

// point k of the sweep: a clone of the base with the axis values set, named by the base and
// a hash of the values, checked to be a valid case; false (with an error) when it is not
bool add_point(size_t k, const std::string& base_name, const std::string& base_sha,
               cases::Diagnostics& diag, Sweep* out) {
  Sweep& sw = *out;
  YAML::Node doc = YAML::Clone(sw.base);
  std::string ident = base_sha;
  YAML::Node point(YAML::NodeType::Map);
  size_t rest = k;
  std::vector<size_t> idx(sw.axes.size());
  for (size_t a = sw.axes.size(); a-- > 0;) {
    idx[a] = sw.zip ? k : rest % sw.axes[a].values.size();
    if (!sw.zip) rest /= sw.axes[a].values.size();
  }
  bool ok = true;
  for (size_t a = 0; a < sw.axes.size(); ++a) {
    const SweepAxis& ax = sw.axes[a];
    const YAML::Node& v = ax.values[idx[a]];
    const std::string bad = set_path(doc, ax.path, v);
    if (!bad.empty()) {
      diag.error(ax.mark, "axis path '" + cases::brief(ax.path) +
                              "' names no parameter of the base case: " + bad);
      ok = false;
      continue;
    }
    point[ax.path] = YAML::Clone(v);
    ident += "\n" + ax.path + "=" + scalar_text(v);
  }
  if (!ok) return false;
  const std::string name = base_name + "-" + cases::sha256_hex(ident).substr(0, 10);
  doc["name"] = name;
  YAML::Node swn(YAML::NodeType::Map);
  swn["name"] = sw.name;
  swn["point"] = point;
  doc["sweep"] = swn;
  YAML::Emitter e;
  e << doc;
  SweepPoint p{name,
               kGeneratedHeader + sw.path + "; do not edit\n" + std::string(e.c_str()) + "\n"};
  // the generated case must be valid: an error names the axis and the point
  try {
    // the budget is judged by run and validate, where --allow-large can raise it
    app::load_case_text(p.yaml, name + ".yaml", app::LoadOptions{true});
  } catch (const cases::CaseErrors& errs) {
    std::string what = errs.errors().empty() ? "" : errs.errors()[0].message;
    std::string vals;
    for (size_t a = 0; a < sw.axes.size(); ++a)
      vals += (a ? ", " : "") + cases::brief(sw.axes[a].path) + " = " +
              cases::brief(scalar_text(sw.axes[a].values[idx[a]]));
    diag.error(sw.axes.empty() ? YAML::Mark() : sw.axes[0].mark,
               "the point (" + vals + ") gives an invalid case: " + what);
    return false;
  }
  sw.points.push_back(std::move(p));
  return true;
}

}  // namespace

Sweep load_sweep(const std::string& path, const std::vector<fs::path>& base_dirs) {
  cases::Diagnostics diag(path);
  std::string text;
  const auto root_node = cases::parse_file(path, diag, &text);
  if (!root_node) diag.throw_if_any();
  Sweep sw;
  sw.path = path;
  cases::Map root(*root_node, diag, "");
  sw.name = root.required_string("sweep").value_or("");
  const auto base_rel = root.required_string("base");
  const auto mode = root.choice("mode", {"grid", "zip"});
  sw.zip = mode && *mode == "zip";
  auto axes = root.seq("axes");
  if (!axes && !root.has("axes"))
    root.error_here("missing required key 'axes'; expected a list of {path, values|range}");
  if (axes && axes->size() == 0) root.error("axes", "'axes' is empty; expected at least one axis");
  if (axes) {
    for (size_t i = 0; i < axes->size(); ++i) {
      auto a = axes->map_at(i);
      if (!a) continue;
      SweepAxis ax = read_axis(*a, i);
      if (const std::string bad = axis_problem(ax, sw.axes); !bad.empty()) diag.error(ax.mark, bad);
      sw.axes.push_back(ax);
    }
  }
  root.finish();
  if (base_rel) read_base(path, *base_rel, base_dirs, root, &sw);
  if (sw.zip && sw.axes.size() > 1) {
    for (const auto& ax : sw.axes)
      if (ax.values.size() != sw.axes[0].values.size())
        diag.error(ax.mark, "zip axis '" + cases::brief(ax.path) + "' has " +
                                std::to_string(ax.values.size()) + " values; expected " +
                                std::to_string(sw.axes[0].values.size()) + " like the first axis");
  }
  for (const auto& ax : sw.axes)
    if (ax.values.empty() && diag.empty())
      diag.error(ax.mark,
                 "axis '" + cases::brief(ax.path) + "' has no values; expected at least one");
  diag.throw_if_any();

  // the number of points, without overflow, and what generating them costs
  const size_t count = checked_point_count(sw, diag);
  diag.throw_if_any();

  // every point: a clone of the base with the axis values set
  const std::string base_name =
      sw.base["name"] && sw.base["name"].IsScalar() ? sw.base["name"].Scalar() : "case";
  const std::string base_sha = cases::sha256_hex(YAML::Dump(sw.base));
  for (size_t k = 0; k < count; ++k)
    if (!add_point(k, base_name, base_sha, diag, &sw)) break;
  diag.throw_if_any();
  return sw;
}

ExpandResult expand_sweep(const Sweep& sweep, const fs::path& out_dir) {
  ExpandResult r;
  std::set<std::string> ids;
  for (const SweepPoint& p : sweep.points) ids.insert(p.case_name);
  // the folder is the sweep's: another sweep's cases, or a file of the user's where a case
  // goes, are refused before anything is written
  const fs::path manifest_path = out_dir / kManifestName;
  std::optional<SweepManifest> old;
  try {
    old = read_manifest(manifest_path);
  } catch (const std::runtime_error& e) {
    throw ExpandRefused(std::string(e.what()) + "; nothing was written");
  }
  if (old && old->sweep != sweep.name)
    throw ExpandRefused(out_dir.string() + " holds the cases of sweep '" +
                        cases::brief(old->sweep) + "' (" + kManifestName +
                        "); expected an empty folder or one of sweep '" + sweep.name +
                        "'; nothing was written");
  for (const SweepPoint& p : sweep.points) {
    const fs::path f = out_dir / (p.case_name + ".yaml");
    std::error_code ec;
    if (fs::symlink_status(f, ec).type() != fs::file_type::not_found && !generated_by_expand(f))
      throw ExpandRefused(f.string() +
                          " exists and was not written by 'armstudy sweep expand'; expected "
                          "no such file (move it away); nothing was written");
  }
  fs::create_directories(out_dir);
  for (const SweepPoint& p : sweep.points) {
    const fs::path f = out_dir / (p.case_name + ".yaml");
    std::string now, why;
    bool runtime = false;
    if (cases::read_input_file(f.string(), {cases::kMaxFileBytes, "YAML file", false}, &now, &why,
                               &runtime) &&
        now == p.yaml)
      continue;
    app::write_file_atomic(f, p.yaml);
    ++r.written;
  }
  // points no longer in the sweep: only case files expansion wrote (their first line says so)
  std::vector<fs::path> stale;
  for (const auto& e : fs::directory_iterator(out_dir)) {
    const fs::path f = e.path();
    if (f.extension() != ".yaml" || ids.count(f.stem().string())) continue;
    if (generated_by_expand(f)) stale.push_back(f);
  }
  std::sort(stale.begin(), stale.end());
  for (const auto& f : stale) {
    fs::remove(f);
    r.removed.push_back(f.stem().string());
  }
  SweepManifest m{sweep.name, sweep.path, std::vector<std::string>(ids.begin(), ids.end())};
  app::write_file_atomic(manifest_path, manifest_text(m));
  return r;
}

}  // namespace armstudy::cli
