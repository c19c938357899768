// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/sweep_manifest.hpp"

#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <unordered_set>

#include <nlohmann/json.hpp>

#include "cases/yaml_source.hpp"

namespace armstudy::cli {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {
constexpr std::uintmax_t kMaxManifestBytes = 16u << 20;

// the ids a manifest may list: at least one, each a case name (letters, digits, '.', '_'
// or '-', as load_case.cpp checks a case's name: never "", "../x" or "/etc"), each once
void check_case_ids(const std::vector<std::string>& ids) {
  static const std::regex ok("[A-Za-z0-9][A-Za-z0-9._-]{0,99}");
  if (ids.empty()) throw std::runtime_error("\"cases\" is empty; expected the sweep's case ids");
  std::unordered_set<std::string> seen;
  for (const std::string& id : ids) {
    if (!std::regex_match(id, ok))
      throw std::runtime_error("\"cases\" holds '" + cases::brief(id) + "'" +
                               "; expected case names (letters, digits, '.', '_' or '-')");
    if (!seen.insert(id).second)
      throw std::runtime_error("\"cases\" lists '" + id + "' twice; expected each case once");
  }
}
}  // namespace

std::string manifest_text(const SweepManifest& m) {
  const json j = {{"armstudy_sweep_manifest", 1},
                  {"sweep", m.sweep},
                  {"sweep_file", m.sweep_file},
                  {"cases", m.cases}};
  return j.dump(1) + "\n";
}

std::optional<SweepManifest> read_manifest(const fs::path& path) {
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(path, ec);
  if (ec || st.type() == fs::file_type::not_found) return std::nullopt;
  const std::string where = path.string() + ": ";
  if (st.type() != fs::file_type::regular)
    throw std::runtime_error(where +
                             "not a regular file; expected the sweep manifest that "
                             "'armstudy sweep expand' writes");
  if (fs::file_size(path, ec) > kMaxManifestBytes || ec)
    throw std::runtime_error(where + "larger than 16 MiB; expected a sweep manifest");
  std::ifstream in(path, std::ios::binary);
  json j;
  try {
    j = json::parse(in);
  } catch (const json::exception&) {
    throw std::runtime_error(where + "not JSON; expected a sweep manifest");
  }
  SweepManifest m;
  try {
    if (!j.is_object() || j.value("armstudy_sweep_manifest", 0) != 1)
      throw std::runtime_error("no \"armstudy_sweep_manifest\": 1");
    m.sweep = j.at("sweep").get<std::string>();
    m.sweep_file = j.at("sweep_file").get<std::string>();
    m.cases = j.at("cases").get<std::vector<std::string>>();
    check_case_ids(m.cases);
  } catch (const std::exception& e) {
    throw std::runtime_error(where + "not a sweep manifest of this armstudy (" +
                             std::string(dynamic_cast<const json::exception*>(&e)
                                             ? "a key is missing or of the wrong type"
                                             : e.what()) +
                             ")");
  }
  return m;
}

bool generated_by_expand(const fs::path& path) {
  std::error_code ec;
  if (fs::symlink_status(path, ec).type() != fs::file_type::regular) return false;
  std::ifstream in(path, std::ios::binary);
  const std::string header = kGeneratedHeader;
  std::string head(header.size(), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  return in.gcount() == static_cast<std::streamsize>(head.size()) && head == header;
}

}  // namespace armstudy::cli
