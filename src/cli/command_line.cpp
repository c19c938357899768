// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/command_line.hpp"

#include "app/pipeline.hpp"
#include "cases/yaml_reader.hpp"
#include "cli/command_examples.hpp"
#include "cli/version_text.hpp"

namespace armstudy::cli {
namespace {

constexpr const char* kAllowLargeHelp =
    "Run cases whose estimated work or memory is beyond the budget (docs/budgets.md)";

CLI::App* add_run(CLI::App& app, Args& a, CLI::Option** out_option) {
  auto* run = app.add_subcommand("run", "Solve, render and report case files");
  run->add_option("cases", a.run_paths, "Case files (YAML), or folders of case files")
      ->required()
      ->check(CLI::ExistingPath);
  *out_option =
      run->add_option("--out", a.out_dir,
                      "Output folder, made if missing; each case goes to OUT/<case name>/ (without "
                      "--out: armstudy-out in the current folder, named on stderr)")
          ->capture_default_str();
  run->add_flag("--no-render", a.no_render,
                "Skip MuJoCo frame rendering (everything else is made)");
  run->add_flag("--no-sensitivity", a.no_sensitivity,
                "Skip the re-solves of each case's sensitivity: part (docs/sensitivity.md)");
  run->add_flag("--pdf", a.options.pdf,
                "Also print each report to report.pdf with headless Chromium");
  run->add_flag("--json", a.run_json,
                "Print a JSON summary of the run on stdout (each case's result, exit code, "
                "seconds, folder and answer) instead of one line per case");
  run->add_option("--jobs,-j", a.jobs, "Cases run in parallel")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  run->add_option("--shard", a.shard,
                  "Run only shard I of N (0 <= I < N) of the cases sorted by name, e.g. 0/4");
  run->add_flag("--force", a.force,
                "Redo cases whose output already exists for the same case file (default: skip)");
  run->add_flag("--allow-large", a.allow_large, kAllowLargeHelp);
  return run;
}

// `sweep expand` (the command `sweep` has no other)
CLI::App* add_sweep_expand(CLI::App& app, Args& a) {
  auto* sweep = app.add_subcommand("sweep", "Parameter sweeps over a base case");
  sweep->require_subcommand(1);
  auto* expand = sweep->add_subcommand("expand", "Write one case file per sweep point");
  expand->add_option("sweep", a.sweep_file, "Sweep file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  expand->add_option("--out", a.sweep_out, "Folder for the generated case files")
      ->capture_default_str();
  expand
      ->add_option("--base-dir", a.base_dirs,
                   "A folder the sweep's base case may also be in (default: only the sweep "
                   "file's folder)")
      ->check(CLI::ExistingDirectory);
  return expand;
}

CLI::App* add_list(CLI::App& app, Args& a) {
  auto* list = app.add_subcommand("list", "Print the case ids of case files, in a stable order");
  list->add_option("dirs", a.list_items, "Folders of case files (or case files)")->required();
  list->add_flag("--json", a.list_json, "Print id, study, path and sha256 as JSON");
  return list;
}

CLI::App* add_merge(CLI::App& app, Args& a, CLI::Option** out_option) {
  auto* merge =
      app.add_subcommand("merge",
                         "Build index.html, summary.md, junit.xml, sweep tables and the sweep "
                         "report (sweep/index.html) from the results.json of output folders");
  merge->add_option("dirs", a.merge_dirs, "Output folders (DIR/<case>/results.json)")->required();
  *out_option =
      merge->add_option("--out", a.merge_out, "Where to write (default: the first folder)");
  merge->add_option("--manifest", a.merge_manifest,
                    "The sweep's sweep-manifest.json (default: one in a merged folder); a case "
                    "of the sweep without a result fails the merge");
  return merge;
}

CLI::App* add_diff(CLI::App& app, Args& a) {
  auto* diff = app.add_subcommand(
      "diff",
      "What changed between two output folders of run or merge (diff.html, diff.md); exit 0 "
      "when nothing moved beyond its tolerance, 1 when something did, 2 on bad input");
  diff->add_option("base", a.diff_base, "The base output folder (e.g. the main branch's reports)")
      ->required();
  diff->add_option("new", a.diff_new, "The new output folder (e.g. the pull request's reports)")
      ->required();
  diff->add_option("--out", a.diff_out, "Where to write diff.html and diff.md")
      ->capture_default_str();
  diff->add_option(
      "--tolerances", a.diff_options.tolerances_file,
      "YAML file of tolerances per study and key figure (default: exact, run times ignored)");
  diff->add_option(
          "--pixel-tolerance", a.diff_options.pixel_tolerance,
          "A pixel differs when a channel differs by more than this (0-255; default 0 or the "
          "tolerances file's frames.channel)")
      ->check(CLI::Range(0, 255));
  diff->add_option(
      "--pixels", a.diff_options.pixels_allowed,
      "Pixels beyond the pixel tolerance a frame may have and still match (default 0 or "
      "frames.pixels)");
  return diff;
}

CLI::App* add_validate(CLI::App& app, Args& a) {
  auto* validate = app.add_subcommand("validate", "Check case files without running them");
  validate->add_option("cases", a.validate_paths, "Case files (YAML)")->required();
  validate->add_flag("--allow-large", a.allow_large, kAllowLargeHelp);
  return validate;
}

CLI::App* add_init(CLI::App& app, Args& a) {
  auto* init = app.add_subcommand(
      "init", "Print a case of a study with every key at its default, each explained");
  std::string studies;
  for (const auto& e : app::study_registry())
    studies += (studies.empty() ? "" : ", ") + std::string(e.study);
  init->add_option("study", a.init_study, "The study: " + studies)->required();
  init->add_option("--out,-o", a.init_out,
                   "Write the case to this file instead of stdout (a file armstudy did not "
                   "write is never replaced)");
  return init;
}

}  // namespace

// armstudy itself: its description, --version and the footer naming the studies
void describe_app(CLI::App& app) {
  app.set_version_flag(
      "--version", [] { return version_text(); },
      "Print armstudy's version and commit, the versions of the libraries it "
      "runs with and the browser --pdf would use, and exit");
  app.require_subcommand(1);
  std::string studies;
  for (const auto& e : app::study_registry())
    studies += "\n  " + std::string(e.study) + ": " + std::string(e.summary);
  app.footer("Studies:" + studies +
             "\nExit codes: 0 done, 1 a study could not be solved or failed a check, 2 bad input "
             "or usage, 3 runtime failure (rendering, output, internal error).");
}

// every command and its options, in the order --help lists them
Commands add_commands(CLI::App& app, Args& a) {
  Commands c;
  c.run = add_run(app, a, &c.run_out);
  c.expand = add_sweep_expand(app, a);
  c.list = add_list(app, a);
  c.merge = add_merge(app, a, &c.merge_out);
  c.diff = add_diff(app, a);
  c.validate = add_validate(app, a);
  c.init = add_init(app, a);
  add_examples(app);
  return c;
}

// the options of `command` (--out, -j, ...), for messages
std::vector<std::string> option_names(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* o : command.get_options()) {
    for (const auto& n : o->get_lnames()) names.push_back("--" + n);
    for (const auto& n : o->get_snames()) names.push_back("-" + n);
  }
  return names;
}

std::string unknown_option_message(const CLI::App& app) {
  // the command given, deepest first: its own options, then its parents'
  const CLI::App* command = &app;
  std::string path = "armstudy";
  for (;;) {
    const auto subs = command->get_subcommands();
    if (subs.empty()) break;
    command = subs.front();
    path += " " + command->get_name();
  }
  for (const CLI::App* at = command; at; at = at->get_parent()) {
    for (const std::string& arg : at->remaining()) {
      if (arg.size() < 2 || arg[0] != '-' || (arg[1] >= '0' && arg[1] <= '9') || arg[1] == '.')
        continue;  // a value or a negative number, not an option
      const std::string name = arg.substr(0, arg.find('='));
      const std::vector<std::string> known = option_names(*command);
      std::string message = path + ": unknown option '" + name + "'";
      if (const auto c = cases::closest(name, known)) message += " (did you mean '" + *c + "'?)";
      std::string list;
      for (const auto& k : known)
        if (k != "--help" && k != "-h") list += (list.empty() ? "" : ", ") + k;
      if (!list.empty()) message += "; expected one of: " + list;
      return message + "\nRun with --help for more information.";
    }
  }
  return "";
}

}  // namespace armstudy::cli
