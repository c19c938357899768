// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The JSON mapping of the typed study results (src/studies/<study>/study_results.hpp),
/// written once per type as a `fields` function that names every key:
///
///   template <class V> void fields(V& v, Energy& e) {
///     v("initial_J", e.initial, "mechanical energy at t = 0");
///     v.optional("note", e.note, "present only for a singular motion");
///   }
///
/// and turned here into the three things that must agree: the writer (to_json, numbers as
/// app/json_numbers.hpp writes them: NaN and infinity as null), the strict reader
/// (from_json: every key required, an unknown or misspelt key is an error naming its path)
/// and the JSON Schema of the section (results.schema.json; the unit in each description
/// comes from the key's suffix, e.g. "_J" -> J).
///
/// Field types: double (null reads as NaN), int, long long, bool, std::string, std::vector,
/// std::array, std::map<std::string, T> (an object), std::optional (written as null when
/// empty), and any type with a `fields`. A fourth argument adds JSON Schema keywords the type
/// alone does not say: v("status", x.status, "...", {{"enum", json::array({"a", "b"})}}).
/// v.optional(key, opt) is a key that may be absent; v.inline_if(flag, opt) and
/// v.inline_when(first_key, opt) put an optional group's keys in the enclosing object.

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/number_format.hpp"

namespace armstudy::report {

/// A results.json that does not hold what the study writes: `path` is the JSON pointer of
/// the offending value (e.g. "/placement/optima/0/energy_j").
class ResultsError : public std::runtime_error {
 public:
  ResultsError(std::string path, const std::string& what)
      : std::runtime_error(path + ": " + what), path_(std::move(path)) {}
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// The unit a key's suffix names ("energy_J" -> "J", "q_rad_s" -> "rad/s"), "" for none.
std::string unit_of_key(const std::string& key);

namespace fields_detail {

template <class T>
struct is_vector : std::false_type {};
template <class T>
struct is_vector<std::vector<T>> : std::true_type {};
template <class T>
struct is_array : std::false_type {};
template <class T, size_t N>
struct is_array<std::array<T, N>> : std::true_type {};
template <class T>
struct is_map : std::false_type {};
template <class T>
struct is_map<std::map<std::string, T>> : std::true_type {};
template <class T>
struct is_optional : std::false_type {};
template <class T>
struct is_optional<std::optional<T>> : std::true_type {};

inline const char* type_name(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::boolean: return "a boolean";
    case nlohmann::json::value_t::string: return "a string";
    case nlohmann::json::value_t::array: return "an array";
    case nlohmann::json::value_t::object: return "an object";
    case nlohmann::json::value_t::number_float: return "a number";
    default: return "an integer";
  }
}

// ---- writer ----
template <class T>
nlohmann::json write(const T& x);

struct Writer {
  nlohmann::json* out;
  template <class T>
  void operator()(const char* key, const T& x, const char* = "", const nlohmann::json& = {}) {
    (*out)[key] = write(x);
  }
  template <class T>
  void optional(const char* key, const std::optional<T>& x, const char* = "",
                const nlohmann::json& = {}) {
    if (x) (*out)[key] = write(*x);
  }
  /// the keys of `x`, in this object, when `present` (an earlier field says so)
  template <class T>
  void inline_if(bool, const std::optional<T>& x) {
    if (x) fields(*this, const_cast<T&>(*x));
  }
  /// the same, present when the object holds `key` (the first of T's keys)
  template <class T>
  void inline_when(const char*, const std::optional<T>& x) {
    inline_if(true, x);
  }
};

template <class T>
nlohmann::json write(const T& x) {
  if constexpr (std::is_same_v<T, double>) {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
  } else if constexpr (std::is_same_v<T, bool> || std::is_integral_v<T> ||
                       std::is_same_v<T, std::string>) {
    return nlohmann::json(x);
  } else if constexpr (is_map<T>::value) {
    nlohmann::json o = nlohmann::json::object();
    for (const auto& [k, e] : x) o[k] = write(e);
    return o;
  } else if constexpr (is_vector<T>::value || is_array<T>::value) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& e : x) a.push_back(write(static_cast<const typename T::value_type&>(e)));
    return a;
  } else if constexpr (is_optional<T>::value) {
    return x ? write(*x) : nlohmann::json(nullptr);
  } else {
    nlohmann::json o = nlohmann::json::object();
    Writer w{&o};
    fields(w, const_cast<T&>(x));  // the writer only reads
    return o;
  }
}

// ---- reader ----
template <class T>
void read(const nlohmann::json& j, const std::string& path, T& x);

// every key a T may hold (its optional and inline keys included)
struct KeyCollector {
  std::set<std::string>* keys;
  template <class T>
  void operator()(const char* key, T&, const char* = "", const nlohmann::json& = {}) {
    keys->insert(key);
  }
  template <class T>
  void optional(const char* key, std::optional<T>&, const char* = "", const nlohmann::json& = {}) {
    keys->insert(key);
  }
  template <class T>
  void inline_if(bool, std::optional<T>&) {
    T probe{};
    fields(*this, probe);
  }
  template <class T>
  void inline_when(const char*, std::optional<T>& x) {
    inline_if(true, x);
  }
};

// edit distance of two keys, for "did you mean"
inline size_t distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diag = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

template <class T>
void reject_unknown_keys(const nlohmann::json& j, const std::string& path) {
  std::set<std::string> keys;
  KeyCollector c{&keys};
  T probe{};
  fields(c, probe);
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (keys.count(it.key())) continue;
    std::string best;
    size_t d = 3;  // suggest only a near miss
    for (const std::string& k : keys)
      if (const size_t e = distance(it.key(), k); e < d) d = e, best = k;
    throw ResultsError(
        path + "/" + it.key(),
        "unknown key '" + it.key() + "'" + (best.empty() ? "" : "; did you mean '" + best + "'?"));
  }
}

struct Reader {
  const nlohmann::json* in;
  std::string path;
  std::set<std::string> seen;
  template <class T>
  void operator()(const char* key, T& x, const char* = "", const nlohmann::json& = {}) {
    seen.insert(key);
    const auto it = in->find(key);
    if (it == in->end()) throw ResultsError(path + "/" + key, "missing");
    read(*it, path + "/" + key, x);
  }
  template <class T>
  void optional(const char* key, std::optional<T>& x, const char* = "",
                const nlohmann::json& = {}) {
    seen.insert(key);
    const auto it = in->find(key);
    if (it == in->end()) {
      x.reset();
      return;
    }
    // T{} rather than emplace(): clang 14 takes a nested struct with default member
    // initializers for not default-constructible in emplace's constraint, and the fuzz
    // build (clang) reads every study's section
    x = T{};
    read(*it, path + "/" + key, *x);
  }
  template <class T>
  void inline_if(bool present, std::optional<T>& x) {
    x.reset();
    if (!present) return;
    x = T{};
    fields(*this, *x);
  }
  template <class T>
  void inline_when(const char* key, std::optional<T>& x) {
    inline_if(in->contains(key), x);
  }
};

[[noreturn]] inline void expected(const nlohmann::json& j, const std::string& path,
                                  const char* what) {
  throw ResultsError(path, std::string("expected ") + what + ", found " + type_name(j));
}

template <class T>
void read(const nlohmann::json& j, const std::string& path, T& x) {
  if constexpr (std::is_same_v<T, double>) {
    if (j.is_null())
      x = std::nan("");
    else if (j.is_number())
      x = j.get<double>();
    else
      expected(j, path, "a number or null");
  } else if constexpr (std::is_same_v<T, bool>) {
    if (!j.is_boolean()) expected(j, path, "a boolean");
    x = j.get<bool>();
  } else if constexpr (std::is_integral_v<T>) {
    if (!j.is_number_integer()) expected(j, path, "an integer");
    x = j.get<T>();
  } else if constexpr (std::is_same_v<T, std::string>) {
    if (!j.is_string()) expected(j, path, "a string");
    x = j.get<std::string>();
  } else if constexpr (std::is_same_v<T, std::vector<bool>>) {
    if (!j.is_array()) expected(j, path, "an array");
    x.clear();
    for (size_t k = 0; k < j.size(); ++k) {
      bool b = false;
      read(j[k], path + "/" + std::to_string(k), b);
      x.push_back(b);
    }
  } else if constexpr (is_map<T>::value) {
    if (!j.is_object()) expected(j, path, "an object");
    x.clear();
    for (auto it = j.begin(); it != j.end(); ++it)
      read(it.value(), path + "/" + it.key(), x[it.key()]);
  } else if constexpr (is_vector<T>::value) {
    if (!j.is_array()) expected(j, path, "an array");
    x.clear();
    x.resize(j.size());
    for (size_t k = 0; k < j.size(); ++k) read(j[k], path + "/" + std::to_string(k), x[k]);
  } else if constexpr (is_array<T>::value) {
    if (!j.is_array() || j.size() != x.size())
      throw ResultsError(path,
                         "expected an array of " + std::to_string(x.size()) + ", found " +
                             (j.is_array() ? std::to_string(j.size()) + " items" : type_name(j)));
    for (size_t k = 0; k < x.size(); ++k) read(j[k], path + "/" + std::to_string(k), x[k]);
  } else if constexpr (is_optional<T>::value) {
    if (j.is_null()) {
      x.reset();
    } else {
      x.emplace();
      read(j, path, *x);
    }
  } else {
    if (!j.is_object()) expected(j, path, "an object");
    reject_unknown_keys<T>(j, path);  // first: a misspelt key is named, not the key it hides
    Reader r{&j, path, {}};
    fields(r, x);
    for (auto it = j.begin(); it != j.end(); ++it)
      if (!r.seen.count(it.key()))  // a key of an inline group that is not there
        throw ResultsError(path + "/" + it.key(), "unexpected key '" + it.key() + "' here");
  }
}

// ---- schema ----
template <class T>
nlohmann::json schema();

inline std::string describe(const char* key, const char* text) {
  const std::string unit = unit_of_key(key);
  std::string d = text;
  if (!unit.empty()) d += (d.empty() ? "" : "; ") + std::string("unit: ") + unit;
  return d;
}

struct SchemaWriter {
  nlohmann::json* properties;
  nlohmann::json* required;
  template <class T>
  void operator()(const char* key, T&, const char* text = "", const nlohmann::json& extra = {}) {
    required->push_back(key);
    add(key, schema<T>(), text, extra);
  }
  template <class T>
  void optional(const char* key, std::optional<T>&, const char* text = "",
                const nlohmann::json& extra = {}) {
    add(key, schema<T>(), text, extra);
  }
  template <class T>
  void inline_if(bool, std::optional<T>&) {
    nlohmann::json not_required = nlohmann::json::array();
    SchemaWriter w{properties, &not_required};
    T probe{};
    fields(w, probe);
  }
  template <class T>
  void inline_when(const char*, std::optional<T>& x) {
    inline_if(true, x);
  }
  // `extra`: keywords the type alone does not say (a pattern, an enum, a minimum)
  void add(const char* key, nlohmann::json s, const char* text, const nlohmann::json& extra) {
    const std::string d = describe(key, text);
    if (!d.empty()) s["description"] = d;
    if (extra.is_object())
      for (auto it = extra.begin(); it != extra.end(); ++it) s[it.key()] = it.value();
    (*properties)[key] = std::move(s);
  }
};

template <class T>
nlohmann::json schema() {
  using nlohmann::json;
  if constexpr (std::is_same_v<T, double>) {
    return {{"type", json::array({"number", "null"})}};
  } else if constexpr (std::is_same_v<T, bool>) {
    return {{"type", "boolean"}};
  } else if constexpr (std::is_integral_v<T>) {
    return {{"type", "integer"}};
  } else if constexpr (std::is_same_v<T, std::string>) {
    return {{"type", "string"}};
  } else if constexpr (is_map<T>::value) {
    return {{"type", "object"}, {"additionalProperties", schema<typename T::mapped_type>()}};
  } else if constexpr (is_vector<T>::value) {
    return {{"type", "array"}, {"items", schema<typename T::value_type>()}};
  } else if constexpr (is_array<T>::value) {
    const size_t n = std::tuple_size_v<T>;
    return {{"type", "array"},
            {"items", schema<typename T::value_type>()},
            {"minItems", n},
            {"maxItems", n}};
  } else if constexpr (is_optional<T>::value) {
    return {{"anyOf", json::array({schema<typename T::value_type>(), {{"type", "null"}}})}};
  } else {
    json props = json::object(), req = json::array();
    SchemaWriter w{&props, &req};
    T probe{};
    fields(w, probe);
    return {{"type", "object"},
            {"required", req},
            {"properties", props},
            {"additionalProperties", false}};
  }
}

}  // namespace fields_detail

/// `x` as JSON (every key of its `fields`).
template <class T>
nlohmann::json to_json(const T& x) {
  return fields_detail::write(x);
}

/// `j` read strictly into a T: every key present with its type, no other key.
/// @throws ResultsError naming the JSON pointer (below `path`) of the first problem.
template <class T>
T from_json(const nlohmann::json& j, const std::string& path = "") {
  T x{};
  fields_detail::read(j, path, x);
  return x;
}

/// Every key a T's JSON object may hold (its optional and inline keys included).
template <class T>
std::set<std::string> field_keys() {
  std::set<std::string> keys;
  fields_detail::KeyCollector c{&keys};
  T probe{};
  fields(c, probe);
  return keys;
}

/// The JSON Schema (2020-12) of T's JSON form: every key required unless optional, no
/// other key allowed (additionalProperties false), each key's unit in its description.
template <class T>
nlohmann::json json_schema() {
  return fields_detail::schema<T>();
}

/// results[study] (a whole results.json) read strictly into the study's typed results.
/// @throws ResultsError naming the JSON pointer of the first problem ("/<study>": missing).
template <class T>
T read_study_results(const nlohmann::json& results, const std::string& study) {
  const auto it = results.find(study);
  if (it == results.end()) throw ResultsError("/" + study, "missing");
  return from_json<T>(*it, "/" + study);
}

/// A value as a page prints it: "yes"/"no", integers as numbers (6 significant digits).
inline std::string as_text(bool b) { return b ? "yes" : "no"; }
inline std::string as_text(long long v) { return format_sig(static_cast<double>(v), 6); }
inline std::string as_text(long v) { return as_text(static_cast<long long>(v)); }
inline std::string as_text(int v) { return as_text(static_cast<long long>(v)); }
inline std::string as_text(unsigned v) { return as_text(static_cast<long long>(v)); }
inline std::string as_text(double v) { return format_sig(v, 6); }

/// Column `col` of rows of numbers (a time series of vectors), NaN where a row is short.
template <class Rows>
std::vector<double> column(const Rows& rows, size_t col) {
  std::vector<double> out;
  out.reserve(rows.size());
  for (const auto& r : rows) out.push_back(col < r.size() ? r[col] : std::nan(""));
  return out;
}

}  // namespace armstudy::report
