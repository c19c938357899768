// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/source_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "report/number_format.hpp"

namespace armstudy::report {
namespace {

using nlohmann::json;

// a scalar of results.json as the text a selector compares with
bool scalar_matches(const json& v, const std::string& want) {
  if (v.is_string()) return v.get<std::string>() == want;
  if (v.is_boolean()) return want == (v.get<bool>() ? "true" : "false");
  if (v.is_number()) {
    char* end = nullptr;
    const double w = std::strtod(want.c_str(), &end);
    return end && *end == '\0' && !want.empty() && v.get<double>() == w;
  }
  return false;
}

// applies one selector, "3" or "k=v,k2=v2", to an array
const json* select(const json& arr, const std::string& sel) {
  if (!arr.is_array()) return nullptr;
  if (sel.find('=') == std::string::npos) {
    char* end = nullptr;
    const long k = std::strtol(sel.c_str(), &end, 10);
    if (!end || *end != '\0' || k < 0 || static_cast<size_t>(k) >= arr.size()) return nullptr;
    return &arr[static_cast<size_t>(k)];
  }
  std::vector<std::pair<std::string, std::string>> want;
  size_t at = 0;
  while (at <= sel.size()) {
    const size_t comma = std::min(sel.find(',', at), sel.size());
    const std::string part = sel.substr(at, comma - at);
    const size_t eq = part.find('=');
    if (eq == std::string::npos) return nullptr;
    want.emplace_back(part.substr(0, eq), part.substr(eq + 1));
    at = comma + 1;
  }
  const json* found = nullptr;
  for (const json& e : arr) {
    if (!e.is_object()) continue;
    const bool all = std::all_of(want.begin(), want.end(), [&](const auto& kv) {
      return e.contains(kv.first) && scalar_matches(e[kv.first], kv.second);
    });
    if (!all) continue;
    if (found) return nullptr;  // more than one: the path does not name one value
    found = &e;
  }
  return found;
}

std::optional<double> number_of(const json* v) {
  if (!v || !v->is_number()) return std::nullopt;
  const double x = v->get<double>();
  if (!std::isfinite(x)) return std::nullopt;
  return x;
}

std::string with_unit(double v, const std::string& unit) {
  return format_sig(v, 6) + (unit.empty() ? "" : " " + unit);
}

std::string cell(const std::optional<double>& v, const std::string& unit) {
  return v ? with_unit(*v, unit) : "-";
}

// the element of results.json at a value path (nullptr: none)
const json* node_at(const json& results, const std::string& path) {
  if (path.starts_with("key:")) {
    const std::string name = path.substr(4);
    if (!results.contains("key_figures")) return nullptr;
    for (const json& k : results["key_figures"])
      if (k.is_object() && k.value("name", "") == name && k.contains("value")) return &k["value"];
    return nullptr;
  }
  const json* at = &results;
  size_t i = 0;
  while (i < path.size() && at) {
    size_t end = i;
    while (end < path.size() && path[end] != '.' && path[end] != '[') ++end;
    const std::string key = path.substr(i, end - i);
    if (!key.empty()) at = at->is_object() && at->contains(key) ? &(*at)[key] : nullptr;
    i = end;
    while (at && i < path.size() && path[i] == '[') {
      const size_t close = path.find(']', i);
      if (close == std::string::npos) return nullptr;
      at = select(*at, path.substr(i + 1, close - i - 1));
      i = close + 1;
    }
    if (i < path.size() && path[i] == '.') ++i;
  }
  return at;
}

// a claim's term: a number given as text, the number at a value path, or the list of
// finite numbers there (a point)
struct Term {
  std::optional<double> value;
  std::optional<std::vector<double>> point;
};

Term term_at(const json& results, const std::string& text) {
  Term t;
  if (text.empty()) return t;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end && end != text.c_str() && *end == '\0') {
    t.value = v;
    return t;
  }
  const json* n = node_at(results, text);
  if (n && n->is_array() && !n->empty()) {
    std::vector<double> p;
    for (const json& x : *n) {
      const std::optional<double> c = number_of(&x);
      if (!c) return t;
      p.push_back(*c);
    }
    t.point = std::move(p);
  } else {
    t.value = number_of(n);
  }
  return t;
}

double norm(const std::vector<double>& p) {
  double s = 0;
  for (double x : p) s += x * x;
  return std::sqrt(s);
}

// a claim's values, their errors and its verdict: a tie (equal to tie_rel) is no relation;
// a gap within the methods' resolution or within the sum of a's and b's errors decides
// nothing (a tie); `same` holds when a and b (or their points) are that close
void judge_claim(const cases::SourceClaim& c, const json& results, SourceRowRecord& r) {
  r.kind = "claim";
  r.relation = c.relation;
  const Term a = term_at(results, c.a), b = term_at(results, c.b);
  r.a = a.value;
  r.b = b.value;
  r.a_point = a.point;
  r.b_point = b.point;
  if (!c.a_error.empty()) r.a_error = term_at(results, c.a_error).value;
  if (!c.b_error.empty()) r.b_error = term_at(results, c.b_error).value;
  r.verdict = "no_value";
  if ((!c.a_error.empty() && !r.a_error) || (!c.b_error.empty() && !r.b_error)) return;
  double gap = 0, scale = 0;
  if (a.point && b.point) {
    if (a.point->size() != b.point->size() || c.relation != "same") return;
    std::vector<double> d(a.point->size());
    for (size_t k = 0; k < d.size(); ++k) d[k] = (*a.point)[k] - (*b.point)[k];
    gap = norm(d);
    scale = std::max(norm(*a.point), norm(*b.point));
    r.distance = gap;
  } else if (a.value && b.value) {
    gap = std::abs(*a.value - *b.value);
    scale = std::max(std::abs(*a.value), std::abs(*b.value));
  } else {
    return;
  }
  const double error = r.a_error.value_or(0) + r.b_error.value_or(0);
  const bool tie = gap <= c.tie_rel * scale;
  if (c.relation == "same") {
    r.verdict = tie || gap <= error ? "confirmed" : "contradicted";
    return;
  }
  const bool holds = !tie && (c.relation == "less" ? *a.value < *b.value : *a.value > *b.value);
  const bool unresolved = !tie && gap <= std::max(c.resolution_rel * scale, error);
  r.verdict = unresolved ? "tie" : holds ? "confirmed" : "contradicted";
}

// a claim's term as the table shows it: its value or point, with its error where given
std::string term_cell(const std::optional<double>& v, const std::optional<std::vector<double>>& p,
                      const std::optional<double>& error, const std::string& unit) {
  std::string t = "-";
  if (p) {
    t = "(";
    for (size_t k = 0; k < p->size(); ++k) t += (k ? ", " : "") + format_sig((*p)[k], 6);
    t += ")" + (unit.empty() ? "" : " " + unit);
  } else if (v) {
    t = with_unit(*v, unit);
  }
  if (error && (v || p)) t += " ± " + format_sig(*error, 2);
  return t;
}

// the claim's two cells: its terms, and their gap (a - b, or the points' distance) beside
// the sum of their errors where the case gives them
void claim_cells(const SourceRowRecord& r, std::string& terms, std::string& gap) {
  terms = "a = " + term_cell(r.a, r.a_point, r.a_error, r.unit) +
          ", b = " + term_cell(r.b, r.b_point, r.b_error, r.unit);
  if (r.distance) {
    gap = "distance " + with_unit(*r.distance, r.unit);
  } else if (r.a && r.b) {
    const double scale = std::max(std::abs(*r.a), std::abs(*r.b));
    gap = "a - b = " + format_sig(*r.a - *r.b, 3) +
          (scale > 0 ? " (" + format_sig(100 * (*r.a - *r.b) / scale, 3) + " %)" : "");
  }
  if (!gap.empty() && (r.a_error || r.b_error))
    gap += "; their errors together " +
           format_sig(r.a_error.value_or(0) + r.b_error.value_or(0), 2) +
           (r.unit.empty() ? "" : " " + r.unit);
}

}  // namespace

std::optional<double> value_at(const json& results, const std::string& path) {
  return number_of(node_at(results, path));
}

SourceRecord compare_with_source(const cases::SourceSpec& spec, const json& results) {
  SourceRecord out;
  out.document = spec.document;
  for (const cases::PrintedItem& it : spec.printed) {
    SourceRowRecord r;
    r.where = it.where;
    r.says = it.says;
    r.unit = it.unit;
    r.why = it.why;
    if (!it.reason.empty()) r.reason = it.reason;
    if (it.claim) {
      judge_claim(*it.claim, results, r);
    } else {
      r.kind = "figure";
      r.printed = it.value;
      r.tolerance = it.tolerance;
      if (!it.at_source_setting.empty())
        r.at_source_setting = value_at(results, it.at_source_setting);
      if (!it.at_optimum.empty()) r.at_optimum = value_at(results, it.at_optimum);
      const std::optional<double> ours = r.at_source_setting ? r.at_source_setting : r.at_optimum;
      if (!ours || !r.printed) {
        r.verdict = "no_value";
      } else {
        r.difference = *ours - *r.printed;
        const double slack = 1e-12 * std::max(1.0, std::abs(*r.printed));
        // within a tolerance the study imposes, the value is met by it: no agreement
        const bool within = std::abs(*r.difference) <= it.tolerance + slack;
        r.verdict = !within ? "differs" : it.by_constraint ? "met_by_constraint" : "agrees";
      }
    }
    out.rows.push_back(std::move(r));
  }
  return out;
}

CheckRecord source_explained_check(const SourceRecord& source) {
  int unexplained = 0;
  for (const SourceRowRecord& r : source.rows)
    if ((r.verdict == "differs" || r.verdict == "contradicted" || r.verdict == "tie" ||
         r.verdict == "no_value") &&
        (!r.reason || r.why.empty()))
      ++unexplained;
  CheckRecord c;
  c.name = "source.differences_explained";
  c.description = "every figure of " + source.document +
                  " armstudy differs from, every claim it contradicts, has its reason "
                  "(a docs/defects.md entry) on page 2";
  c.value = unexplained;
  c.tolerance = 0;
  c.passed = unexplained == 0;
  return c;
}

std::string source_summary(const SourceRecord& source) {
  int figures = 0, agrees = 0, met = 0, claims = 0, confirmed = 0, ties = 0, none = 0;
  for (const SourceRowRecord& r : source.rows) {
    none += r.verdict == "no_value";
    if (r.kind == "figure") {
      ++figures;
      agrees += r.verdict == "agrees";
      met += r.verdict == "met_by_constraint";
    } else {
      ++claims;
      confirmed += r.verdict == "confirmed";
      ties += r.verdict == "tie";
    }
  }
  std::string s = source.document + ": ";
  if (figures)
    s += std::to_string(figures) + (figures == 1 ? " printed figure, " : " printed figures, ") +
         std::to_string(agrees) + " agree, " +
         (met ? std::to_string(met) + " met by a constraint, " : std::string()) +
         std::to_string(figures - agrees - met) + " differ";
  if (figures && claims) s += "; ";
  if (claims)
    s += std::to_string(claims) + (claims == 1 ? " claim, " : " claims, ") +
         std::to_string(confirmed) + " confirmed, " +
         (ties ? std::to_string(ties) + " a tie at the methods' resolution, " : std::string()) +
         std::to_string(claims - confirmed - ties) + " contradicted";
  if (none) s += " (" + std::to_string(none) + " with no armstudy value)";
  return s + ". Reasons: page 2.";
}

Section source_section(const SourceRecord& source) {
  Section s;
  s.id = "source";
  s.heading = "Source and armstudy";
  s.paragraph(
      "What " + source.document +
      " prints for this case, beside armstudy's value under the source's own setting (the "
      "printed placement, grid or parameters) and at armstudy's own optimum. A printed figure "
      "agrees when armstudy's value rounds to it (within half a unit of its last printed "
      "digit); a figure the study itself constrains (its tolerance is the constraint) is "
      "met by constraint, not an agreement; a claim is confirmed when armstudy's values stand in "
      "the relation it states "
      "(a tie, equal to 1e-6, is no relation; within the resolution of the methods the values "
      "come from, where the source names them, or within the sum of the two values' stated "
      "errors (±), they decide nothing: a tie); a claim that two values or two locations are "
      "the same is confirmed when they differ, or lie apart, by no more than the sum of their "
      "errors, and contradicted otherwise. A difference is "
      "armstudy's value at the "
      "source's setting minus the printed one, or at armstudy's optimum where the setting has "
      "no value (an unreachable line), and says which. Every difference names its reason; each is "
      "derived in docs/defects.md under the anchor given.");
  Table t;
  t.caption = "The source's figures and claims for this case, and armstudy's.";
  t.header = {"Where",
              "The source prints",
              "armstudy at the source's setting",
              "armstudy at its optimum",
              "Difference (armstudy − printed)",
              "Verdict",
              "Why (docs/defects.md)"};
  for (const SourceRowRecord& r : source.rows) {
    std::string at_setting, at_opt, diff;
    if (r.kind == "claim") {
      claim_cells(r, at_setting, diff);
      at_opt = "-";
    } else {
      at_setting = cell(r.at_source_setting, r.unit);
      at_opt = cell(r.at_optimum, r.unit);
      if (r.difference) {
        diff = format_sig(*r.difference, 4) + (r.unit.empty() ? "" : " " + r.unit);
        if (r.printed && *r.printed != 0)
          diff += " (" + format_sig(100 * *r.difference / std::abs(*r.printed), 3) + " %)";
        // its baseline: the source's setting where armstudy has a value there
        diff += r.at_source_setting ? ", at the source's setting" : ", at armstudy's optimum";
      }
    }
    std::string why = r.why;
    if (r.reason) why += (why.empty() ? "" : " ") + std::string("(#") + *r.reason + ")";
    std::string says = r.says;
    if (r.kind == "figure" && r.printed) says += " [" + with_unit(*r.printed, r.unit) + "]";
    t.rows.push_back({r.where, says, at_setting, at_opt, diff.empty() ? "-" : diff,
                      r.verdict == "no_value"            ? "no value"
                      : r.verdict == "met_by_constraint" ? "met by constraint"
                                                         : r.verdict,
                      why.empty() ? "-" : why});
  }
  s.table(std::move(t));
  return s;
}

}  // namespace armstudy::report
