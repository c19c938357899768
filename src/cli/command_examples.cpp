// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/command_examples.hpp"

#include <string>
#include <utility>
#include <vector>

namespace armstudy::cli {
namespace {

// a command path ("" for armstudy, "sweep expand") and its examples: "# what" then the command
const std::vector<std::pair<std::string, std::vector<const char*>>>& examples() {
  static const std::vector<std::pair<std::string, std::vector<const char*>>> table = {
      {"",
       {"# Start a case of your own, check it, run it", "armstudy init placement -o my-arm.yaml",
        "armstudy validate my-arm.yaml", "armstudy run my-arm.yaml --out /tmp/out"}},
      {"init",
       {"# Print a commented placement case with every key at its default",
        "armstudy init placement", "# Write a throwing case to a file, then run it",
        "armstudy init throwing -o throw.yaml && armstudy run throw.yaml --out /tmp/out"}},
      {"run",
       {"# Solve, render and report a bundled case into /tmp/out/placement-example-2/",
        "armstudy run /usr/share/doc/armstudy/examples/cases/placement-example-2.yaml --out "
        "/tmp/out",
        "# Every case of a folder, two at a time, each report also as a PDF",
        "armstudy run cases/ --out reports --jobs 2 --pdf",
        "# In CI: no frames, a machine-readable summary on standard output",
        "armstudy run cases/*.yaml --out reports --no-render --json > summary.json"}},
      {"sweep",
       {"# One case file per point of a sweep, then run them",
        "armstudy sweep expand link-ratio.yaml --out sweep-cases && armstudy run sweep-cases "
        "--out sweep-out"}},
      {"sweep expand",
       {"# One case file per point of a sweep, into sweep-cases/",
        "armstudy sweep expand link-ratio.yaml --out sweep-cases",
        "# A sweep whose base case lies in another folder",
        "armstudy sweep expand sweeps/link-ratio.yaml --base-dir cases --out sweep-cases"}},
      {"list",
       {"# The case ids of a folder, in the order shards split them", "armstudy list sweep-cases",
        "# With study, path and sha256, as JSON", "armstudy list --json sweep-cases"}},
      {"merge",
       {"# The pages of four shards' output folders, written into the first",
        "armstudy merge shard-0 shard-1 shard-2 shard-3",
        "# Into a folder of its own, checked against the sweep's manifest",
        "armstudy merge shard-* --out all --manifest sweep-cases/sweep-manifest.json"}},
      {"diff",
       {"# What moved between the main branch's reports and a pull request's",
        "armstudy diff main-reports pr-reports --out diff",
        "# Within tolerances per study and key figure",
        "armstudy diff main-reports pr-reports --out diff --tolerances diff-tolerances.yaml"}},
      {"validate",
       {"# Check case files without running them",
        "armstudy validate /usr/share/doc/armstudy/examples/cases/*.yaml",
        "# A case beyond the work budget, checked all the same",
        "armstudy validate --allow-large big.yaml"}},
  };
  return table;
}

// the command at `path` ("sweep expand"), or nullptr
CLI::App* command_at(CLI::App& app, const std::string& path) {
  CLI::App* at = &app;
  size_t begin = 0;
  while (at && begin < path.size()) {
    size_t end = path.find(' ', begin);
    if (end == std::string::npos) end = path.size();
    const std::string name = path.substr(begin, end - begin);
    CLI::App* parent = at;
    at = nullptr;
    for (CLI::App* sub : parent->get_subcommands([](const CLI::App*) { return true; }))
      if (sub->get_name() == name) at = sub;
    begin = end + 1;
  }
  return at;
}

}  // namespace

void add_examples(CLI::App& app) {
  for (const auto& [path, lines] : examples()) {
    CLI::App* command = command_at(app, path);
    if (!command) continue;  // a command this build does not have
    std::string text = command->get_footer();
    text += std::string(text.empty() ? "" : "\n") + "Examples:";
    for (const char* line : lines) text += std::string("\n  ") + line;
    command->footer(text);
  }
}

}  // namespace armstudy::cli
