// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Typed, position-aware reading of YAML case files (yaml-cpp 0.7).
///
/// Every problem is recorded in Diagnostics with its file:line:column (yaml-cpp marks are
/// 0-based; we add 1) and reading goes on, so a user sees every error of a file at once
/// (the first kMaxErrors of them, then how many more there were).
/// yaml-cpp accepts duplicate and unknown keys silently: Map detects both itself, in time
/// linear in the number of keys. Map also resolves YAML merge keys (`<<: *defaults`, or
/// `<<: [*a, *b]`) as YAML 1.1 defines them: the mapping's own keys win, then the merged
/// mappings in order. Files are checked before yaml-cpp reads them (yaml_source.hpp).

#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "cases/budget.hpp"
#include "cases/case_error.hpp"
#include "cases/yaml_source.hpp"

namespace armstudy::cases {

/// Errors kept per file; more are counted, not kept.
inline constexpr size_t kMaxErrors = 50;

class KeyCatalog;

/// Collects the errors of one file.
class Diagnostics {
 public:
  explicit Diagnostics(std::string path) : path_(std::move(path)) {}
  const std::string& path() const { return path_; }
  /// Records `message` at a yaml-cpp mark (0-based; a null mark records no position).
  void error(const YAML::Mark& mark, std::string message);
  bool empty() const { return errors_.empty(); }
  /// The first kMaxErrors errors.
  const std::vector<CaseError>& errors() const { return errors_; }
  /// Every error recorded, kept or not.
  size_t count() const { return errors_.size() + dropped_; }
  /// @throws CaseErrors if any error was recorded (the kept ones, then one saying how many
  /// more there were).
  void throw_if_any() const;
  /// Records what the case asks for (judged against the budget by the caller).
  void demand(Demand d) { demands_.push_back(std::move(d)); }
  const std::vector<Demand>& demands() const { return demands_; }
  /// Catalog mode (KeyCatalog below): the maps read with this Diagnostics record each key
  /// they ask for instead of reading a file.
  void set_catalog(KeyCatalog* catalog) { catalog_ = catalog; }
  KeyCatalog* catalog() const { return catalog_; }

 private:
  std::string path_;
  KeyCatalog* catalog_ = nullptr;
  std::vector<CaseError> errors_;
  std::vector<Demand> demands_;
  size_t dropped_ = 0;
};

/// Bounds a number must meet; `unit` is only for messages ("m", "kg", "deg").
struct NumberRule {
  enum class Sign { kAny, kPositive, kNonNegative } sign = Sign::kAny;
  std::optional<double> min;  ///< inclusive
  std::optional<double> max;  ///< inclusive
  std::string unit;
  bool or_zero = false;  ///< 0 is allowed besides [min, max] (a mass: none, or a real one)

  static NumberRule positive(std::string unit) {
    return {Sign::kPositive, {}, {}, std::move(unit)};
  }
  static NumberRule non_negative(std::string unit) {
    return {Sign::kNonNegative, {}, {}, std::move(unit)};
  }
  static NumberRule range(double lo, double hi, std::string unit) {
    return {Sign::kAny, lo, hi, std::move(unit)};
  }
  static NumberRule any(std::string unit) { return {Sign::kAny, {}, {}, std::move(unit)}; }
  /// 0, or a value in [lo, hi]
  static NumberRule zero_or_range(double lo, double hi, std::string unit) {
    return {Sign::kAny, lo, hi, std::move(unit), true};
  }
};

/// A number as messages show it: 6 significant digits, C locale ("0.4", "1e-06").
std::string format_number(double v);

/// A number exactly, for a limit and the value that broke it: a whole number below 1e15
/// in full ("1000001", never "1e+06"), else the shortest text that reads back to it.
std::string exact_number(double v);

/// Magnitudes a case number may have (besides 0): products of a few of them stay finite
/// and normal in double precision. Beyond them a number is refused as out of range.
inline constexpr double kMaxMagnitude = 1e100;
inline constexpr double kMinMagnitude = 1e-100;

/// Checks a finite number against a rule; returns the complaint or "".
std::string violation(double value, const NumberRule& rule);

/// Reads a scalar node as a finite number meeting `rule`; records an error at the node
/// (naming `what`) and returns nullopt otherwise: for text that is no number, a number
/// that overflows or underflows a double, a denormal, a magnitude outside
/// [kMinMagnitude, kMaxMagnitude], or one that breaks the rule.
std::optional<double> read_number(const YAML::Node& node, Diagnostics& diag, std::string_view what,
                                  const NumberRule& rule);

/// One key of a case file as a loader asks for it: what KeyCatalog records.
struct KeyInfo {
  /// dotted, a list's items as [] ("arm.links[].length")
  std::string path;
  /// number, integer, string, choice, boolean, numbers (a list of numbers), mapping, list,
  /// value (read by the loader itself: its meaning says what it takes)
  std::string kind = "value";
  NumberRule rule;                          ///< number, integer, numbers
  std::optional<std::string> default_text;  ///< the loader's default, as YAML text
  std::vector<std::string> choices;         ///< choice
  size_t count = 0;                         ///< numbers: the length it must have (0: any)
  bool required = false;
};

/// The keys the case loaders read, recorded by running them in catalog mode: a Map whose
/// Diagnostics has a catalog answers as if every key it asks for were present (unless its
/// path is in `absent`), each typed read giving the loader's default or nothing (as for a
/// value it refuses), map() an empty mapping and seq() a list of two empty mappings, so that
/// a loader walks every branch it can reach and records each key's kind, rule and default.
/// Loaders read nothing else (no files), so a catalog is the one description of the keys
/// that the schema, the key reference and `armstudy init` are made from (app/case_keys.hpp).
class KeyCatalog {
 public:
  /// Paths (as KeyInfo::path) read as absent in this pass.
  std::set<std::string> absent;
  /// Every key recorded, in the order first asked for.
  std::vector<KeyInfo> keys;
  /// The paths a loader asked has() for (the branches a later pass may leave out).
  std::set<std::string> asked;
  /// Records a key; a later record of the same path adds what it knows (a kind for a
  /// value, a default, required).
  void record(KeyInfo k);
  /// `path` with each list index as [] ("arm.links[2].mass" -> "arm.links[].mass").
  static std::string pattern(const std::string& path);
};

class Seq;

/// A YAML mapping being read. Every key asked for becomes known; finish() reports the
/// rest as unknown, with a "did you mean" suggestion. Duplicate keys are errors.
class Map {
 public:
  /// `context` names the mapping in messages, e.g. "arm.links[2]" ("" for the root).
  Map(const YAML::Node& node, Diagnostics& diag, std::string context);

  bool has(std::string_view key) const;
  /// The key's value node (undefined node if missing); marks the key known.
  YAML::Node get(std::string_view key);

  std::optional<double> number(std::string_view key, const NumberRule& rule);
  double number_or(std::string_view key, double fallback, const NumberRule& rule);
  /// Records "missing required key" if absent; returns NaN then.
  double required_number(std::string_view key, const NumberRule& rule);
  std::optional<int> integer(std::string_view key, int min, int max);
  int integer_or(std::string_view key, int fallback, int min, int max);
  std::optional<std::string> string(std::string_view key);
  std::string string_or(std::string_view key, std::string fallback);
  std::optional<std::string> required_string(std::string_view key);
  /// A string that must be one of `allowed`.
  std::optional<std::string> choice(std::string_view key, const std::vector<std::string>& allowed);
  std::optional<bool> boolean(std::string_view key);
  bool boolean_or(std::string_view key, bool fallback);
  /// A list of numbers; `size` 0 means any non-empty length; nullopt when absent.
  /// `default_value`: what the loader keeps when the key is absent (in the key's unit), for
  /// the key reference, the schema and `armstudy init`; empty: none.
  std::optional<std::vector<double>> numbers(std::string_view key, const NumberRule& rule,
                                             size_t size = 0,
                                             const std::vector<double>& default_value = {});
  std::optional<Map> map(std::string_view key);
  /// A list; nullopt when absent. `default_items`: the items (as YAML scalars) the loader
  /// keeps when the key is absent, for the key reference, the schema and `armstudy init`.
  std::optional<Seq> seq(std::string_view key, const std::vector<std::string>& default_items = {});

  /// Records an error at the key's value (or at the mapping if the key is missing).
  void error(std::string_view key, std::string message);
  /// Records an error at the mapping itself.
  void error_here(std::string message);
  /// Reports every key never asked for as unknown.
  void finish();

  const YAML::Node& node() const { return node_; }
  Diagnostics& diag() const { return *diag_; }
  const std::string& context() const { return context_; }
  std::string path_of(std::string_view key) const;

 private:
  struct Entry {
    std::string key;
    YAML::Node key_node;
    YAML::Node value;
    bool merged = false;  ///< from a merge key (<<), not written in this mapping
  };
  void merge_from(const YAML::Node& source, int depth, bool in_list);
  const Entry* find(std::string_view key) const;

  YAML::Node node_;
  Diagnostics* diag_;
  std::string context_;
  std::vector<Entry> entries_;                     ///< in file order, merged ones last
  std::unordered_map<std::string, size_t> index_;  ///< key -> entries_ index
  /// keys asked for (by has() too: an alternative key is known), in order
  mutable std::vector<std::string> known_;
  mutable std::unordered_set<std::string> known_set_;
  bool valid_ = false;
  /// catalog mode: records `k` (its path made from `key`); true when the key is present
  bool catalog_key(std::string_view key, KeyInfo k) const;
  void mark_known(std::string_view key) const;
};

/// A YAML sequence being read.
class Seq {
 public:
  Seq(const YAML::Node& node, Diagnostics& diag, std::string context);
  size_t size() const { return node_.size(); }
  YAML::Node at(size_t i) const { return node_[i]; }
  /// Element i as a mapping (nullopt and an error if it is not one).
  std::optional<Map> map_at(size_t i) const;
  std::string path_at(size_t i) const;
  Diagnostics& diag() const { return *diag_; }
  const YAML::Node& node() const { return node_; }

 private:
  YAML::Node node_;
  Diagnostics* diag_;
  std::string context_;
};

/// What a case file is, for the message of an empty file or a root that is no mapping.
inline const std::string kCaseFileExpected = "a YAML mapping with 'study:' and 'name:'";

/// Parses a YAML file; on a file that is not a regular file of at most kMaxFileBytes, text
/// or structure refused by check_yaml_source, a syntax error, an empty file or a
/// non-mapping root, records the error and returns nullopt. `text` receives the bytes.
/// `expected` is what an empty file or another root should have been (a case file's by
/// default).
std::optional<YAML::Node> parse_file(const std::string& path, Diagnostics& diag, std::string* text,
                                     const std::string& expected = kCaseFileExpected);

/// Parses YAML text like parse_file (errors recorded against diag's path). Line breaks
/// may be LF, CRLF or a CR alone.
std::optional<YAML::Node> parse_text(const std::string& text, Diagnostics& diag,
                                     const std::string& expected = kCaseFileExpected);

/// The closest of `candidates` to `word` by edit distance, if close enough to suggest.
std::optional<std::string> closest(std::string_view word,
                                   const std::vector<std::string>& candidates);

}  // namespace armstudy::cases
