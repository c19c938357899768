// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include <algorithm>
#include <regex>

#include "app/pipeline.hpp"
#include "app/run_order.hpp"

namespace armstudy::app {

namespace {

LoadedCase load_root(const std::optional<YAML::Node>& root_node, cases::Diagnostics& diag,
                     LoadedCase out, const LoadOptions& options);

}  // namespace

LoadedCase load_case(const std::string& path, const LoadOptions& options) {
  cases::Diagnostics diag(path);
  LoadedCase out;
  out.info.path = path;
  const auto root_node = cases::parse_file(path, diag, &out.info.yaml);
  return load_root(root_node, diag, std::move(out), options);
}

LoadedCase load_case_text(const std::string& text, const std::string& path,
                          const LoadOptions& options) {
  cases::Diagnostics diag(path);
  LoadedCase out;
  out.info.path = path;
  out.info.yaml = text;
  const auto root_node = cases::parse_text(text, diag);
  return load_root(root_node, diag, std::move(out), options);
}

namespace {

// the study's estimated work (with the sensitivity part's re-solves) and memory, and the
// frames, against the budget
void check_budget(cases::Map& root, const cases::CaseInfo& info) {
  const cases::RenderOptions& render = info.render;
  const cases::Resolves resolves{info.sensitivity.items.size(), kSensitivityResolveFraction};
  cases::Diagnostics& diag = root.diag();
  std::vector<cases::Demand> demands = diag.demands();
  if (demands.empty()) {
    cases::Demand d;
    d.what = "the case";
    d.mark = root.node().Mark();
    demands.push_back(d);
  }
  for (const cases::Demand& d : demands) {
    for (const cases::OverBudget& o :
         cases::over_budget(d, render.frames, render.frame.width, render.frame.height, resolves)) {
      if (o.frames && root.has("render"))
        root.error("render", o.message);
      else
        diag.error(d.mark, o.message);
    }
  }
}

}  // namespace

// the keys every case has, after study: (the case's top-level keys read in the order of
// their errors, file:line:col)
void read_case_parts(cases::Map& root, LoadedCase& out) {
  if (const auto name = root.required_string("name")) {
    // the name is a folder name: keep it portable
    static const std::regex ok("[A-Za-z0-9][A-Za-z0-9._-]{0,99}");
    if (name->size() > 100 || !std::regex_match(*name, ok)) {
      root.error("name",
                 "'name' is '" + cases::brief(*name) +
                     "'; expected letters, digits, '.', '_' or '-' (at most 100, no spaces)");
    } else {
      out.info.name = *name;
    }
  }
  out.info.description = root.string_or("description", "");
  if (const auto e = root.choice("expect", {"solved", "unsolvable"}))
    out.info.expect_unsolvable = *e == "unsolvable";
  if (auto r = root.map("render")) {
    const cases::RenderOptions defaults;  // each default written once, in RenderOptions
    out.info.render.frame.width = r->integer_or("width", defaults.frame.width, 64, 4096);
    out.info.render.frame.height = r->integer_or("height", defaults.frame.height, 64, 4096);
    out.info.render.frames = r->integer_or("frames", defaults.frames, 1, 24);
    out.info.render.shadows = r->boolean_or("shadows", defaults.shadows);
    r->finish();
  }
  if (auto sw = root.map("sweep")) {
    out.info.sweep_name = sw->string_or("name", "");
    if (auto point = sw->map("point")) {
      for (const auto& kv : point->node()) {
        const std::string key = kv.first.Scalar();
        point->get(key);
        out.info.sweep_point.emplace_back(key, YAML::Dump(kv.second));
      }
      point->finish();
    }
    sw->finish();
  }
  out.info.source = cases::read_source(root);
  out.info.sensitivity = cases::read_sensitivity(root);
}

namespace {

LoadedCase load_root(const std::optional<YAML::Node>& root_node, cases::Diagnostics& diag,
                     LoadedCase out, const LoadOptions& options) {
  if (!root_node) diag.throw_if_any();
  out.info.sha256 = cases::sha256_hex(out.info.yaml);

  cases::Map root(*root_node, diag, "");
  std::vector<std::string> studies;
  for (const StudyEntry& e : study_registry()) studies.emplace_back(e.study);
  const auto study = root.has("study") ? root.choice("study", studies) : std::nullopt;
  if (!root.has("study")) {
    root.get("study");
    std::string list;
    for (const auto& s : studies) list += (list.empty() ? "" : ", ") + s;
    root.error_here("missing required key 'study'; expected one of: " + list);
  }
  read_case_parts(root, out);
  if (study) {
    out.info.study = *study;
    const auto it = std::find_if(study_registry().begin(), study_registry().end(),
                                 [&](const StudyEntry& e) { return e.study == *study; });
    out.run = it->load(root);
    out.entry = &*it;
  }
  if (study) root.finish();  // with no known study, its keys cannot be judged
  if (diag.empty() && !options.allow_large) check_budget(root, out.info);
  diag.throw_if_any();
  out.demands = diag.demands();
  out.allow_large = options.allow_large;
  return out;
}

}  // namespace
}  // namespace armstudy::app
