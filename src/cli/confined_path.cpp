// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/confined_path.hpp"

#include <system_error>

namespace armstudy::cli {
namespace fs = std::filesystem;

bool lies_inside(const fs::path& path, const fs::path& root) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(path), ec);
  if (ec) return false;
  const fs::path r = fs::weakly_canonical(fs::absolute(root), ec);
  if (ec) return false;
  auto pi = p.begin();
  for (auto ri = r.begin(); ri != r.end(); ++ri) {
    if (ri->empty()) continue;  // a trailing separator
    if (pi == p.end() || *pi != *ri) return false;
    ++pi;
  }
  return true;
}

std::string confined_problem(const fs::path& folder, const std::string& rel) {
  const std::string expected = "; expected a path relative to the case folder, inside it";
  if (rel.empty()) return "an empty path" + expected;
  const fs::path p(rel);
  if (p.is_absolute()) return "an absolute path" + expected;
  for (const auto& part : p)
    if (part == "..") return "a path with '..'" + expected;
  if (!lies_inside(folder / p, folder))
    return "a path through a symlink out of the case folder" + expected;
  return "";
}

}  // namespace armstudy::cli
