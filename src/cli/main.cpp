// armstudy: planar-arm studies from YAML case files to rendered reports.
//
// Exit codes: 0 done; 1 a study could not be solved or failed its own checks; 2 bad
// input or usage (case file errors, unknown options); 3 a runtime failure (rendering,
// writing output, an internal error).

#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <exception>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "cases/case_error.hpp"
#include "cli/pipeline.hpp"
#include "cli/progress.hpp"
#include "cli/run_case.hpp"
#include "version.hpp"

namespace {

using armstudy::app::LoadedCase;

constexpr int kExitDone = 0;
constexpr int kExitUnsolved = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitRuntime = 3;

// Loads every case; prints every error of every file; false if any failed.
bool load_all(const std::vector<std::string>& paths, std::vector<LoadedCase>* out) {
  bool ok = true;
  std::map<std::string, std::string> names;
  for (const std::string& p : paths) {
    try {
      LoadedCase c = armstudy::app::load_case(p);
      if (auto it = names.find(c.info.name); it != names.end()) {
        std::fprintf(stderr, "%s: case name '%s' is also the name of %s; expected unique names\n",
                     p.c_str(), c.info.name.c_str(), it->second.c_str());
        ok = false;
        continue;
      }
      names[c.info.name] = p;
      if (out) out->push_back(std::move(c));
    } catch (const armstudy::cases::CaseErrors& e) {
      std::fprintf(stderr, "%s\n", e.what());
      ok = false;
    }
  }
  return ok;
}

int cmd_validate(const std::vector<std::string>& paths) {
  std::vector<LoadedCase> cases;
  const bool ok = load_all(paths, &cases);
  for (const auto& c : cases)
    std::printf("ok: %s (study %s, case %s)\n", c.info.path.c_str(), c.info.study.c_str(),
                c.info.name.c_str());
  return ok ? kExitDone : kExitBadInput;
}

int cmd_run(const std::vector<std::string>& paths, const armstudy::app::RunOptions& options,
            int jobs) {
  std::vector<LoadedCase> cases;
  if (!load_all(paths, &cases)) {
    std::fprintf(stderr, "nothing was written: fix the case files above\n");
    return kExitBadInput;
  }
  armstudy::app::ProgressReporter progress(stderr, armstudy::app::stderr_is_terminal());
  std::atomic<size_t> next{0};
  std::mutex mu;
  int worst = kExitDone;
  auto worker = [&] {
    for (size_t i = next++; i < cases.size(); i = next++) {
      LoadedCase& c = cases[i];
      int code = kExitDone;
      std::string line;
      try {
        const auto o = armstudy::app::run_case(c, options, progress.task(c.info.name));
        code = o.exit_code;
        char secs[32];
        std::snprintf(secs, sizeof secs, "%.1f s", o.seconds);
        line = (code == 0 ? "done: " : "FAILED: ") + c.info.name + " (" + c.info.study + ", " +
               secs + ") -> " + o.folder.string() + (o.message.empty() ? "" : "\n  " + o.message);
      } catch (const std::exception& e) {
        code = kExitRuntime;
        line = "ERROR: " + c.info.name + ": " + e.what();
      }
      progress.line(line);
      std::lock_guard<std::mutex> lock(mu);
      worst = std::max(worst, code);
    }
  };
  const int n = std::clamp(jobs, 1, static_cast<int>(std::max<size_t>(1, cases.size())));
  std::vector<std::thread> pool;
  for (int k = 1; k < n; ++k) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  progress.finish();
  if (worst == kExitDone)
    std::fprintf(stderr, "all %zu case(s) done; output in %s\n", cases.size(),
                 options.out_dir.c_str());
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"armstudy: energy-optimal placement, throwing and time-optimal studies of planar "
               "robot arms, from YAML case files to MuJoCo-rendered reports"};
  app.set_version_flag("--version", std::string("armstudy ") + armstudy::kVersion);
  app.require_subcommand(1);
  std::string studies;
  for (const auto& e : armstudy::app::study_registry())
    studies += "\n  " + std::string(e.study) + ": " + std::string(e.summary);
  app.footer("Studies:" + studies +
             "\nExit codes: 0 done, 1 a study could not be solved or failed a check, 2 bad input "
             "or usage, 3 runtime failure (rendering, output, internal error).");

  std::vector<std::string> run_paths, validate_paths;
  armstudy::app::RunOptions options;
  std::string out_dir = "reports/out";
  bool no_render = false;
  int jobs = 1;
  auto* run = app.add_subcommand("run", "Solve, render and report case files");
  run->add_option("cases", run_paths, "Case files (YAML)")->required()->check(CLI::ExistingFile);
  run->add_option("--out", out_dir, "Output folder; each case goes to OUT/<case name>/")
      ->capture_default_str();
  run->add_flag("--no-render", no_render, "Skip MuJoCo frame rendering (everything else is made)");
  run->add_flag("--pdf", options.pdf, "Also print each report to report.pdf with headless Chromium");
  run->add_option("--jobs,-j", jobs, "Cases run in parallel")->check(CLI::Range(1, 64))
      ->capture_default_str();
  auto* validate = app.add_subcommand("validate", "Check case files without running them");
  validate->add_option("cases", validate_paths, "Case files (YAML)")->required();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help, version or the error
    return e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success) ? 0 : (code ? kExitBadInput : 0);
  }
  try {
    if (*validate) return cmd_validate(validate_paths);
    options.out_dir = out_dir;
    options.render = !no_render;
    return cmd_run(run_paths, options, jobs);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "armstudy: internal error: %s\n", e.what());
    return kExitRuntime;
  }
}
