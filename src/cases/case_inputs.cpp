// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/case_inputs.hpp"

#include <yaml-cpp/yaml.h>

namespace armstudy::cases {
namespace {

// a scalar's text, a flow list of scalars, or "" for anything else
std::string flat_text(const YAML::Node& n) {
  if (n.IsScalar()) return n.Scalar();
  if (n.IsNull()) return "null";
  if (!n.IsSequence()) return "";
  std::string s = "[";
  for (size_t i = 0; i < n.size(); ++i) {
    if (!n[i].IsScalar()) return "";
    s += (i ? ", " : "") + n[i].Scalar();
  }
  return s + "]";
}

void flatten(const YAML::Node& n, const std::string& path, int depth,
             std::map<std::string, std::string>& out) {
  if (depth > 64) return;  // the loaders refuse deeper nesting (yaml_source.hpp)
  if (const std::string text = flat_text(n); !text.empty() || n.IsScalar()) {
    out[path] = text;
  } else if (n.IsMap()) {
    if (n.size() == 0) out[path] = "{}";
    for (const auto& kv : n) {
      const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
      flatten(kv.second, path.empty() ? key : path + "." + key, depth + 1, out);
    }
  } else if (n.IsSequence()) {
    if (n.size() == 0) out[path] = "[]";
    for (size_t i = 0; i < n.size(); ++i)
      flatten(n[i], path + "[" + std::to_string(i + 1) + "]", depth + 1, out);
  }
}

}  // namespace

std::map<std::string, std::string> case_inputs(const std::string& yaml_text) {
  std::map<std::string, std::string> out;
  try {
    flatten(YAML::Load(yaml_text), "", 0, out);
  } catch (const YAML::Exception&) {
    out.clear();
  }
  return out;
}

}  // namespace armstudy::cases
