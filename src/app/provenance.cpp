// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "app/provenance.hpp"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "cases/case_info.hpp"
#include "version.hpp"

namespace armstudy::app {
namespace fs = std::filesystem;

namespace {
std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(" \t", colon + 1));
    }
  }
  return "unknown";
}
}  // namespace

report::ProvenanceRecord provenance() {
  report::ProvenanceRecord p;
  p.armstudy_version = kVersion;
  if (*git_commit()) p.git_commit = git_commit();
  p.mujoco_version = mj_versionString();
#if defined(__clang__)
  p.compiler = std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  p.compiler = std::string("gcc ") + __VERSION__;
#else
  p.compiler = "unknown";
#endif
  p.cpu_model = cpu_model();
  return p;
}

std::vector<report::FileRecord> list_files(const fs::path& dir, const std::string& skip) {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files.push_back(fs::relative(e.path(), dir));
  std::sort(files.begin(), files.end());
  std::vector<report::FileRecord> out;
  for (const auto& rel : files) {
    if (rel.generic_string() == skip) continue;
    std::ifstream in(dir / rel, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    const std::string bytes = ss.str();
    out.push_back(
        {rel.generic_string(), static_cast<long long>(bytes.size()), cases::sha256_hex(bytes)});
  }
  return out;
}

}  // namespace armstudy::app
