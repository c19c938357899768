// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
// File helpers shared by the tests: the source tree, read or write a whole file, make a fresh
// temporary folder. Test files use these instead of helpers of their own of the same name, so
// that a folder's files compile together in unity batches (cmake/unity_build.cmake).

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

namespace armstudy::testing {

/// The source tree (the ARMSTUDY_SOURCE_DIR the test targets define).
inline const std::filesystem::path kSource = ARMSTUDY_SOURCE_DIR;

/// The bytes of `p` ("" when it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// `text` as the whole of `p` (replaced if it exists).
inline void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << text;
}

/// `armstudy_<name>_<pid>` under the system's temporary folder. The process id keeps two test
/// runs apart (scripts/test.sh runs the sanitizer tier beside the Release suite, and a fixed
/// name let one run remove the other's folder mid-test).
inline std::filesystem::path temp_path(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("armstudy_" + name + "_" + std::to_string(::getpid()));
}

/// An empty folder temp_path(name) (removed first).
inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path d = temp_path(name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace armstudy::testing
