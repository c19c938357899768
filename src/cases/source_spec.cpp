// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/source_spec.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <regex>

#include "cases/yaml_reader.hpp"

namespace armstudy::cases {

double printed_precision(const std::string& text) {
  std::string mantissa = text;
  int exponent = 0;
  if (const size_t e = text.find_first_of("eE"); e != std::string::npos) {
    mantissa = text.substr(0, e);
    try {
      exponent = std::stoi(text.substr(e + 1));
    } catch (...) {
      exponent = 0;
    }
  }
  const size_t dot = mantissa.find('.');
  int decimals = 0;
  if (dot != std::string::npos)
    decimals = static_cast<int>(std::count_if(mantissa.begin() + static_cast<long>(dot) + 1,
                                              mantissa.end(),
                                              [](unsigned char c) { return std::isdigit(c); }));
  return 0.5 * std::pow(10.0, exponent - decimals);
}

namespace {

// a value path: dotted keys, [N] or [k=v,...] selectors, or key:NAME
bool valid_path(const std::string& p) {
  static const std::regex key_figure("key:[^\\s]+");
  static const std::regex dotted(
      "[A-Za-z_][A-Za-z0-9_]*(\\[[^\\]]+\\])*(\\.[A-Za-z_][A-Za-z0-9_]*(\\[[^\\]]+\\])*)*");
  return std::regex_match(p, key_figure) || std::regex_match(p, dotted);
}

std::optional<std::string> path_key(Map& m, std::string_view key) {
  auto p = m.string(key);
  if (p && !valid_path(*p)) {
    m.error(key, "'" + std::string(key) + "' is '" + brief(*p) +
                     "'; expected a results.json value path (dotted keys with [N] or "
                     "[key=value,...] selectors, e.g. placement.evaluations[label=a].energy_J) "
                     "or key:NAME for a key figure");
    return std::nullopt;
  }
  return p;
}

// a claim's key that is a number or a value path, as text ("" when absent or wrong)
std::string number_or_path(Map& c, const char* key, NumberRule rule) {
  const YAML::Node n = c.get(key);
  const std::string text = n.IsScalar() ? n.Scalar() : "";
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  const bool number = !text.empty() && end && *end == '\0' && std::isfinite(v);
  if (number) {
    // read as every case number is: no hexadecimal (0x10), no denormal (1e-309)
    if (c.number(key, rule)) return text;
  } else if (!valid_path(text)) {
    c.error(key, "'" + std::string(key) + "' is '" + brief(text) +
                     "'; expected a number or a value path");
  } else {
    return text;
  }
  return "";
}

SourceClaim read_claim(Map& c) {
  SourceClaim out;
  if (auto a = path_key(c, "a")) out.a = *a;
  if (!c.has("a")) c.error("a", "missing required key 'a' (the value the claim is about)");
  if (auto r = c.choice("relation", {"less", "greater", "same"})) out.relation = *r;
  if (!c.has("relation"))
    c.error("relation", "missing required key 'relation' (less, greater or same)");
  if (c.has("b"))
    out.b = number_or_path(c, "b", NumberRule::any(""));
  else
    c.error("b", "missing required key 'b' (a value path or a number)");
  if (c.has("a_error")) out.a_error = number_or_path(c, "a_error", NumberRule::non_negative(""));
  if (c.has("b_error")) out.b_error = number_or_path(c, "b_error", NumberRule::non_negative(""));
  out.tie_rel = c.number_or("tie_rel", out.tie_rel, NumberRule::non_negative(""));
  out.measure = c.string_or("measure", "");
  out.resolution_rel =
      c.number_or("resolution_rel", out.resolution_rel, NumberRule::non_negative(""));
  c.finish();
  return out;
}

PrintedItem read_item(Map& m) {
  PrintedItem it;
  if (auto w = m.required_string("where")) it.where = *w;
  if (auto s = m.required_string("says")) it.says = *s;
  const YAML::Node v = m.get("value");  // (known even when absent: a misspelling suggests it)
  if (v) {
    it.value = m.number("value", NumberRule::any(""));
    if (it.value && v.IsScalar()) it.tolerance = printed_precision(v.Scalar());
  }
  it.unit = m.string_or("unit", "");
  it.tolerance = m.number_or("tolerance", it.tolerance, NumberRule::non_negative(it.unit));
  it.by_constraint = m.boolean_or("by_constraint", false);
  if (auto p = path_key(m, "at_source_setting")) it.at_source_setting = *p;
  if (auto p = path_key(m, "at_optimum")) it.at_optimum = *p;
  if (auto c = m.map("claim")) it.claim = read_claim(*c);
  it.reason = m.string_or("reason", "");
  if (!it.reason.empty() && !std::regex_match(it.reason, std::regex("[a-z0-9-]+")))
    m.error("reason", "'reason' is '" + brief(it.reason) +
                          "'; expected the anchor of a docs/defects.md entry (a-z, 0-9, '-')");
  it.why = m.string_or("why", "");
  if (it.value && it.claim)
    m.error_here(
        "an entry of 'source.printed' is a figure ('value') or a claim ('claim'), "
        "not both");
  if (!it.value && !it.claim)
    m.error_here("an entry of 'source.printed' needs 'value' (a printed figure) or 'claim'");
  if (it.value && it.at_source_setting.empty() && it.at_optimum.empty())
    m.error_here(
        "a printed figure needs 'at_source_setting' or 'at_optimum' (the "
        "results.json value to compare it with)");
  m.finish();
  return it;
}

}  // namespace

SourceSpec read_source(Map& root) {
  SourceSpec out;
  auto s = root.map("source");
  if (!s) return out;
  if (auto d = s->required_string("document")) out.document = *d;
  std::map<std::string, std::string> reasons;  // anchor -> the reason in one sentence
  if (auto r = s->map("reasons")) {
    for (const auto& kv : r->node()) {
      const std::string key = kv.first.Scalar();
      if (auto why = r->string(key)) reasons[key] = *why;
    }
    r->finish();
  }
  if (auto list = s->seq("printed")) {
    for (size_t i = 0; i < list->size(); ++i) {
      auto m = list->map_at(i);
      if (!m) continue;
      PrintedItem it = read_item(*m);
      if (!it.reason.empty() && it.why.empty()) {
        const auto found = reasons.find(it.reason);
        if (found != reasons.end())
          it.why = found->second;
        else
          m->error("reason", "reason '" + it.reason +
                                 "' has no sentence: give 'why' here or 'source.reasons." +
                                 it.reason + "'");
      }
      out.printed.push_back(std::move(it));
    }
  } else {
    s->error("printed", "missing required key 'printed' (the source's figures and claims)");
  }
  s->finish();
  return out;
}

}  // namespace armstudy::cases
