// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
// Output-folder helpers shared by the e2e tests: a quick case under any name, and every
// entry under a folder with its bytes (to prove that a run left a user's files as they were).

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "testing/files.hpp"

namespace armstudy::testing {

/// placement-example-2 (a quick case) as `dir`/<name>.yaml, named `name`.
inline std::filesystem::path quick_case(const std::filesystem::path& dir, const std::string& name) {
  std::string text =
      slurp(std::filesystem::path(ARMSTUDY_SOURCE_DIR) / "reports/cases/placement-example-2.yaml");
  const size_t at = text.find("\nname: ");
  text.replace(at + 7, text.find('\n', at + 1) - at - 7, name);
  const std::filesystem::path p = dir / (name + ".yaml");
  std::ofstream(p) << text;
  return p;
}

/// Every entry under `dir` (hidden ones included, links not followed): a file with its
/// bytes, a link as "-> target", a folder as "/".
inline std::map<std::string, std::string> snapshot(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::map<std::string, std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = fs::relative(e.path(), dir).string();
    if (e.is_symlink())
      found[rel] = "-> " + fs::read_symlink(e.path()).string();
    else if (e.is_directory())
      found[rel] = "/";
    else
      found[rel] = slurp(e.path());
  }
  return found;
}

}  // namespace armstudy::testing
