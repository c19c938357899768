// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/yaml_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "cases/yaml_source.hpp"

namespace armstudy::cases {
namespace {

std::string describe_kind(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Map: return "a mapping";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Null: return "nothing";
    case YAML::NodeType::Scalar: return "'" + brief(n.Scalar()) + "'";
    default: return "nothing";
  }
}

size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

}  // namespace

std::string format_number(double v) {
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os << v;
  return os.str();
}

std::string exact_number(double v) {
  if (std::isfinite(v) && v == std::floor(v) && std::abs(v) < 1e15) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
  }
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);  // shortest round trip, C locale
  return std::string(buf, r.ptr);
}

void Diagnostics::error(const YAML::Mark& mark, std::string message) {
  if (errors_.size() >= kMaxErrors) {
    ++dropped_;
    return;
  }
  CaseError e;
  e.path = path_;
  if (!mark.is_null() && mark.line >= 0) {
    e.line = mark.line + 1;
    e.column = mark.column + 1;
  }
  e.message = std::move(message);
  errors_.push_back(std::move(e));
}

void Diagnostics::throw_if_any() const {
  if (errors_.empty()) return;
  if (dropped_ == 0) throw CaseErrors(errors_);
  std::vector<CaseError> all = errors_;
  CaseError more;
  more.path = path_;
  more.message = "... and " + std::to_string(dropped_) + " more error(s) (only the first " +
                 std::to_string(kMaxErrors) + " are shown)";
  all.push_back(std::move(more));
  throw CaseErrors(std::move(all));
}

std::string violation(double v, const NumberRule& rule) {
  const std::string u = rule.unit.empty() ? "" : " " + rule.unit;
  if (rule.sign == NumberRule::Sign::kPositive && !(v > 0)) return "should be > 0" + u;
  if (rule.sign == NumberRule::Sign::kNonNegative && !(v >= 0)) return "should be >= 0" + u;
  if (rule.or_zero && v == 0) return "";
  if (rule.or_zero && rule.min && rule.max && (v < *rule.min || v > *rule.max))
    return "should be 0 or in [" + exact_number(*rule.min) + ", " + exact_number(*rule.max) + "]" +
           u;
  if (rule.min && v < *rule.min) {
    if (rule.max)
      return "should be in [" + exact_number(*rule.min) + ", " + exact_number(*rule.max) + "]" + u;
    return "should be >= " + exact_number(*rule.min) + u;
  }
  if (rule.max && v > *rule.max) {
    if (rule.min)
      return "should be in [" + exact_number(*rule.min) + ", " + exact_number(*rule.max) + "]" + u;
    return "should be <= " + exact_number(*rule.max) + u;
  }
  return "";
}

namespace {
// why text yaml-cpp would not convert is no number we can use: it overflows or underflows
// a double ("1e400", "1e-400"), or "" if it is just not a number
std::string out_of_range(const std::string& s) {
  const char* begin = s.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if (end == begin || *end != '\0' || errno != ERANGE) return "";
  if (std::isinf(v)) return "overflows a double (its largest is 1.8e308)";
  return "underflows a double (too close to 0 to be represented)";
}
}  // namespace

// (over 60 lines, kept whole: the checks of one scalar in the order a reader meets them,
// each with its own message)
std::optional<double> read_number(const YAML::Node& node, Diagnostics& diag, std::string_view what,
                                  const NumberRule& rule) {
  const std::string name(what);
  if (!node.IsScalar()) {
    diag.error(node.Mark(), name + " is " + describe_kind(node) + "; expected a number");
    return std::nullopt;
  }
  double v = 0;
  const std::string& s = node.Scalar();
  // yaml-cpp reads "1.0" and !!str 0.5 as numbers: a quoted or text-tagged scalar is text,
  // and text where a number belongs is refused (!!float and !!int are numbers)
  const std::string& tag = node.Tag();
  if (tag == "!") {
    diag.error(node.Mark(), name + " is the quoted text '" + brief(s) +
                                "'; expected a number (written without quotes)");
    return std::nullopt;
  }
  if (tag != "?" && tag != "tag:yaml.org,2002:float" && tag != "tag:yaml.org,2002:int") {
    const std::string shown = tag.rfind("tag:yaml.org,2002:", 0) == 0 ? "!!" + tag.substr(18) : tag;
    diag.error(node.Mark(), name + " is '" + brief(s) + "' tagged " + brief(shown) +
                                "; expected a number (untagged, or tagged !!float or !!int)");
    return std::nullopt;
  }
  // yaml-cpp converts .nan/.inf; anything else that is not a number fails
  try {
    v = node.as<double>();
  } catch (const YAML::Exception&) {
    const std::string range = out_of_range(s);
    if (!range.empty()) {
      diag.error(node.Mark(), name + " is " + brief(s) + ", which " + range +
                                  "; expected a magnitude in [" + format_number(kMinMagnitude) +
                                  ", " + format_number(kMaxMagnitude) + "] or 0");
    } else {
      diag.error(node.Mark(), name + " is '" + brief(s) + "'; expected a number");
    }
    return std::nullopt;
  }
  if (!std::isfinite(v)) {
    diag.error(node.Mark(), name + " is " + brief(s) + "; expected a finite number");
    return std::nullopt;
  }
  if (std::fpclassify(v) == FP_SUBNORMAL || (v == 0 && !out_of_range(s).empty())) {
    diag.error(
        node.Mark(),
        name + " is " + brief(s) +
            (v == 0 ? ", which underflows a double to 0"
                    : ", a denormal number (below 2.2e-308 in magnitude, with lost precision)") +
            "; expected 0 or a magnitude of at least " + format_number(kMinMagnitude));
    return std::nullopt;
  }
  if (v != 0 && (std::abs(v) > kMaxMagnitude || std::abs(v) < kMinMagnitude)) {
    diag.error(node.Mark(), name + " is " + format_number(v) +
                                ", outside the magnitudes armstudy "
                                "computes with; expected 0 or a magnitude in [" +
                                format_number(kMinMagnitude) + ", " + format_number(kMaxMagnitude) +
                                "]");
    return std::nullopt;
  }
  const std::string bad = violation(v, rule);
  if (!bad.empty()) {
    diag.error(node.Mark(), name + " is " + exact_number(v) + "; " + bad);
    return std::nullopt;
  }
  return v;
}

// ----------------------------------------------------------------------------- Map

Map::Map(const YAML::Node& node, Diagnostics& diag, std::string context)
    : node_(node), diag_(&diag), context_(std::move(context)) {
  if (!node.IsMap()) {
    diag.error(node.Mark(), (context_.empty() ? std::string("the file") : "'" + context_ + "'") +
                                " is " + describe_kind(node) + "; expected a mapping of keys");
    return;
  }
  valid_ = true;
  // duplicate keys: yaml-cpp keeps every pair but operator[] returns the first
  std::vector<YAML::Node> merges;
  for (const auto& kv : node) {
    if (!kv.first.IsScalar()) {
      diag.error(kv.first.Mark(),
                 "a key of " + (context_.empty() ? std::string("the file") : "'" + context_ + "'") +
                     " is not a plain word; expected a key name");
      continue;
    }
    const std::string k = kv.first.Scalar();
    if (k == "<<" && kv.first.Tag() == "?") {  // a plain <<: the merge key
      merges.push_back(kv.second);
      continue;
    }
    if (index_.count(k)) {
      diag.error(kv.first.Mark(),
                 "duplicate key '" + brief(path_of(k)) + "'; expected each key once");
    } else {
      index_.emplace(k, entries_.size());
      entries_.push_back({k, kv.first, kv.second, false});
    }
  }
  for (const YAML::Node& m : merges) merge_from(m, 0, false);
}

void Map::merge_from(const YAML::Node& source, int depth, bool in_list) {
  const std::string where = "the merge key '" + path_of("<<") + "'";
  if (depth > kMaxDepth) {
    diag_->error(source.Mark(),
                 where + " nests merges too deeply; expected at most " + std::to_string(kMaxDepth));
    return;
  }
  if (source.IsSequence()) {
    if (in_list) {
      diag_->error(source.Mark(),
                   where + " holds a list inside a list; expected a mapping or a list of mappings");
      return;
    }
    for (const auto& m : source) merge_from(m, depth + 1, true);
    return;
  }
  if (!source.IsMap()) {
    diag_->error(source.Mark(), where + " is " + describe_kind(source) +
                                    "; expected a mapping (e.g. *defaults) or a list of mappings");
    return;
  }
  // a merged mapping's own merge keys count too, after its explicit keys
  std::vector<YAML::Node> inner;
  for (const auto& kv : source) {
    if (!kv.first.IsScalar()) continue;  // refused where the mapping itself is read
    const std::string k = kv.first.Scalar();
    if (k == "<<" && kv.first.Tag() == "?") {
      inner.push_back(kv.second);
      continue;
    }
    if (index_.count(k)) continue;  // the mapping's own key, or an earlier merge, wins
    index_.emplace(k, entries_.size());
    entries_.push_back({k, kv.first, kv.second, true});
  }
  for (const YAML::Node& m : inner) merge_from(m, depth + 1, false);
}

const Map::Entry* Map::find(std::string_view key) const {
  if (!valid_) return nullptr;
  const auto it = index_.find(std::string(key));
  return it == index_.end() ? nullptr : &entries_[it->second];
}

std::string Map::path_of(std::string_view key) const {
  return context_.empty() ? std::string(key) : context_ + "." + std::string(key);
}

// ----------------------------------------------------------------------------- catalog

std::string KeyCatalog::pattern(const std::string& path) {
  std::string out;
  for (size_t i = 0; i < path.size(); ++i) {
    out += path[i];
    if (path[i] != '[') continue;
    size_t j = i + 1;
    while (j < path.size() && std::isdigit(static_cast<unsigned char>(path[j]))) ++j;
    if (j > i + 1 && j < path.size() && path[j] == ']') i = j - 1;
  }
  return out;
}

void KeyCatalog::record(KeyInfo k) {
  for (KeyInfo& have : keys) {
    if (have.path != k.path) continue;
    if (have.kind == "value" && k.kind != "value") {
      have.kind = k.kind;
      have.rule = k.rule;
      have.choices = k.choices;
      have.count = k.count;
    }
    if (!have.default_text) have.default_text = k.default_text;
    have.required = have.required || k.required;
    return;
  }
  keys.push_back(std::move(k));
}

void Map::mark_known(std::string_view key) const {
  std::string k(key);
  if (known_set_.insert(k).second) known_.push_back(std::move(k));
}

bool Map::catalog_key(std::string_view key, KeyInfo k) const {
  KeyCatalog& c = *diag_->catalog();
  k.path = KeyCatalog::pattern(path_of(key));
  const bool present = !c.absent.count(k.path);
  c.record(std::move(k));
  return present;
}

bool Map::has(std::string_view key) const {
  mark_known(key);  // an alternative the loader checks for is a key a message may suggest
  if (diag_->catalog()) {
    diag_->catalog()->asked.insert(KeyCatalog::pattern(path_of(key)));
    return catalog_key(key, {});
  }
  return find(key) != nullptr;
}

YAML::Node Map::get(std::string_view key) {
  mark_known(key);
  if (diag_->catalog()) {
    catalog_key(key, {});
    return YAML::Node(YAML::NodeType::Undefined);
  }
  if (const Entry* e = find(key)) return e->value;
  return YAML::Node(YAML::NodeType::Undefined);
}

namespace {
// what a catalog pass records of a key (its path is the Map's to make)
KeyInfo key_info(const char* kind, NumberRule rule = {},
                 std::optional<std::string> default_text = std::nullopt, bool required = false) {
  KeyInfo k;
  k.kind = kind;
  k.rule = std::move(rule);
  k.default_text = std::move(default_text);
  k.required = required;
  return k;
}

// a default list as YAML flow text ("[1, 2]"); none when it has no items
std::optional<std::string> flow_list(const std::vector<std::string>& items) {
  if (items.empty()) return std::nullopt;
  std::string t;
  for (const std::string& i : items) t += (t.empty() ? "[" : ", ") + i;
  return t + "]";
}

// a value a catalog pass gives for a required number: inside its rule, so that the loader
// goes on as for a file that has it
double plausible(const NumberRule& rule) {
  if (rule.min && rule.max) return (*rule.min + *rule.max) / 2;
  if (rule.min) return *rule.min + 1;
  if (rule.max) return *rule.max - 1;
  return 1.0;
}
}  // namespace

std::optional<double> Map::number(std::string_view key, const NumberRule& rule) {
  if (diag_->catalog()) {
    catalog_key(key, key_info("number", rule));
    mark_known(key);
    return std::nullopt;
  }
  const YAML::Node n = get(key);
  if (!n.IsDefined()) return std::nullopt;
  return read_number(n, *diag_, "'" + path_of(key) + "'", rule);
}

double Map::number_or(std::string_view key, double fallback, const NumberRule& rule) {
  if (diag_->catalog()) {
    catalog_key(key, key_info("number", rule, format_number(fallback)));
    mark_known(key);
    return fallback;
  }
  const bool present = has(key);
  const auto v = number(key, rule);
  if (v) return *v;
  return present ? std::numeric_limits<double>::quiet_NaN() : fallback;
}

double Map::required_number(std::string_view key, const NumberRule& rule) {
  if (diag_->catalog()) {
    mark_known(key);
    return catalog_key(key, key_info("number", rule, std::nullopt, true))
               ? plausible(rule)
               : std::numeric_limits<double>::quiet_NaN();
  }
  if (!has(key)) {
    get(key);
    error_here("missing required key '" + path_of(key) + "'; expected a number" +
               (rule.unit.empty() ? "" : " in " + rule.unit));
    return std::numeric_limits<double>::quiet_NaN();
  }
  const auto v = number(key, rule);
  return v ? *v : std::numeric_limits<double>::quiet_NaN();
}

std::optional<int> Map::integer(std::string_view key, int min, int max) {
  if (diag_->catalog()) {
    catalog_key(key, key_info("integer", NumberRule::range(min, max, "")));
    mark_known(key);
    return std::nullopt;
  }
  const YAML::Node n = get(key);
  if (!n.IsDefined()) return std::nullopt;
  const auto v = read_number(n, *diag_, "'" + path_of(key) + "'", NumberRule::range(min, max, ""));
  if (!v) return std::nullopt;
  if (*v != std::floor(*v)) {
    diag_->error(n.Mark(),
                 "'" + path_of(key) + "' is " + brief(n.Scalar()) + "; expected a whole number");
    return std::nullopt;
  }
  return static_cast<int>(*v);
}

int Map::integer_or(std::string_view key, int fallback, int min, int max) {
  if (diag_->catalog())
    catalog_key(key,
                key_info("integer", NumberRule::range(min, max, ""), std::to_string(fallback)));
  const auto v = integer(key, min, max);
  return v ? *v : fallback;
}

std::optional<std::string> Map::string(std::string_view key) {
  if (diag_->catalog()) {
    catalog_key(key, key_info("string"));
    mark_known(key);
    return std::nullopt;
  }
  const YAML::Node n = get(key);
  if (!n.IsDefined()) return std::nullopt;
  if (!n.IsScalar()) {
    diag_->error(n.Mark(), "'" + path_of(key) + "' is " + describe_kind(n) + "; expected a string");
    return std::nullopt;
  }
  return n.Scalar();
}

std::string Map::string_or(std::string_view key, std::string fallback) {
  if (diag_->catalog() && !fallback.empty()) catalog_key(key, key_info("string", {}, fallback));
  const auto v = string(key);
  return v ? *v : fallback;
}

std::optional<std::string> Map::required_string(std::string_view key) {
  if (diag_->catalog()) {
    catalog_key(key, key_info("string", {}, std::nullopt, true));
    mark_known(key);
    return std::nullopt;
  }
  if (!has(key)) {
    get(key);
    error_here("missing required key '" + path_of(key) + "'; expected a string");
    return std::nullopt;
  }
  return string(key);
}

std::optional<std::string> Map::choice(std::string_view key,
                                       const std::vector<std::string>& allowed) {
  if (diag_->catalog()) {
    KeyInfo k = key_info("choice");
    k.choices = allowed;
    catalog_key(key, std::move(k));
    mark_known(key);
    return std::nullopt;
  }
  const auto v = string(key);
  if (!v) return std::nullopt;
  if (std::find(allowed.begin(), allowed.end(), *v) != allowed.end()) return v;
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  std::string msg = "'" + path_of(key) + "' is '" + brief(*v) + "'; expected one of: " + list;
  if (const auto c = closest(*v, allowed)) msg += " (did you mean '" + *c + "'?)";
  error(key, msg);
  return std::nullopt;
}

std::optional<bool> Map::boolean(std::string_view key) {
  if (diag_->catalog()) {
    catalog_key(key, key_info("boolean"));
    mark_known(key);
    return std::nullopt;
  }
  const YAML::Node n = get(key);
  if (!n.IsDefined()) return std::nullopt;
  if (n.IsScalar()) {
    const std::string& s = n.Scalar();
    if (s == "true") return true;
    if (s == "false") return false;
  }
  diag_->error(n.Mark(),
               "'" + path_of(key) + "' is " + describe_kind(n) + "; expected true or false");
  return std::nullopt;
}

bool Map::boolean_or(std::string_view key, bool fallback) {
  if (diag_->catalog()) catalog_key(key, key_info("boolean", {}, fallback ? "true" : "false"));
  const auto v = boolean(key);
  return v ? *v : fallback;
}

std::optional<std::vector<double>> Map::numbers(std::string_view key, const NumberRule& rule,
                                                size_t size,
                                                const std::vector<double>& default_value) {
  if (diag_->catalog()) {
    std::vector<std::string> items;
    for (const double v : default_value) items.push_back(format_number(v));
    KeyInfo k = key_info("numbers", rule, flow_list(items));
    k.count = size;
    catalog_key(key, std::move(k));
    mark_known(key);
    return std::nullopt;
  }
  const YAML::Node n = get(key);
  if (!n.IsDefined()) return std::nullopt;
  if (!n.IsSequence() || n.size() == 0 || (size != 0 && n.size() != size)) {
    diag_->error(n.Mark(), "'" + path_of(key) + "' is " + describe_kind(n) +
                               "; expected a list of " +
                               (size ? std::to_string(size) + " numbers" : "numbers"));
    return std::nullopt;
  }
  std::vector<double> out;
  bool ok = true;
  for (size_t i = 0; i < n.size(); ++i) {
    const auto v =
        read_number(n[i], *diag_, "'" + path_of(key) + "[" + std::to_string(i + 1) + "]'", rule);
    if (v)
      out.push_back(*v);
    else
      ok = false;
  }
  if (!ok) return std::nullopt;
  return out;
}

std::optional<Map> Map::map(std::string_view key) {
  if (diag_->catalog()) {
    mark_known(key);
    if (!catalog_key(key, key_info("mapping"))) return std::nullopt;
    return Map(YAML::Node(YAML::NodeType::Map), *diag_, path_of(key));
  }
  const YAML::Node n = get(key);
  if (!n.IsDefined()) return std::nullopt;
  if (!n.IsMap()) {
    diag_->error(n.Mark(),
                 "'" + path_of(key) + "' is " + describe_kind(n) + "; expected a mapping of keys");
    return std::nullopt;
  }
  return Map(n, *diag_, path_of(key));
}

std::optional<Seq> Map::seq(std::string_view key, const std::vector<std::string>& default_items) {
  if (diag_->catalog()) {
    mark_known(key);
    if (!catalog_key(key, key_info("list", {}, flow_list(default_items)))) return std::nullopt;
    // two items: a list of links is then a 2-link arm, which every study takes
    YAML::Node two(YAML::NodeType::Sequence);
    two.push_back(YAML::Node(YAML::NodeType::Map));
    two.push_back(YAML::Node(YAML::NodeType::Map));
    return Seq(two, *diag_, path_of(key));
  }
  const YAML::Node n = get(key);
  if (!n.IsDefined()) return std::nullopt;
  if (!n.IsSequence()) {
    diag_->error(n.Mark(), "'" + path_of(key) + "' is " + describe_kind(n) + "; expected a list");
    return std::nullopt;
  }
  return Seq(n, *diag_, path_of(key));
}

void Map::error(std::string_view key, std::string message) {
  if (const Entry* e = find(key)) {
    diag_->error(e->value.Mark(), std::move(message));
    return;
  }
  diag_->error(node_.Mark(), std::move(message));
}

void Map::error_here(std::string message) { diag_->error(node_.Mark(), std::move(message)); }

void Map::finish() {
  if (!valid_) return;
  std::string expected;  // the list of known keys, made once
  for (const Entry& e : entries_) {
    if (known_set_.count(e.key)) continue;
    std::string msg = "unknown key '" + brief(path_of(e.key)) + "'" +
                      (e.merged ? " (from the merge key '<<')" : "");
    if (const auto c = closest(e.key, known_)) {
      msg += "; did you mean '" + *c + "'?";
    } else {
      if (expected.empty()) {
        std::vector<std::string> sorted = known_;
        std::sort(sorted.begin(), sorted.end());
        for (size_t i = 0; i < sorted.size(); ++i) expected += (i ? ", " : "") + sorted[i];
      }
      msg += "; expected one of: " + expected;
    }
    diag_->error(e.key_node.Mark(), msg);
  }
}

// ----------------------------------------------------------------------------- Seq

Seq::Seq(const YAML::Node& node, Diagnostics& diag, std::string context)
    : node_(node), diag_(&diag), context_(std::move(context)) {}

std::string Seq::path_at(size_t i) const { return context_ + "[" + std::to_string(i + 1) + "]"; }

std::optional<Map> Seq::map_at(size_t i) const {
  const YAML::Node n = node_[i];
  if (!n.IsMap()) {
    diag_->error(n.Mark(),
                 "'" + path_at(i) + "' is " + describe_kind(n) + "; expected a mapping of keys");
    return std::nullopt;
  }
  return Map(n, *diag_, path_at(i));
}

// ----------------------------------------------------------------------------- files

std::optional<YAML::Node> parse_file(const std::string& path, Diagnostics& diag, std::string* text,
                                     const std::string& expected) {
  std::string bytes;
  if (!read_regular_file(path, diag, &bytes)) return std::nullopt;
  auto root = parse_text(bytes, diag, expected);
  if (text) *text = std::move(bytes);
  return root;
}

std::optional<YAML::Node> parse_text(const std::string& text, Diagnostics& diag,
                                     const std::string& expected) {
  // old Mac line breaks (a CR alone): yaml-cpp reads a file of them as one line, often a
  // comment, so "the file is empty"; as LF, one for one, the lines and columns stay
  std::string bytes = text;
  for (size_t i = 0; i < bytes.size(); ++i)
    if (bytes[i] == '\r' && (i + 1 == bytes.size() || bytes[i + 1] != '\n')) bytes[i] = '\n';
  if (!check_yaml_source(bytes, diag)) return std::nullopt;
  YAML::Node root;
  try {
    root = YAML::Load(bytes);
  } catch (const YAML::ParserException& e) {
    diag.error(e.mark, "not valid YAML (" + e.msg + "); expected a YAML mapping");
    return std::nullopt;
  }
  if (root.IsNull() || !root.IsDefined()) {
    diag.error(YAML::Mark::null_mark(), "the file is empty; expected " + expected);
    return std::nullopt;
  }
  if (!root.IsMap()) {
    diag.error(root.Mark(), "the file holds " + describe_kind(root) + "; expected " + expected);
    return std::nullopt;
  }
  return root;
}

std::optional<std::string> closest(std::string_view word,
                                   const std::vector<std::string>& candidates) {
  std::optional<std::string> best;
  size_t best_d = std::numeric_limits<size_t>::max();
  for (const auto& c : candidates) {
    const size_t d = edit_distance(word, c);
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  if (!best) return std::nullopt;
  const size_t limit = std::max<size_t>(2, word.size() / 3);
  if (best_d == 0 || best_d > limit) return std::nullopt;
  return best;
}

}  // namespace armstudy::cases
