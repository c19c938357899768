// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/run_refusal.hpp"

#include <cstdio>
#include <mutex>
#include <string_view>

#include <nlohmann/json.hpp>

namespace armstudy::cli {
namespace {

std::mutex g_mu;
std::string g_said;  // every refusal said, one per line

}  // namespace

void say_refusal(const std::string& text) {
  std::fprintf(stderr, "%s\n", text.c_str());
  keep_refusal(text);
}

void keep_refusal(const std::string& text) {
  std::lock_guard<std::mutex> lock(g_mu);
  g_said += text + "\n";
}

bool run_json_requested(int argc, const char* const* argv) {
  bool run = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--") break;  // the rest are case files
    if (!run) {
      if (!arg.starts_with("-")) {
        if (arg != "run") return false;  // another command
        run = true;
      }
      continue;
    }
    if (arg == "--json") return true;
  }
  return false;
}

std::string refusal_json(const std::string& out_dir, int exit_code) {
  std::string error;
  {
    std::lock_guard<std::mutex> lock(g_mu);
    error = g_said;
  }
  while (!error.empty() && error.back() == '\n') error.pop_back();
  if (error.empty()) error = "the run stopped before any case ran (see stderr)";
  const nlohmann::json j = {{"out", out_dir},
                            {"exit_code", exit_code},
                            {"error", error},
                            {"cases", nlohmann::json::array()},
                            {"skipped", nlohmann::json::array()}};
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace armstudy::cli
