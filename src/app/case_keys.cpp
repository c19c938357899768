// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "app/case_keys.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "app/pipeline.hpp"
#include "app/study_loaders.hpp"
#include "report/case_report.hpp"

namespace armstudy::app {
namespace {
using cases::KeyCatalog;
using cases::KeyInfo;
using nlohmann::json;

// every study's name, in the order of --help
std::vector<std::string> study_names() {
  std::vector<std::string> names;
  for (const StudyLoader& l : study_loaders()) names.emplace_back(l.study);
  return names;
}

// one catalog pass: the case's own keys, then (with a loader) the study's, with `absent`
// left out
KeyCatalog catalog_pass(const StudyLoader* loader, const std::set<std::string>& absent) {
  cases::Diagnostics diag("(catalog)");
  KeyCatalog catalog;
  catalog.absent = absent;
  diag.set_catalog(&catalog);
  cases::Map root(YAML::Node(YAML::NodeType::Map), diag, "");
  root.choice("study", study_names());
  LoadedCase out;
  read_case_parts(root, out);
  if (loader) loader->load(root);
  for (KeyInfo& k : catalog.keys) k.required = k.required || k.path == "study";
  return catalog;
}

// the mapping a key is in ("" for the root)
std::string parent_of(const std::string& path) {
  const size_t dot = path.rfind('.');
  return dot == std::string::npos ? "" : path.substr(0, dot);
}

// every key a loader reads: the passes of case_keys()
std::vector<KeyInfo> all_keys(const StudyLoader* loader) {
  KeyCatalog all = catalog_pass(loader, {});
  std::set<std::set<std::string>> done = {{}};
  auto run = [&](const std::set<std::string>& absent) {
    if (!done.insert(absent).second) return;
    const KeyCatalog c = catalog_pass(loader, absent);
    for (const KeyInfo& k : c.keys) all.record(k);
    all.asked.insert(c.asked.begin(), c.asked.end());
  };
  // each key a loader asks has() for left out, then each pair in one mapping, until no
  // pass finds a new one
  for (size_t before = 0; before != all.asked.size();) {
    before = all.asked.size();
    const std::vector<std::string> asked(all.asked.begin(), all.asked.end());
    for (size_t i = 0; i < asked.size(); ++i) {
      run({asked[i]});
      for (size_t j = i + 1; j < asked.size(); ++j)
        if (parent_of(asked[i]) == parent_of(asked[j])) run({asked[i], asked[j]});
    }
  }
  return all.keys;
}

const StudyLoader& loader_of(std::string_view study) {
  for (const StudyLoader& l : study_loaders())
    if (l.study == study) return l;
  std::string list;
  for (const auto& s : study_names()) list += (list.empty() ? "" : ", ") + s;
  throw std::invalid_argument("unknown study '" + std::string(study) +
                              "'; expected one of: " + list);
}

// the paths of the keys every case has (no study's loader)
const std::set<std::string>& common_paths() {
  static const std::set<std::string> paths = [] {
    std::set<std::string> p;
    for (const KeyInfo& k : all_keys(nullptr)) p.insert(k.path);
    return p;
  }();
  return paths;
}

// ---- schema ----

json number_schema(const cases::NumberRule& rule, bool integer) {
  json s = {{"type", integer ? "integer" : "number"}};
  if (rule.sign == cases::NumberRule::Sign::kPositive) s["exclusiveMinimum"] = 0;
  if (rule.sign == cases::NumberRule::Sign::kNonNegative) s["minimum"] = 0;
  if (rule.or_zero && rule.min && rule.max) {  // 0, or a value in [min, max]
    s["anyOf"] =
        json::array({json{{"const", 0}}, json{{"minimum", *rule.min}, {"maximum", *rule.max}}});
    return s;
  }
  if (rule.min) s["minimum"] = *rule.min;
  if (rule.max) s["maximum"] = *rule.max;
  return s;
}

// the default as JSON (a number, true/false, text, or a list of numbers or of text)
json default_json(const KeyInfo& k) {
  const std::string& t = *k.default_text;
  if (k.kind == "boolean") return t == "true";
  if (k.kind == "numbers" || k.kind == "list") {  // YAML flow text: "[1, 2]", "[path_speed]"
    json items = json::array();
    for (const YAML::Node& item : YAML::Load(t)) {
      const std::string text = item.Scalar();
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (k.kind == "numbers" && end && *end == '\0')
        items.push_back(v);
      else
        items.push_back(text);
    }
    return items;
  }
  if (k.kind == "number" || k.kind == "integer") {
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (end && *end == '\0') return k.kind == "integer" ? json(static_cast<long long>(v)) : json(v);
  }
  return t;
}

std::string unit_of(const KeyInfo& k) {
  return k.kind == "number" || k.kind == "numbers" ? k.rule.unit : "";
}

std::string description(const CaseKey& k) {
  std::string d = k.doc ? std::string(k.doc->meaning) : "";
  if (const std::string u = unit_of(k.info); !u.empty()) d += " Unit: " + u + ".";
  if (k.doc && !k.doc->default_words.empty())
    d += " Default: " + std::string(k.doc->default_words) + ".";
  return d;
}

json leaf_schema(const CaseKey& k) {
  const KeyInfo& i = k.info;
  json s = json::object();
  if (i.kind == "number" || i.kind == "integer") s = number_schema(i.rule, i.kind == "integer");
  if (i.kind == "string") s = {{"type", "string"}};
  if (i.kind == "choice") s = {{"enum", i.choices}};
  if (i.kind == "boolean") s = {{"type", "boolean"}};
  if (i.kind == "numbers") {
    s = {{"type", "array"}, {"items", number_schema(i.rule, false)}, {"minItems", 1}};
    if (i.count) s["minItems"] = s["maxItems"] = i.count;
  }
  if (i.kind == "mapping") s = {{"type", "object"}};
  if (i.kind == "list") s = {{"type", "array"}};
  s["description"] = description(k);
  if (i.default_text && i.kind != "mapping") s["default"] = default_json(i);
  return s;
}

// the schema of the mapping whose keys are `keys` under `prefix` ("" the root; "arm." ...)
json object_schema(const std::vector<CaseKey>& keys, const std::string& prefix) {
  json props = json::object(), required = json::array();
  for (const CaseKey& k : keys) {
    const std::string& p = k.info.path;
    if (p.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = p.substr(prefix.size());
    if (rest.find('.') != std::string::npos || rest.find("[]") != std::string::npos) continue;
    json s = leaf_schema(k);
    const bool children = std::any_of(keys.begin(), keys.end(), [&](const CaseKey& c) {
      return c.info.path.compare(0, p.size() + 1, p + ".") == 0 ||
             c.info.path.compare(0, p.size() + 3, p + "[].") == 0;
    });
    if (k.info.kind == "mapping" && children) {
      json o = object_schema(keys, p + ".");
      o["description"] = s["description"];
      s = o;
    } else if (k.info.kind == "list" && children) {
      json items = object_schema(keys, p + "[].");
      if (k.doc && k.doc->example.empty() == false && k.doc->example[0] == '[' &&
          k.doc->example.find('{') == std::string_view::npos)
        items = json::object();  // a list of plain values (its loader reads them itself)
      if (p == "sensitivity")    // a key alone, or a mapping with its step
        items = {{"anyOf", json::array({{{"type", "string"}}, items})}};
      s["items"] = items;
    }
    props[rest] = s;
    if (k.info.required) required.push_back(rest);
  }
  json o = {{"type", "object"}, {"properties", props}, {"additionalProperties", false}};
  if (!required.empty()) o["required"] = required;
  return o;
}

// ---- text ----

std::string type_text(const KeyInfo& k) {
  if (k.kind == "number") return "number";
  if (k.kind == "integer") return "whole number";
  if (k.kind == "string") return "text";
  if (k.kind == "boolean") return "true or false";
  if (k.kind == "choice") {
    std::string s = "one of ";
    for (size_t i = 0; i < k.choices.size(); ++i) s += (i ? ", " : "") + k.choices[i];
    return s;
  }
  if (k.kind == "numbers")
    return "list of " + (k.count ? std::to_string(k.count) + " numbers" : "numbers");
  if (k.kind == "mapping") return "mapping";
  if (k.kind == "list") return "list";
  return "see meaning";
}

std::string range_text(const KeyInfo& k) {
  if (k.kind != "number" && k.kind != "integer" && k.kind != "numbers") return "";
  const auto& r = k.rule;
  if (r.or_zero && r.min && r.max)
    return "0 or [" + cases::format_number(*r.min) + ", " + cases::format_number(*r.max) + "]";
  if (r.min && r.max)
    return "[" + cases::format_number(*r.min) + ", " + cases::format_number(*r.max) + "]";
  if (r.min) return ">= " + cases::format_number(*r.min);
  if (r.max) return "<= " + cases::format_number(*r.max);
  if (r.sign == cases::NumberRule::Sign::kPositive) return "> 0";
  if (r.sign == cases::NumberRule::Sign::kNonNegative) return ">= 0";
  return "";
}

std::string default_text(const CaseKey& k) {
  if (k.doc && !k.doc->default_words.empty()) return std::string(k.doc->default_words);
  if (k.info.default_text) return *k.info.default_text;
  return k.info.required ? "(required)" : "";
}

std::string md_cell(std::string s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

void md_keys(std::ostringstream& md, const std::vector<CaseKey>& keys) {
  md << "| key | type | unit | default | range | meaning |\n|---|---|---|---|---|---|\n";
  for (const CaseKey& k : keys)
    md << "| `" << k.info.path << "` | " << md_cell(type_text(k.info)) << " | "
       << md_cell(unit_of(k.info)) << " | " << md_cell(default_text(k)) << " | "
       << md_cell(range_text(k.info)) << " | " << md_cell(k.doc ? std::string(k.doc->meaning) : "")
       << " |\n";
  md << "\n";
}

}  // namespace

std::vector<CaseKey> case_keys(std::string_view study) {
  const StudyLoader& loader = loader_of(study);
  std::vector<CaseKey> out;
  for (KeyInfo& k : all_keys(&loader)) {
    const cases::KeyDoc* doc = cases::find_key_doc(study, k.path);
    out.push_back({std::move(k), doc});
  }
  return out;
}

json case_schema() {
  json defs = json::object(), all_of = json::array();
  for (const std::string& study : study_names()) {
    json d = object_schema(case_keys(study), "");
    d["properties"]["study"] = {{"const", study}, {"description", "the study: " + study}};
    defs[study] = d;
    all_of.push_back(
        {{"if", {{"properties", {{"study", {{"const", study}}}}}, {"required", {"study"}}}},
         {"then", {{"$ref", "#/definitions/" + study}}}});
  }
  return {{"$schema", "http://json-schema.org/draft-07/schema#"},
          {"title", "armstudy case file"},
          {"description",
           "A case file of armstudy (YAML): made from the case loaders by `armstudy` itself "
           "(app/case_keys.hpp); docs/case-reference.md has every key's meaning"},
          {"type", "object"},
          {"required", {"study", "name"}},
          {"properties", {{"study", {{"enum", study_names()}}}}},
          {"allOf", all_of},
          {"definitions", defs}};
}

std::string case_reference_markdown() {
  std::ostringstream md;
  md << "# Case file keys\n\n"
        "<!-- generated by armstudy from its case loaders (app/case_keys.hpp); regenerate "
        "with ARMSTUDY_WRITE_SCHEMA=1 build/tests/cases_tests --gtest_filter=CaseSchema.* -->\n\n"
        "Every key a case file may have, as the loaders read it: its type, unit, default and "
        "range come from the loaders themselves, so this page and `case.schema.json` (the JSON "
        "Schema editors use: name it on the file's first line as `# yaml-language-server: "
        "$schema=...`) cannot disagree with armstudy. A list's items are `[]` in a path "
        "(`arm.links[].length` is the length of each link). `armstudy init STUDY` prints a "
        "case with every key at its default. The format is explained in "
        "[case_files.md](case_files.md).\n\n";
  const std::vector<CaseKey> any = case_keys(study_names().front());
  md << "## Every case\n\n";
  std::vector<CaseKey> common;
  for (const CaseKey& k : any)
    if (common_paths().count(k.info.path)) common.push_back(k);
  md_keys(md, common);
  for (const std::string& study : study_names()) {
    md << "## " << study << "\n\n";
    std::vector<CaseKey> own;
    for (CaseKey& k : case_keys(study))
      if (!common_paths().count(k.info.path)) own.push_back(std::move(k));
    md_keys(md, own);
  }
  return md.str();
}

namespace {

// the text of a comment: `text` in lines of at most 88 characters, each "<indent># "
std::string comment_lines(const std::string& text, const std::string& indent) {
  std::string out, line;
  std::istringstream words(text);
  std::string w;
  while (words >> w) {
    if (!line.empty() && indent.size() + 2 + line.size() + 1 + w.size() > 88) {
      out += indent + "# " + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + w;
  }
  if (!line.empty()) out += indent + "# " + line + "\n";
  return out;
}

struct InitWriter {
  const std::vector<CaseKey>& keys;
  std::string study;
  std::string out;

  bool has_children(const std::string& path) const {
    return std::any_of(keys.begin(), keys.end(), [&](const CaseKey& c) {
      return parent_of(c.info.path) == path || parent_of(c.info.path) == path + "[]";
    });
  }

  // the value written for `k` ("" for a mapping), or none when it has neither default nor
  // example
  std::optional<std::string> value_of(const CaseKey& k) const {
    if (k.info.path == "study") return study;
    if (k.info.path == "name") {
      std::string name = "my-" + study;
      std::replace(name.begin(), name.end(), '_', '-');
      return name;
    }
    if (k.info.kind == "mapping" && has_children(k.info.path)) return "";
    if (k.doc && !k.doc->example.empty()) return std::string(k.doc->example);
    if (k.info.default_text && k.info.kind == "number") {
      // 1e-12 is text to YAML 1.1 readers (PyYAML, some editors): write 1.0e-12
      std::string d = *k.info.default_text;
      if (const size_t e = d.find('e'); e != std::string::npos && d.find('.') == std::string::npos)
        d.insert(e, ".0");
      return d;
    }
    if (k.info.default_text) {
      const std::string& d = *k.info.default_text;
      const bool plain = k.info.kind != "string" ||
                         (!d.empty() && d.find_first_of(":#'\"{}[],&*!|>%@`") == std::string::npos);
      return plain ? d : "\"" + d + "\"";
    }
    return std::nullopt;
  }

  // the lines of the keys in `parent`; true when one of them is written (not a comment)
  bool write(const std::string& parent, const std::string& indent, bool active,
             std::string& text) const {
    bool any_on = false;
    for (const CaseKey& k : keys) {
      if (parent_of(k.info.path) != parent) continue;
      const std::string& path = k.info.path;
      const std::string name = path.substr(parent.empty() ? 0 : parent.size() + 1);
      const bool container = (k.info.kind == "mapping" || k.info.kind == "list");
      const auto value = value_of(k);
      bool on = active && value &&
                (k.info.required || (k.doc && k.doc->init) || (k.info.default_text && !container));
      // a mapping is written when one of its keys is (or its meaning says so)
      std::string children;
      if (k.info.kind == "mapping" && has_children(path)) {
        const bool child_on = write(path, indent + "  ", active, children);
        // (not one whose default is elsewhere: the study's own arm)
        const bool own_default = k.doc && !k.doc->default_words.empty();
        on = active && ((child_on && !own_default) || (k.doc && k.doc->init));
        if (!on && child_on) {
          children.clear();
          write(path, indent + "  ", false, children);
        }
      }
      std::string about = k.doc ? std::string(k.doc->meaning) : "";
      if (const std::string u = unit_of(k.info); !u.empty()) about += " Unit: " + u + ".";
      if (const std::string r = range_text(k.info); !r.empty()) about += " Range: " + r + ".";
      if (k.doc && !k.doc->default_words.empty())
        about += " Default: " + std::string(k.doc->default_words) + ".";
      else if (!k.info.default_text && !k.info.required && !on && !container)
        about += " Optional, no default.";
      if (k.info.kind == "list" && has_children(path)) {
        std::string items;
        for (const CaseKey& c : keys)
          if (parent_of(c.info.path) == path + "[]")
            items += (items.empty() ? "" : ", ") + c.info.path.substr(path.size() + 3);
        about += " Each item: " + items + " (docs/case-reference.md).";
      }
      text += comment_lines(about, indent);
      text += indent + (on ? "" : "# ") + name + ":" +
              (value && !value->empty() ? " " + *value : std::string()) + "\n";
      text += children;
      any_on = any_on || on;
    }
    return any_on;
  }
};

// the schema beside the templates: <prefix>/share/armstudy, or the source tree
std::string schema_location() {
  return (report::template_dir().parent_path() / "case.schema.json").string();
}

}  // namespace

std::string init_case(std::string_view study) {
  const std::vector<CaseKey> keys = case_keys(study);
  InitWriter w{keys, std::string(study), ""};
  w.out =
      "# yaml-language-server: $schema=" + schema_location() + "\n" +
      comment_lines("A " + std::string(study) +
                        " case with every key at its default (armstudy init " + std::string(study) +
                        "). A key left as a comment is optional and has no default: "
                        "remove the '# ' to set it. Every key: docs/case-reference.md.",
                    "") +
      "\n";
  w.write("", "", true, w.out);
  return w.out;
}

}  // namespace armstudy::app
