// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "app/sensitivity.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <regex>
#include <stdexcept>

#include "cases/case_error.hpp"
#include "cases/yaml_reader.hpp"

namespace armstudy::app {
namespace {

// shortest text that reads back as the same double
std::string exact_text(double v) {
  char b[40];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    if (std::strtod(b, nullptr) == v) break;
  }
  return b;
}

// the node at `path` (dotted keys, [N] 1-based) in `root`, which must exist
YAML::Node sensitivity_node(YAML::Node root, const std::string& path) {
  static const std::regex segment("([A-Za-z_][A-Za-z0-9_]*)(?:\\[([0-9]+)\\])?");
  YAML::Node cur = root;
  size_t at = 0;
  for (;;) {
    const size_t dot = path.find('.', at);
    const std::string part =
        path.substr(at, dot == std::string::npos ? std::string::npos : dot - at);
    std::smatch m;
    if (!std::regex_match(part, m, segment) || !cur.IsMap() || !cur[m[1].str()])
      throw std::invalid_argument("'" + path + "' names no key of the case");
    YAML::Node next = cur[m[1].str()];
    if (m[2].matched) {
      const size_t i = std::stoul(m[2].str());
      if (!next.IsSequence() || i < 1 || i > next.size())
        throw std::invalid_argument("'" + path + "' names no entry of a list of the case");
      next.reset(next[i - 1]);
    }
    cur.reset(next);
    if (dot == std::string::npos) return cur;
    at = dot + 1;
  }
}

std::string percent_text(double share) {
  char b[32];
  std::snprintf(b, sizeof b, "%g %%", 100 * share);
  return b;
}

// "-10 %" or "-0.25" for one side of a key
std::string side_text(const cases::SensitivityItem& it, int sign) {
  return (sign < 0 ? "-" : "+") + (it.relative ? percent_text(it.step) : exact_text(it.step));
}

// one re-solve of the case with the key at `values`
report::SensitivityStepRecord solve_step(const LoadedCase& nominal, const std::string& key,
                                         const std::string& step_name,
                                         const std::vector<double>& values,
                                         const std::string& headline,
                                         const std::vector<std::string>& nominal_binding,
                                         double nominal_value) {
  const auto t0 = std::chrono::steady_clock::now();
  report::SensitivityStepRecord s;
  s.key_value = values;
  try {
    // judged against the budget as the case was (a step of a key that sets the size, a
    // grid or a step count, may take it beyond: then the step is "invalid", saying so)
    LoadedCase c = load_case_text(case_text_with(nominal.info.yaml, key, values), nominal.info.path,
                                  LoadOptions{nominal.allow_large});
    c.run->warm_start(*nominal.run);
    const studies::Status st = c.run->solve({});
    s.warm = c.run->warm_started();
    s.message = c.run->message();
    if (st != studies::Status::kSolved) {
      s.status = "unsolvable";
    } else {
      s.status = s.message.rfind("NOT converged", 0) == 0 ? "not_converged" : "solved";
      for (const KeyFigure& k : c.run->key_figures())
        if (k.name == headline && std::isfinite(k.value)) s.value = k.value;
      if (s.value) s.change = *s.value - nominal_value;
      s.binding = c.run->binding();
      s.binding_changed = s.binding != nominal_binding;
      // its answer, if it meets the case's own limits for less, is a start of the case's next
      // solve (StudyRun::offer_start; run_case solves the case again)
      nominal.run->offer_start(*c.run, "the sensitivity step " + key + " " + step_name);
    }
  } catch (const cases::CaseErrors& e) {
    s.status = "invalid";
    s.message = e.errors().empty() ? "the case refuses this value" : e.errors().front().message;
  } catch (const std::exception& e) {
    s.status = "unsolvable";
    s.message = e.what();
  }
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

std::string values_text(const std::vector<double>& v) {
  if (v.size() == 1) return exact_text(v[0]);
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + exact_text(v[i]);
  return s + "]";
}

}  // namespace

std::string case_text_with(const std::string& yaml, const std::string& key,
                           const std::vector<double>& values) {
  cases::Diagnostics diag("(sensitivity)");
  const auto parsed = cases::parse_text(yaml, diag);
  if (!parsed) throw std::invalid_argument("the case text does not parse");
  YAML::Node root = YAML::Clone(*parsed);
  root.remove("sensitivity");
  root.remove("source");
  YAML::Node n = sensitivity_node(root, key);
  if (n.IsSequence()) {
    if (n.size() != values.size())
      throw std::invalid_argument("'" + key + "' has " + std::to_string(n.size()) + " entries");
    for (size_t i = 0; i < values.size(); ++i) n[i] = exact_text(values[i]);
  } else {
    if (values.size() != 1) throw std::invalid_argument("'" + key + "' is one number");
    n = exact_text(values[0]);
  }
  YAML::Emitter e;
  e << root;
  return std::string(e.c_str()) + "\n";
}

// (over 60 lines, kept whole: the keys' steps in order, each re-solved and recorded)
std::optional<report::SensitivityRecord> run_sensitivity(const LoadedCase& nominal,
                                                         const studies::ProgressFn& progress,
                                                         double from, double to) {
  const auto& items = nominal.info.sensitivity.items;
  if (items.empty() || !nominal.run) return std::nullopt;
  const auto t0 = std::chrono::steady_clock::now();
  report::SensitivityRecord r;
  r.figure = nominal.run->headline();
  bool found = false;
  for (const KeyFigure& k : nominal.run->key_figures())
    if (k.name == r.figure) {
      found = std::isfinite(k.value);
      r.nominal = k.value;
      r.unit = k.unit;
      r.label = k.label.empty() ? k.name : k.label;
    }
  if (!found) return std::nullopt;
  r.binding = nominal.run->binding();
  const size_t total = 2 * items.size();
  size_t done = 0;
  for (const cases::SensitivityItem& it : items) {
    report::SensitivityKeyRecord k;
    k.key = it.key;
    k.step_kind = it.relative ? "relative" : "absolute";
    k.step = it.step;
    k.nominal = it.nominal;
    k.why = it.why;
    for (const int sign : {-1, +1}) {
      if (progress)
        progress(from + (to - from) * double(done) / double(total),
                 "sensitivity " + std::to_string(done + 1) + "/" + std::to_string(total) + ": " +
                     it.key + " " + side_text(it, sign));
      std::vector<double> values = it.nominal;
      for (double& v : values) v = it.relative ? v * (1 + sign * it.step) : v + sign * it.step;
      (sign < 0 ? k.minus : k.plus) =
          solve_step(nominal, it.key, side_text(it, sign), values, r.figure, r.binding, r.nominal);
      ++done;
    }
    // central difference over the two steps; the key's relative change is 2 h (relative)
    // or 2 d / k0 (absolute)
    const double dk = it.relative          ? 2 * it.step
                      : it.nominal[0] != 0 ? 2 * it.step / it.nominal[0]
                                           : NAN;
    if (k.minus.value && k.plus.value && r.nominal != 0 && std::isfinite(dk))
      k.elasticity = ((*k.plus.value - *k.minus.value) / r.nominal) / dk;
    // where the case stayed solvable, when a step found no answer
    const bool ok_minus = k.minus.status == "solved", ok_plus = k.plus.status == "solved";
    if (!ok_minus || !ok_plus) {
      std::string lo = ok_minus ? values_text(k.minus.key_value) : values_text(it.nominal);
      std::string hi = ok_plus ? values_text(k.plus.key_value) : values_text(it.nominal);
      k.range = "answered from " + lo + " to " + hi + "; ";
      if (!ok_minus)
        k.range += "not at " + values_text(k.minus.key_value) + " (" + k.minus.status + ")";
      if (!ok_minus && !ok_plus) k.range += ", ";
      if (!ok_plus)
        k.range += "not at " + values_text(k.plus.key_value) + " (" + k.plus.status + ")";
    }
    r.keys.push_back(std::move(k));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace armstudy::app
