// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/sensitivity_spec.hpp"

#include <cmath>
#include <regex>
#include <string>
#include <unordered_map>
#include <vector>

#include "cases/yaml_reader.hpp"

namespace armstudy::cases {
namespace {

// the node at `path` (dotted keys, [N] 1-based into a list) below `root`; an undefined
// node when the file does not write it
YAML::Node node_at(const YAML::Node& root, const std::string& path) {
  static const std::regex segment("([A-Za-z_][A-Za-z0-9_]*)(?:\\[([0-9]+)\\])?");
  YAML::Node cur = root;
  size_t at = 0;
  while (at <= path.size()) {
    const size_t dot = path.find('.', at);
    const std::string part =
        path.substr(at, dot == std::string::npos ? std::string::npos : dot - at);
    std::smatch m;
    if (!std::regex_match(part, m, segment) || !cur.IsMap())
      return YAML::Node(YAML::NodeType::Undefined);
    YAML::Node next = cur[m[1].str()];
    if (!next) return YAML::Node(YAML::NodeType::Undefined);
    if (m[2].matched) {
      const size_t i = std::stoul(m[2].str());
      if (!next.IsSequence() || i < 1 || i > next.size())
        return YAML::Node(YAML::NodeType::Undefined);
      next.reset(next[i - 1]);  // (`next = ...` would write the entry over the list)
    }
    cur.reset(next);
    if (dot == std::string::npos) return cur;
    at = dot + 1;
  }
  return YAML::Node(YAML::NodeType::Undefined);
}

// a finite number written as a plain scalar
std::optional<double> number_of(const YAML::Node& n) {
  if (!n.IsScalar()) return std::nullopt;
  const std::string& t = n.Scalar();
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (t.empty() || !end || *end != '\0' || !std::isfinite(v)) return std::nullopt;
  return v;
}

// what the key must not vary: the parts every case has and this one
bool reserved(const std::string& key) {
  for (const char* r :
       {"study", "name", "description", "expect", "render", "sweep", "source", "sensitivity"})
    if (key == r || key.rfind(std::string(r) + ".", 0) == 0 ||
        key.rfind(std::string(r) + "[", 0) == 0)
      return true;
  return false;
}

// resolves the key against the file and fills the nominal value(s); "" or the complaint
std::string resolve(const YAML::Node& root, SensitivityItem& it) {
  if (reserved(it.key))
    return "'" + brief(it.key) +
           "' is not a parameter of the study; expected a numeric key "
           "of the study's part (e.g. throwing.constraints.friction_coefficient)";
  const YAML::Node n = node_at(root, it.key);
  if (!n)
    return "'" + brief(it.key) +
           "' names no key written in the case file; expected a dotted path to a number the "
           "file writes (a default the file leaves out: write the key with its value first)";
  if (n.IsSequence()) {
    for (size_t i = 0; i < n.size(); ++i) {
      const auto v = number_of(n[i]);
      if (!v) return "'" + brief(it.key) + "' is a list that holds more than numbers";
      it.nominal.push_back(*v);
    }
    if (it.nominal.empty()) return "'" + brief(it.key) + "' is an empty list";
    it.list = true;
    return "";
  }
  const auto v = number_of(n);
  if (!v)
    return "'" + brief(it.key) + "' is " +
           (n.IsScalar() ? "'" + brief(n.Scalar()) + "'" : std::string("not a number")) +
           " in the case file; expected a key whose value is a number (or a list of numbers)";
  it.nominal.push_back(*v);
  return "";
}

}  // namespace

// (over 60 lines, kept whole: one entry's keys read in the order of their errors (file:line:col))
SensitivitySpec read_sensitivity(Map& root) {
  SensitivitySpec out;
  if (!root.has("sensitivity")) return out;
  auto list = root.seq("sensitivity");
  if (!list) return out;
  if (list->size() > kMaxSensitivityKeys)  // said once; every entry is still read (linear)
    root.error("sensitivity", "'sensitivity' has " + std::to_string(list->size()) +
                                  " entries; expected at most " +
                                  std::to_string(kMaxSensitivityKeys) +
                                  " (each key is two re-solves of the case)");
  struct Repeats {
    YAML::Mark first;
    int count = 0;
    YAML::Mark second{};
  };
  std::unordered_map<std::string, Repeats> seen;
  std::vector<std::string> repeated;  // in the order of their second entries
  for (size_t i = 0; i < list->size(); ++i) {
    const YAML::Node e = list->at(i);
    SensitivityItem it;
    if (e.IsScalar()) {  // a key alone: the default step
      it.key = e.Scalar();
      if (const std::string bad = resolve(root.node(), it); !bad.empty()) {
        list->diag().error(e.Mark(), bad);
        continue;
      }
    } else {
      auto m = list->map_at(i);
      if (!m) continue;
      const auto key = m->required_string("key");
      const auto rel =
          m->has("relative") ? m->number("relative", NumberRule::positive("")) : std::nullopt;
      const auto abs =
          m->has("absolute") ? m->number("absolute", NumberRule::positive("")) : std::nullopt;
      it.why = m->string_or("why", "");
      if (m->has("relative") && m->has("absolute"))
        m->error("absolute",
                 "an entry of 'sensitivity' has one step, 'relative' or "
                 "'absolute', not both");
      m->finish();
      if (!key) continue;
      it.key = *key;
      if (const std::string bad = resolve(root.node(), it); !bad.empty()) {
        m->error("key", bad);
        continue;
      }
      if (abs) {
        it.relative = false;
        it.step = *abs;
        if (it.list)
          m->error("absolute", "'" + brief(it.key) +
                                   "' is a list, varied as a whole by a relative step; "
                                   "expected 'relative'");
      } else if (rel) {
        it.step = rel.value_or(kDefaultRelativeStep);
        if (it.step >= 1)
          m->error("relative", "'relative' is " + format_number(it.step) +
                                   "; expected a share below 1 (0.1 is +-10 %)");
      }
      if (it.relative) {
        bool zero = false;
        for (double v : it.nominal) zero |= v == 0;
        if (zero)
          m->error("key", "'" + brief(it.key) +
                              "' is 0 in the case file, which a relative step cannot vary; "
                              "expected 'absolute' with a step in the key's unit");
      }
    }
    if (it.relative && !e.IsMap()) {
      bool zero = false;
      for (double v : it.nominal) zero |= v == 0;
      if (zero) {
        list->diag().error(e.Mark(), "'" + brief(it.key) +
                                         "' is 0 in the case file, which the default relative "
                                         "step cannot vary; expected {key: ..., absolute: STEP}");
        continue;
      }
    }
    // a repeat is said once per key, at its second entry (a hash of the keys: linear)
    const auto [first, fresh] = seen.try_emplace(it.key, Repeats{e.Mark(), 1});
    if (!fresh && ++first->second.count == 2) {
      first->second.second = e.Mark();
      repeated.push_back(it.key);
    }
    out.items.push_back(std::move(it));
  }
  for (const std::string& key : repeated) {
    const Repeats& r = seen.at(key);
    list->diag().error(
        r.second, "'" + brief(key) + "' is listed " +
                      (r.count == 2 ? std::string("twice") : std::to_string(r.count) + " times") +
                      " in 'sensitivity'; expected each key once");
  }
  return out;
}

}  // namespace armstudy::cases
