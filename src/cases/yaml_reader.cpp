#include "cases/yaml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace armstudy::cases {
namespace {

std::string describe_kind(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Map: return "a mapping";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Null: return "nothing";
    case YAML::NodeType::Scalar: return "'" + n.Scalar() + "'";
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

void Diagnostics::error(const YAML::Mark& mark, std::string message) {
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
  if (!errors_.empty()) throw CaseErrors(errors_);
}

std::string violation(double v, const NumberRule& rule) {
  const std::string u = rule.unit.empty() ? "" : " " + rule.unit;
  if (rule.sign == NumberRule::Sign::kPositive && !(v > 0)) return "should be > 0" + u;
  if (rule.sign == NumberRule::Sign::kNonNegative && !(v >= 0)) return "should be >= 0" + u;
  if (rule.min && v < *rule.min) {
    if (rule.max) return "should be in [" + format_number(*rule.min) + ", " + format_number(*rule.max) + "]" + u;
    return "should be >= " + format_number(*rule.min) + u;
  }
  if (rule.max && v > *rule.max) {
    if (rule.min) return "should be in [" + format_number(*rule.min) + ", " + format_number(*rule.max) + "]" + u;
    return "should be <= " + format_number(*rule.max) + u;
  }
  return "";
}

std::optional<double> read_number(const YAML::Node& node, Diagnostics& diag, std::string_view what,
                                  const NumberRule& rule) {
  const std::string name(what);
  if (!node.IsScalar()) {
    diag.error(node.Mark(), name + " is " + describe_kind(node) + "; expected a number");
    return std::nullopt;
  }
  double v = 0;
  const std::string& s = node.Scalar();
  // yaml-cpp converts .nan/.inf; anything else that is not a number fails
  try {
    v = node.as<double>();
  } catch (const YAML::Exception&) {
    diag.error(node.Mark(), name + " is '" + s + "'; expected a number");
    return std::nullopt;
  }
  if (!std::isfinite(v)) {
    diag.error(node.Mark(), name + " is " + s + "; expected a finite number");
    return std::nullopt;
  }
  const std::string bad = violation(v, rule);
  if (!bad.empty()) {
    diag.error(node.Mark(), name + " is " + format_number(v) + "; " + bad);
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
  std::vector<std::string> seen;
  for (const auto& kv : node) {
    if (!kv.first.IsScalar()) {
      diag.error(kv.first.Mark(), "a key of '" + context_ + "' is not a plain word; expected a key name");
      continue;
    }
    const std::string k = kv.first.Scalar();
    if (std::find(seen.begin(), seen.end(), k) != seen.end()) {
      diag.error(kv.first.Mark(), "duplicate key '" + path_of(k) + "'; expected each key once");
    } else {
      seen.push_back(k);
    }
  }
}

std::string Map::path_of(std::string_view key) const {
  return context_.empty() ? std::string(key) : context_ + "." + std::string(key);
}

bool Map::has(std::string_view key) const {
  if (!valid_) return false;
  for (const auto& kv : node_)
    if (kv.first.IsScalar() && kv.first.Scalar() == key) return true;
  return false;
}

YAML::Node Map::get(std::string_view key) {
  known_.emplace_back(key);
  if (!valid_) return YAML::Node(YAML::NodeType::Undefined);
  for (const auto& kv : node_)
    if (kv.first.IsScalar() && kv.first.Scalar() == key) return kv.second;
  return YAML::Node(YAML::NodeType::Undefined);
}

std::optional<double> Map::number(std::string_view key, const NumberRule& rule) {
  const YAML::Node n = get(key);
  if (!n.IsDefined()) return std::nullopt;
  return read_number(n, *diag_, "'" + path_of(key) + "'", rule);
}

double Map::number_or(std::string_view key, double fallback, const NumberRule& rule) {
  const bool present = has(key);
  const auto v = number(key, rule);
  if (v) return *v;
  return present ? std::numeric_limits<double>::quiet_NaN() : fallback;
}

double Map::required_number(std::string_view key, const NumberRule& rule) {
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
  const YAML::Node n = get(key);
  if (!n.IsDefined()) return std::nullopt;
  const auto v = read_number(n, *diag_, "'" + path_of(key) + "'",
                             NumberRule::range(min, max, ""));
  if (!v) return std::nullopt;
  if (*v != std::floor(*v)) {
    diag_->error(n.Mark(), "'" + path_of(key) + "' is " + n.Scalar() + "; expected a whole number");
    return std::nullopt;
  }
  return static_cast<int>(*v);
}

int Map::integer_or(std::string_view key, int fallback, int min, int max) {
  const auto v = integer(key, min, max);
  return v ? *v : fallback;
}

std::optional<std::string> Map::string(std::string_view key) {
  const YAML::Node n = get(key);
  if (!n.IsDefined()) return std::nullopt;
  if (!n.IsScalar()) {
    diag_->error(n.Mark(), "'" + path_of(key) + "' is " + describe_kind(n) + "; expected a string");
    return std::nullopt;
  }
  return n.Scalar();
}

std::string Map::string_or(std::string_view key, std::string fallback) {
  const auto v = string(key);
  return v ? *v : fallback;
}

std::optional<std::string> Map::required_string(std::string_view key) {
  if (!has(key)) {
    get(key);
    error_here("missing required key '" + path_of(key) + "'; expected a string");
    return std::nullopt;
  }
  return string(key);
}

std::optional<std::string> Map::choice(std::string_view key, const std::vector<std::string>& allowed) {
  const auto v = string(key);
  if (!v) return std::nullopt;
  if (std::find(allowed.begin(), allowed.end(), *v) != allowed.end()) return v;
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  std::string msg = "'" + path_of(key) + "' is '" + *v + "'; expected one of: " + list;
  if (const auto c = closest(*v, allowed)) msg += " (did you mean '" + *c + "'?)";
  error(key, msg);
  return std::nullopt;
}

std::optional<bool> Map::boolean(std::string_view key) {
  const YAML::Node n = get(key);
  if (!n.IsDefined()) return std::nullopt;
  if (n.IsScalar()) {
    const std::string& s = n.Scalar();
    if (s == "true") return true;
    if (s == "false") return false;
  }
  diag_->error(n.Mark(), "'" + path_of(key) + "' is " + describe_kind(n) + "; expected true or false");
  return std::nullopt;
}

bool Map::boolean_or(std::string_view key, bool fallback) {
  const auto v = boolean(key);
  return v ? *v : fallback;
}

std::optional<std::vector<double>> Map::numbers(std::string_view key, const NumberRule& rule,
                                                size_t size) {
  const YAML::Node n = get(key);
  if (!n.IsDefined()) return std::nullopt;
  if (!n.IsSequence() || n.size() == 0 || (size != 0 && n.size() != size)) {
    diag_->error(n.Mark(), "'" + path_of(key) + "' is " + describe_kind(n) + "; expected a list of " +
                               (size ? std::to_string(size) + " numbers" : "numbers"));
    return std::nullopt;
  }
  std::vector<double> out;
  bool ok = true;
  for (size_t i = 0; i < n.size(); ++i) {
    const auto v = read_number(n[i], *diag_, "'" + path_of(key) + "[" + std::to_string(i + 1) + "]'", rule);
    if (v) out.push_back(*v); else ok = false;
  }
  if (!ok) return std::nullopt;
  return out;
}

std::optional<Map> Map::map(std::string_view key) {
  const YAML::Node n = get(key);
  if (!n.IsDefined()) return std::nullopt;
  if (!n.IsMap()) {
    diag_->error(n.Mark(), "'" + path_of(key) + "' is " + describe_kind(n) + "; expected a mapping of keys");
    return std::nullopt;
  }
  return Map(n, *diag_, path_of(key));
}

std::optional<Seq> Map::seq(std::string_view key) {
  const YAML::Node n = get(key);
  if (!n.IsDefined()) return std::nullopt;
  if (!n.IsSequence()) {
    diag_->error(n.Mark(), "'" + path_of(key) + "' is " + describe_kind(n) + "; expected a list");
    return std::nullopt;
  }
  return Seq(n, *diag_, path_of(key));
}

void Map::error(std::string_view key, std::string message) {
  if (valid_) {
    for (const auto& kv : node_) {
      if (kv.first.IsScalar() && kv.first.Scalar() == key) {
        diag_->error(kv.second.Mark(), std::move(message));
        return;
      }
    }
  }
  diag_->error(node_.Mark(), std::move(message));
}

void Map::error_here(std::string message) { diag_->error(node_.Mark(), std::move(message)); }

void Map::finish() {
  if (!valid_) return;
  for (const auto& kv : node_) {
    if (!kv.first.IsScalar()) continue;
    const std::string k = kv.first.Scalar();
    if (std::find(known_.begin(), known_.end(), k) != known_.end()) continue;
    std::string msg = "unknown key '" + path_of(k) + "'";
    if (const auto c = closest(k, known_)) {
      msg += "; did you mean '" + *c + "'?";
    } else {
      std::vector<std::string> sorted = known_;
      std::sort(sorted.begin(), sorted.end());
      sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
      msg += "; expected one of: ";
      for (size_t i = 0; i < sorted.size(); ++i) msg += (i ? ", " : "") + sorted[i];
    }
    diag_->error(kv.first.Mark(), msg);
  }
}

// ----------------------------------------------------------------------------- Seq

Seq::Seq(const YAML::Node& node, Diagnostics& diag, std::string context)
    : node_(node), diag_(&diag), context_(std::move(context)) {}

std::string Seq::path_at(size_t i) const { return context_ + "[" + std::to_string(i + 1) + "]"; }

std::optional<Map> Seq::map_at(size_t i) const {
  const YAML::Node n = node_[i];
  if (!n.IsMap()) {
    diag_->error(n.Mark(), "'" + path_at(i) + "' is " + describe_kind(n) + "; expected a mapping of keys");
    return std::nullopt;
  }
  return Map(n, *diag_, path_at(i));
}

// ----------------------------------------------------------------------------- files

std::optional<YAML::Node> parse_file(const std::string& path, Diagnostics& diag, std::string* text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diag.error(YAML::Mark::null_mark(), "cannot open the case file; expected a readable YAML file");
    return std::nullopt;
  }
  std::ostringstream ss;
  ss << in.rdbuf();
  const std::string bytes = ss.str();
  if (text) *text = bytes;
  return parse_text(bytes, diag);
}

std::optional<YAML::Node> parse_text(const std::string& bytes, Diagnostics& diag) {
  YAML::Node root;
  try {
    root = YAML::Load(bytes);
  } catch (const YAML::ParserException& e) {
    diag.error(e.mark, "not valid YAML (" + e.msg + "); expected a YAML mapping");
    return std::nullopt;
  }
  if (root.IsNull() || !root.IsDefined()) {
    diag.error(YAML::Mark::null_mark(), "the file is empty; expected a YAML mapping with 'study:' and 'name:'");
    return std::nullopt;
  }
  if (!root.IsMap()) {
    diag.error(root.Mark(), "the file holds " + describe_kind(root) +
                                "; expected a YAML mapping with 'study:' and 'name:'");
    return std::nullopt;
  }
  return root;
}

std::optional<std::string> closest(std::string_view word, const std::vector<std::string>& candidates) {
  std::optional<std::string> best;
  size_t best_d = std::numeric_limits<size_t>::max();
  for (const auto& c : candidates) {
    const size_t d = edit_distance(word, c);
    if (d < best_d) { best_d = d; best = c; }
  }
  if (!best) return std::nullopt;
  const size_t limit = std::max<size_t>(2, word.size() / 3);
  if (best_d == 0 || best_d > limit) return std::nullopt;
  return best;
}

}  // namespace armstudy::cases
