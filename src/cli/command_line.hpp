// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// armstudy's command line: every command, its options and what the parse fills in
/// (cli/main.cpp runs the command given).

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "app/run_case.hpp"
#include "cli/diff.hpp"

namespace armstudy::cli {

/// Every option of every command, filled in by the parse.
struct Args {
  std::vector<std::string> run_paths, validate_paths;
  app::RunOptions options;
  std::string out_dir = app::kDefaultOutDir;
  bool no_render = false;
  bool no_sensitivity = false;
  bool run_json = false;
  int jobs = 1;
  std::string shard;
  bool force = false;
  bool allow_large = false;
  std::string sweep_file, sweep_out = "sweep-cases";
  std::vector<std::string> base_dirs;
  std::vector<std::string> list_items;
  bool list_json = false;
  std::vector<std::string> merge_dirs;
  std::string merge_out;
  std::string merge_manifest;
  DiffOptions diff_options;
  std::string diff_base, diff_new, diff_out = diff_options.out.string();
  std::string init_study, init_out;
};

/// The commands, to tell which one was given.
struct Commands {
  CLI::App *run = nullptr, *expand = nullptr, *list = nullptr, *merge = nullptr, *diff = nullptr,
           *validate = nullptr, *init = nullptr;
  CLI::Option *merge_out = nullptr, *run_out = nullptr;
};

/// armstudy itself: --version and the footer naming the studies and the exit codes.
void describe_app(CLI::App& app);

/// Every command and its options, in the order --help lists them, bound to `a`.
Commands add_commands(CLI::App& app, Args& a);

/// After a failed parse: the message naming the first option of the command line that no
/// command given has ("armstudy run: unknown option '--jobz' (did you mean '--jobs'?) ..."),
/// or "" when every option was known. CLI11 would otherwise report a later problem the
/// unknown option caused (its value taken for a case file: "Path does not exist: 2").
std::string unknown_option_message(const CLI::App& app);

}  // namespace armstudy::cli
