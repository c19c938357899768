#pragma once
// File helpers shared by the tests: read a whole file, make a fresh temporary folder.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace armstudy::testing {

/// The bytes of `p` ("" when it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// An empty folder `armstudy_<name>` under the system's temporary folder (removed first).
inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path d = std::filesystem::temp_directory_path() / ("armstudy_" + name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace armstudy::testing
