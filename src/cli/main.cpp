// armstudy: planar-arm studies from YAML case files to rendered reports.
//
// Exit codes: 0 done; 1 a study could not be solved or failed its own checks; 2 bad
// input or usage (case file errors, unknown options); 3 a runtime failure (rendering,
// writing output, an internal error).

#include <CLI/CLI.hpp>

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/pipeline.hpp"
#include "app/run_case.hpp"
#include "app/run_order.hpp"
#include "cases/case_error.hpp"
#include "cases/input_file.hpp"
#include "cli/diff.hpp"
#include "cli/interrupt.hpp"
#include "cli/merge.hpp"
#include "cli/open_files.hpp"
#include "cli/process_memory.hpp"
#include "cli/progress.hpp"
#include "cli/sweep.hpp"
#include "report/case_report.hpp"
#include "report/sweep_report.hpp"
#include "scene/frame_worker.hpp"
#include "scene/frames.hpp"
#include "scene/model_files.hpp"
#include "scene/phase_times.hpp"
#include "scene/scene_error.hpp"
#include "version.hpp"

namespace {

using armstudy::app::LoadedCase;

constexpr int kExitDone = 0;
constexpr int kExitUnsolved = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitRuntime = 3;

std::vector<std::string> case_files(const std::vector<std::string>& items);

// Loads every case; prints every error of every file; false if any failed.
bool load_all(const std::vector<std::string>& paths, std::vector<LoadedCase>* out,
              bool allow_large = false) {
  bool ok = true;
  std::map<std::string, std::string> names;
  for (const std::string& p : paths) {
    try {
      LoadedCase c = armstudy::app::load_case(p, {allow_large});
      if (auto it = names.find(c.info.name); it != names.end()) {
        std::fprintf(stderr, "%s: case name '%s' is also the name of %s; expected unique names\n",
                     p.c_str(), c.info.name.c_str(), it->second.c_str());
        ok = false;
        continue;
      }
      if (const char* clash = armstudy::app::run_level_file(c.info.name)) {
        std::fprintf(stderr,
                     "%s: case name '%s' is the name of %s, which armstudy writes beside the "
                     "case folders; expected another name\n",
                     p.c_str(), c.info.name.c_str(), clash);
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

int cmd_validate(const std::vector<std::string>& paths, bool allow_large) {
  std::vector<LoadedCase> cases;
  const bool ok = load_all(paths, &cases, allow_large);
  for (const auto& c : cases)
    std::printf("ok: %s (study %s, case %s)\n", c.info.path.c_str(), c.info.study.c_str(),
                c.info.name.c_str());
  return ok ? kExitDone : kExitBadInput;
}

// why `out` cannot be an output folder ("" if it can): it is empty, or it or a folder
// above it is a file (a missing folder is made later)
std::string out_problem(const std::string& out) {
  if (out.empty()) return "--out is empty; expected a folder (made if missing)";
  for (std::filesystem::path p = out; !p.empty(); p = p.parent_path()) {
    std::error_code ec;
    const auto st = std::filesystem::status(p, ec);
    if (!std::filesystem::exists(st)) {
      if (p == p.parent_path()) break;
      continue;
    }
    if (std::filesystem::is_directory(st)) break;
    return "--out '" + out + "': " + (p == out ? "is" : "'" + p.string() + "' is") +
           " a file, not a folder; expected a folder (made if missing)";
  }
  return "";
}

// "I/N" with 0 <= I < N
bool parse_shard(const std::string& text, int* index, int* count) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) return false;
  try {
    size_t used = 0;
    *index = std::stoi(text.substr(0, slash), &used);
    if (used != slash) return false;
    *count = std::stoi(text.substr(slash + 1), &used);
    if (used != text.size() - slash - 1) return false;
  } catch (const std::exception&) {
    return false;
  }
  return *count >= 1 && *index >= 0 && *index < *count;
}

// true if out_dir/<name>/results.json is what this run would write again: the same case
// file contents, armstudy version and commit, and render option, and the case passed (a
// failed case is always redone). A missing report.pdf is printed by finish_reports.
// @throws cases::InputFileError when results.json is there but no regular file of at most
// kMaxResultsJsonBytes (a FIFO, a device, a link): nothing is run then
bool already_done(const std::filesystem::path& out_dir, const LoadedCase& c,
                  const armstudy::app::RunOptions& options) {
  const auto rj = out_dir / c.info.name / "results.json";
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(rj, ec))) return false;
  const std::string bytes = armstudy::cases::read_input_file(
      rj.string(), {armstudy::cases::kMaxResultsJsonBytes, "results.json file", false});
  try {
    const auto r =
        armstudy::report::read_record(nlohmann::json::parse(bytes));  // strict: else redone
    const std::string commit = armstudy::git_commit();
    return r.case_info.sha256 == c.info.sha256 && r.armstudy_version == armstudy::kVersion &&
           r.git_commit.value_or("") == commit && r.run_options.render == options.render &&
           armstudy::app::case_passed(r);
  } catch (const std::exception&) {
    return false;
  }
}

// the CPUs this process may run on
int available_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 1;
  return std::max(1, CPU_COUNT(&set));
}

int cmd_run(const std::vector<std::string>& paths, const armstudy::app::RunOptions& options,
            int jobs, const std::string& shard, bool force, bool allow_large) {
  std::vector<LoadedCase> cases;
  if (!load_all(paths, &cases, allow_large)) {
    std::fprintf(stderr, "nothing was written: fix the case files above\n");
    return kExitBadInput;
  }
  if (options.pdf && armstudy::report::find_chromium().empty()) {
    std::fprintf(stderr, "armstudy: %s; nothing was written\n",
                 armstudy::report::missing_chromium_text().c_str());
    return kExitRuntime;
  }
  // a stable subset: cases sorted by name, every N-th from I
  std::sort(cases.begin(), cases.end(),
            [](const LoadedCase& a, const LoadedCase& b) { return a.info.name < b.info.name; });
  if (!shard.empty()) {
    int index = 0, count = 1;
    if (!parse_shard(shard, &index, &count)) {
      std::fprintf(stderr, "--shard '%s': expected I/N with 0 <= I < N, e.g. 0/4\n", shard.c_str());
      return kExitBadInput;
    }
    std::vector<LoadedCase> mine;
    for (size_t i = 0; i < cases.size(); ++i)
      if (static_cast<int>(i % count) == index) mine.push_back(std::move(cases[i]));
    std::fprintf(stderr, "shard %d/%d: %zu of %zu case(s)\n", index, count, mine.size(),
                 cases.size());
    cases = std::move(mine);
  }
  // what killed runs on this host left behind (hidden temporary folders and files)
  {
    const auto stale = armstudy::app::remove_stale_outputs(options.out_dir);
    for (const auto& folder : stale.restored)
      std::fprintf(stderr, "put back %s, the earlier report a killed run had moved aside\n",
                   folder.c_str());
    if (stale.removed)
      std::fprintf(stderr, "removed %zu temporary folder(s) or file(s) of killed runs in %s\n",
                   stale.removed, options.out_dir.c_str());
  }
  if (!force) {
    std::vector<LoadedCase> todo;
    size_t skipped = 0;
    for (auto& c : cases) {
      try {
        if (already_done(options.out_dir, c, options))
          ++skipped;
        else
          todo.push_back(std::move(c));
      } catch (const armstudy::cases::InputFileError& e) {
        std::fprintf(stderr, "armstudy: %s\nnothing was run\n", e.what());
        return e.runtime() ? kExitRuntime : kExitBadInput;
      }
    }
    if (skipped)
      std::fprintf(stderr,
                   "skipped %zu case(s) whose output exists and passed for the same case "
                   "file, armstudy version and options (--force redoes them)\n",
                   skipped);
    cases = std::move(todo);
  }
  // with --pdf, one browser prints each case's page as soon as the case is in place
  armstudy::app::RunOptions case_options = options;
  std::unique_ptr<armstudy::report::PdfPrinter> printer;
  if (options.pdf && !cases.empty()) {
    printer = std::make_unique<armstudy::report::PdfPrinter>(std::max(1, jobs));
    case_options.printer = printer.get();
  }
  armstudy::app::ProgressReporter progress(stderr, armstudy::app::stderr_is_terminal());
  // the longest cases first, so that each core ends on a short one
  const std::vector<size_t> order = armstudy::app::longest_first(cases, options.render);
  std::atomic<size_t> next{0};
  std::mutex mu;
  int worst = kExitDone;
  auto worker = [&] {
    for (size_t i = next++; i < cases.size(); i = next++) {
      LoadedCase& c = cases[order[i]];
      int code = kExitDone;
      std::string line;
      try {
        const auto o = armstudy::app::run_case(c, case_options, progress.task(c.info.name));
        code = o.exit_code;
        char secs[32];
        std::snprintf(secs, sizeof secs, "%.1f s", o.seconds);
        line = (code == 0 ? "done: " : "FAILED: ") + c.info.name + " (" + c.info.study + ", " +
               secs + ") -> " + o.folder.string() + (o.message.empty() ? "" : "\n  " + o.message);
      } catch (const armstudy::scene::ModelError& e) {
        code = kExitBadInput;  // MuJoCo cannot load the arm the case describes
        line = "ERROR: " + c.info.name + " (" + c.info.path + "): " + e.what();
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
  // the cores a case has draw its frames, each core a process (scene/frame_worker.hpp)
  const int frame_processes = std::max(1, available_cores() / n);
  armstudy::scene::set_default_frame_processes(frame_processes);
  // this thread's helpers start now, their first scene drawn while the first case solves
  // (the other threads' start with their first strip)
  if (options.render)
    for (int k = 1; k < frame_processes; ++k)
      armstudy::scene::FrameWorker::prewarm(armstudy::scene::default_horizontal_scene(), {});
  std::vector<std::thread> pool;
  for (int k = 1; k < n; ++k) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  progress.finish();
  if (printer) {
    const auto t0 = std::chrono::steady_clock::now();
    printer->finish();  // the pages still printing
    if (armstudy::scene::phase_times_enabled())
      std::fprintf(stderr, "phase-times: waited %.3f s for the last pages after the cases\n",
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  // the page of all cases and, with --pdf, every case's report.pdf
  for (const auto& problem : armstudy::app::finish_reports(options, jobs)) {
    std::fprintf(stderr, "armstudy: %s\n", problem.c_str());
    worst = std::max(worst, kExitRuntime);
  }
  // what CI reads, over every case in the output folder (not only this run's)
  try {
    std::vector<std::string> warnings;
    const auto outputs = armstudy::app::collect_outputs({options.out_dir}, &warnings);
    armstudy::app::write_merged(outputs, options.out_dir);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "armstudy: cannot write summary.md/junit.xml: %s\n", e.what());
    worst = std::max(worst, kExitRuntime);
  }
  if (worst == kExitDone)
    std::fprintf(stderr, "all %zu case(s) done; output in %s\n", cases.size(),
                 options.out_dir.c_str());
  return worst;
}

int cmd_sweep_expand(const std::string& sweep_path, const std::string& out) {
  try {
    const auto sw = armstudy::app::load_sweep(sweep_path);
    std::fprintf(stderr, "sweep %s: %zu case(s); writing them to %s\n", sw.name.c_str(),
                 sw.points.size(), out.c_str());
    const size_t written = armstudy::app::expand_sweep(sw, out);
    std::fprintf(stderr, "sweep %s: %zu case(s), %zu file(s) written to %s\n", sw.name.c_str(),
                 sw.points.size(), written, out.c_str());
    return kExitDone;
  } catch (const armstudy::cases::CaseErrors& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  }
}

// case files (*.yaml) directly in each folder, or files given directly
std::vector<std::string> case_files(const std::vector<std::string>& items) {
  std::vector<std::string> files;
  for (const auto& it : items) {
    if (std::filesystem::is_directory(it)) {
      for (const auto& e : std::filesystem::directory_iterator(it))
        if (e.path().extension() == ".yaml") files.push_back(e.path().string());
    } else {
      files.push_back(it);
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

int cmd_list(const std::vector<std::string>& items, bool as_json) {
  std::vector<LoadedCase> cases;
  // listing judges no budget: a large case is listed for a run with --allow-large
  const bool ok = load_all(case_files(items), &cases, true);
  std::sort(cases.begin(), cases.end(),
            [](const LoadedCase& a, const LoadedCase& b) { return a.info.name < b.info.name; });
  if (as_json) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& c : cases)
      j.push_back({{"id", c.info.name},
                   {"study", c.info.study},
                   {"path", c.info.path},
                   {"sha256", c.info.sha256}});
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    for (const auto& c : cases) std::printf("%s\n", c.info.name.c_str());
  }
  return ok ? kExitDone : kExitBadInput;
}

int cmd_merge(const std::vector<std::string>& dirs, std::string out) {
  std::vector<std::filesystem::path> ds(dirs.begin(), dirs.end());
  bool missing = false;
  for (const auto& d : ds) {
    std::error_code ec;
    if (!std::filesystem::is_directory(d, ec)) {
      std::fprintf(stderr, "armstudy merge: %s: %s; expected an output folder of 'armstudy run'\n",
                   d.c_str(), std::filesystem::exists(d, ec) ? "not a folder" : "no such folder");
      missing = true;
    }
  }
  if (missing) {
    std::fprintf(stderr, "nothing was written\n");
    return kExitBadInput;
  }
  if (out.empty()) out = dirs.front();
  std::vector<std::string> warnings;
  std::vector<armstudy::app::CaseOutput> outputs;
  try {
    outputs = armstudy::app::collect_outputs(ds, &warnings);
  } catch (const armstudy::cases::InputFileError& e) {
    std::fprintf(stderr, "armstudy merge: %s\nnothing was written\n", e.what());
    return e.runtime() ? kExitRuntime : kExitBadInput;
  }
  for (const auto& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  const size_t failed = armstudy::app::write_merged(outputs, out);
  std::fprintf(stderr, "merged %zu case(s) into %s (%zu failed)\n", outputs.size(), out.c_str(),
               failed);
  // the pages: every case folder inside `out`, and the sweep's plots over its axes
  try {
    const nlohmann::json table = armstudy::app::sweep_json(outputs);
    if (!table["rows"].empty()) {
      std::string name = "sweep";
      for (const auto& o : outputs)
        if (o.record.case_info.sweep) {
          name = o.record.case_info.sweep->name;
          break;
        }
      const int plots =
          armstudy::report::write_sweep_report(std::filesystem::path(out) / "sweep", table, name);
      std::fprintf(stderr, "sweep report: %s/sweep/index.html (%d plot(s))\n", out.c_str(), plots);
    }
    armstudy::report::write_index(out, armstudy::app::index_studies());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "armstudy: cannot write the pages: %s\n", e.what());
    return kExitRuntime;
  }
  return failed ? kExitUnsolved : kExitDone;
}

}  // namespace

int main(int argc, char** argv) {
  armstudy::cli::keep_freed_memory();          // before any thread: see process_memory.hpp
  armstudy::app::install_interrupt_cleanup();  // first: every thread inherits its signal mask
  // a write to a pipe or socket whose reader is gone (a helper that died, a closed `| head`)
  // fails with EPIPE and is reported, instead of killing armstudy without a word
  std::signal(SIGPIPE, SIG_IGN);
  CLI::App app{
      "armstudy: energy-optimal placement, throwing and time-optimal studies of planar "
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
  run->add_option("cases", run_paths, "Case files (YAML), or folders of case files")
      ->required()
      ->check(CLI::ExistingPath);
  run->add_option("--out", out_dir, "Output folder; each case goes to OUT/<case name>/")
      ->capture_default_str();
  run->add_flag("--no-render", no_render, "Skip MuJoCo frame rendering (everything else is made)");
  run->add_flag("--pdf", options.pdf,
                "Also print each report to report.pdf with headless Chromium");
  run->add_option("--jobs,-j", jobs, "Cases run in parallel")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  std::string shard;
  bool force = false;
  run->add_option("--shard", shard,
                  "Run only shard I of N (0 <= I < N) of the cases sorted by name, e.g. 0/4");
  run->add_flag("--force", force,
                "Redo cases whose output already exists for the same case file (default: skip)");
  bool allow_large = false;
  const char* allow_large_help =
      "Run cases whose estimated work or memory is beyond the budget (docs/budgets.md)";
  run->add_flag("--allow-large", allow_large, allow_large_help);

  std::string sweep_file, sweep_out = "sweep-cases";
  auto* sweep = app.add_subcommand("sweep", "Parameter sweeps over a base case");
  sweep->require_subcommand(1);
  auto* expand = sweep->add_subcommand("expand", "Write one case file per sweep point");
  expand->add_option("sweep", sweep_file, "Sweep file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  expand->add_option("--out", sweep_out, "Folder for the generated case files")
      ->capture_default_str();

  std::vector<std::string> list_items;
  bool list_json = false;
  auto* list = app.add_subcommand("list", "Print the case ids of case files, in a stable order");
  list->add_option("dirs", list_items, "Folders of case files (or case files)")->required();
  list->add_flag("--json", list_json, "Print id, study, path and sha256 as JSON");

  std::vector<std::string> merge_dirs;
  std::string merge_out;
  auto* merge =
      app.add_subcommand("merge",
                         "Build index.html, summary.md, junit.xml, sweep tables and the sweep "
                         "report (sweep/index.html) from the results.json of output folders");
  merge->add_option("dirs", merge_dirs, "Output folders (DIR/<case>/results.json)")->required();
  auto* merge_out_option =
      merge->add_option("--out", merge_out, "Where to write (default: the first folder)");
  armstudy::app::DiffOptions diff_options;
  std::string diff_base, diff_new, diff_out = diff_options.out.string();
  auto* diff = app.add_subcommand(
      "diff",
      "What changed between two output folders of run or merge (diff.html, diff.md); exit 0 "
      "when nothing moved beyond its tolerance, 1 when something did, 2 on bad input");
  diff->add_option("base", diff_base, "The base output folder (e.g. the main branch's reports)")
      ->required();
  diff->add_option("new", diff_new, "The new output folder (e.g. the pull request's reports)")
      ->required();
  diff->add_option("--out", diff_out, "Where to write diff.html and diff.md")
      ->capture_default_str();
  diff->add_option(
      "--tolerances", diff_options.tolerances_file,
      "YAML file of tolerances per study and key figure (default: exact, run times ignored)");
  diff->add_option(
          "--pixel-tolerance", diff_options.pixel_tolerance,
          "A pixel differs when a channel differs by more than this (0-255; default 0 or the "
          "tolerances file's frames.channel)")
      ->check(CLI::Range(0, 255));
  diff->add_option(
      "--pixels", diff_options.pixels_allowed,
      "Pixels beyond the pixel tolerance a frame may have and still match (default 0 or "
      "frames.pixels)");
  auto* validate = app.add_subcommand("validate", "Check case files without running them");
  validate->add_option("cases", validate_paths, "Case files (YAML)")->required();
  validate->add_flag("--allow-large", allow_large, allow_large_help);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help, version or the error
    return e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)
               ? 0
               : (code ? kExitBadInput : 0);
  }
  // the output folder: "" or a file is bad usage, refused before anything is done
  const std::string* out_given = *run                                  ? &out_dir
                                 : *expand                             ? &sweep_out
                                 : *diff                               ? &diff_out
                                 : *merge && merge_out_option->count() ? &merge_out
                                                                       : nullptr;
  if (out_given) {
    if (const std::string why = out_problem(*out_given); !why.empty()) {
      std::fprintf(stderr, "armstudy: %s\n", why.c_str());
      return kExitBadInput;
    }
  }
  if (*run || *merge || *diff) {
    if (const std::string why = armstudy::cli::ensure_open_files(); !why.empty()) {
      std::fprintf(stderr, "armstudy: %s\n", why.c_str());
      return kExitRuntime;
    }
  }
  int code = kExitRuntime;
  try {
    if (*validate)
      code = cmd_validate(validate_paths, allow_large);
    else if (*expand)
      code = cmd_sweep_expand(sweep_file, sweep_out);
    else if (*list)
      code = cmd_list(list_items, list_json);
    else if (*merge)
      code = cmd_merge(merge_dirs, merge_out);
    else if (*diff) {
      diff_options.base = diff_base;
      diff_options.now = diff_new;
      diff_options.out = diff_out;
      code = armstudy::app::run_diff(diff_options);
    } else {
      options.out_dir = out_dir;
      options.render = !no_render;
      code = cmd_run(case_files(run_paths), options, jobs, shard, force, allow_large);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "armstudy: internal error: %s\n", e.what());
    code = kExitRuntime;
  }
  // every write to standard output checked: `list --json > /dev/full` is a failure
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::fprintf(stderr, "armstudy: cannot write to standard output: %s\n", std::strerror(errno));
    code = std::max(code, kExitRuntime);
  }
  return code;
}
