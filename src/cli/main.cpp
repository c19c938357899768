// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
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
#include <new>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/pipeline.hpp"
#include "app/run_case.hpp"
#include "app/run_order.hpp"
#include "cases/budget.hpp"
#include "cases/case_error.hpp"
#include "cases/case_info.hpp"
#include "cases/input_file.hpp"
#include "cli/command_line.hpp"
#include "cli/confined_path.hpp"
#include "cli/diff.hpp"
#include "cli/init_command.hpp"
#include "cli/interrupt.hpp"
#include "cli/merge.hpp"
#include "cli/open_files.hpp"
#include "cli/process_memory.hpp"
#include "cli/progress.hpp"
#include "cli/run_refusal.hpp"
#include "cli/sweep.hpp"
#include "cli/sweep_manifest.hpp"
#include "cli/version_text.hpp"
#include "report/case_report.hpp"
#include "report/owned_output.hpp"
#include "report/sweep_report.hpp"
#include "report/text_escape.hpp"
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
        armstudy::cli::say_refusal(p + ": case name '" + c.info.name + "' is also the name of " +
                                   it->second + "; expected unique names");
        ok = false;
        continue;
      }
      if (const char* clash = armstudy::cli::run_level_file(c.info.name)) {
        armstudy::cli::say_refusal(p + ": case name '" + c.info.name + "' is the name of " + clash +
                                   ", which armstudy writes beside the case folders; expected "
                                   "another name");
        ok = false;
        continue;
      }
      names[c.info.name] = p;
      if (out) out->push_back(std::move(c));
    } catch (const armstudy::cases::CaseErrors& e) {
      armstudy::cli::say_refusal(e.what());
      ok = false;
    }
  }
  return ok;
}

int cmd_validate(const std::vector<std::string>& paths, bool allow_large) {
  std::vector<LoadedCase> cases;
  const bool ok = load_all(paths, &cases, allow_large);
  for (const auto& c : cases)
    std::printf("ok: %s (study %s, case %s)\n",
                armstudy::report::terminal_text(c.info.path).c_str(), c.info.study.c_str(),
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

// every file results.json lists is there, in the case folder, a regular file of its size,
// and (up to 4 MiB each, where hashing is cheap) of its sha256
bool listed_files_intact(const std::filesystem::path& folder,
                         const armstudy::report::ResultsRecord& r) {
  namespace fs = std::filesystem;
  constexpr long long kHashedBytes = 4ll << 20;
  std::vector<std::string> frames = r.frames;
  for (const auto& f : r.files) {
    if (!armstudy::cli::confined_problem(folder, f.path).empty()) return false;
    std::error_code ec;
    const fs::path p = folder / f.path;
    if (!fs::is_regular_file(p, ec) || static_cast<long long>(fs::file_size(p, ec)) != f.bytes ||
        ec)
      return false;
    if (f.bytes <= kHashedBytes) {
      std::ifstream in(p, std::ios::binary);
      std::ostringstream ss;
      ss << in.rdbuf();
      if (armstudy::cases::sha256_hex(ss.str()) != f.sha256) return false;
    }
  }
  for (const auto& f : r.frames) {
    std::error_code ec;
    if (!armstudy::cli::confined_problem(folder, f).empty() || !fs::is_regular_file(folder / f, ec))
      return false;
  }
  return true;
}

// true if out_dir/<name>/results.json is what this run would write again: the same case
// file contents, armstudy version and commit, and render option, the case passed (a
// failed case is always redone) and the files it lists are intact. A missing report.pdf is
// printed by finish_reports. @throws cases::InputFileError when results.json is there but
// no regular file of at most kMaxResultsJsonBytes (a FIFO, a device, a link): nothing is
// run then
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
           // its sensitivity part as this run would write it (none with --no-sensitivity)
           r.sensitivity.has_value() ==
               (options.sensitivity && !c.info.sensitivity.empty() && r.solved()) &&
           armstudy::cli::case_passed(r) && listed_files_intact(out_dir / c.info.name, r);
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

// the run-level outputs a run (or, with `sweep_report`, a merge) writes in its folder; the
// sweep tables only where there are sweep points
std::vector<std::string> run_level_names(bool sweep_report, bool sweep_tables) {
  std::vector<std::string> figures;
  for (const auto& st : armstudy::app::index_studies())
    if (st.figure.draw) figures.emplace_back(st.figure.file);
  std::vector<std::string> names;
  for (const std::string& n : armstudy::report::run_level_outputs(figures))
    if ((n != "sweep" || sweep_report) && (!n.starts_with("sweep.") || sweep_tables))
      names.push_back(n);
  return names;
}

// prints each entry of `out_dir` armstudy would replace but did not write; true if any
bool refuse_foreign_outputs(const std::filesystem::path& out_dir,
                            const std::vector<std::string>& cases,
                            const std::vector<std::string>& run_level) {
  const auto foreign = armstudy::report::foreign_outputs(out_dir, cases, run_level);
  for (const std::string& f : foreign) armstudy::cli::say_refusal("armstudy: " + f);
  if (!foreign.empty())
    armstudy::cli::say_refusal(
        "nothing was written: armstudy replaces only what it wrote; move these away or choose "
        "another --out");
  return !foreign.empty();
}

// the manifest of the sweep whose case folder is run, copied into the output folder, where
// merge finds it (an earlier sweep's is replaced; a file armstudy did not write is not)
int copy_manifest(const std::vector<std::string>& run_paths, const std::filesystem::path& out) {
  namespace fs = std::filesystem;
  for (const auto& p : run_paths) {
    if (!fs::is_directory(p)) continue;
    try {
      const auto m = armstudy::cli::read_manifest(fs::path(p) / armstudy::cli::kManifestName);
      if (!m) continue;
      const fs::path dst = out / armstudy::cli::kManifestName;
      armstudy::cli::read_manifest(dst);  // throws for a file that is not a manifest
      fs::create_directories(out);
      armstudy::app::write_file_atomic(dst, armstudy::cli::manifest_text(*m));
      return kExitDone;
    } catch (const std::runtime_error& e) {
      armstudy::cli::say_refusal("armstudy: " + armstudy::report::terminal_text(e.what()) +
                                 "; nothing was written");
      return kExitBadInput;
    }
  }
  return kExitDone;
}

// sorts the cases by name and keeps the shard's stable subset, every N-th from I (--shard
// I/N; all when empty); false, having said why, when the shard is not I/N
bool take_shard(const std::string& shard, std::vector<LoadedCase>* all) {
  std::vector<LoadedCase>& cases = *all;
  std::sort(cases.begin(), cases.end(),
            [](const LoadedCase& a, const LoadedCase& b) { return a.info.name < b.info.name; });
  if (!shard.empty()) {
    int index = 0, count = 1;
    if (!parse_shard(shard, &index, &count)) {
      armstudy::cli::say_refusal("--shard '" + shard + "': expected I/N with 0 <= I < N, e.g. 0/4");
      return false;
    }
    std::vector<LoadedCase> mine;
    for (size_t i = 0; i < cases.size(); ++i)
      if (static_cast<int>(i % count) == index) mine.push_back(std::move(cases[i]));
    std::fprintf(stderr, "shard %d/%d: %zu of %zu case(s)\n", index, count, mine.size(),
                 cases.size());
    cases = std::move(mine);
  }
  return true;
}

// removes what killed runs left in the output folder and says what it did
void report_stale_outputs(const std::filesystem::path& out_dir) {
  const auto stale = armstudy::app::remove_stale_outputs(out_dir);
  for (const auto& folder : stale.restored)
    std::fprintf(stderr, "put back %s, the earlier report a killed run had moved aside\n",
                 folder.c_str());
  if (stale.removed)
    std::fprintf(stderr, "removed %zu temporary folder(s) or file(s) of killed runs in %s\n",
                 stale.removed, out_dir.c_str());
}

// drops the cases whose output exists and passed for the same case file, version and
// options; -1, or the exit code when a case file cannot be read
int skip_done_cases(std::vector<LoadedCase>* all, const armstudy::app::RunOptions& options,
                    std::vector<std::string>* skipped_names) {
  std::vector<LoadedCase>& cases = *all;
  std::vector<LoadedCase> todo;
  size_t skipped = 0;
  for (auto& c : cases) {
    try {
      if (already_done(options.out_dir, c, options)) {
        ++skipped;
        skipped_names->push_back(c.info.name);
      } else
        todo.push_back(std::move(c));
    } catch (const armstudy::cases::InputFileError& e) {
      armstudy::cli::say_refusal("armstudy: " + std::string(e.what()) + "\nnothing was run");
      return e.runtime() ? kExitRuntime : kExitBadInput;
    }
  }
  if (skipped)
    std::fprintf(stderr,
                 "skipped %zu case(s) whose output exists and passed for the same case "
                 "file, armstudy version and options (--force redoes them)\n",
                 skipped);
  cases = std::move(todo);
  return -1;
}

// what one case's run ended with: its exit code, its line for the terminal (the answer, for
// stdout, unless the run ended in an error: then the error, for stderr) and its entry of
// run --json
struct CaseEnd {
  int code = kExitDone;
  std::string line, error;
  nlohmann::json summary;
};

// runs one case, turning every error into its exit code and line; `need` is its memory
// estimate (named in the out-of-memory error)
CaseEnd run_one_case(LoadedCase& c, const armstudy::app::RunOptions& case_options,
                     armstudy::cli::ProgressReporter& progress, double need) {
  int code = kExitDone;
  std::string line, error;
  const std::string name = armstudy::report::terminal_text(c.info.name);
  nlohmann::json summary = {{"name", c.info.name}, {"study", c.info.study}, {"path", c.info.path}};
  try {
    const auto o = armstudy::app::run_case(c, case_options, progress.task(c.info.name));
    code = o.exit_code;
    char secs[32];
    std::snprintf(secs, sizeof secs, "%.1f s", o.seconds);
    // one line: the verdict, the case, where its report is, then the answer
    line = (code == 0 ? "done: " : "FAILED: ") + name + " (" + c.info.study + ", " + secs + ", " +
           o.folder.string() + ")" +
           (o.message.empty() ? "" : ": " + armstudy::report::terminal_text(o.message));
    summary.update({{"result", code == 0 ? "done" : "failed"},
                    {"exit_code", code},
                    {"seconds", o.seconds},
                    {"folder", o.folder.string()},
                    {"message", o.message}});
    return {code, line, "", summary};
  } catch (const armstudy::report::ForeignOutput& e) {
    code = kExitBadInput;  // a user's folder of the case's name appeared during the run
    error = e.what();
    line = "ERROR: " + name + ": " + armstudy::report::terminal_lines(error);
  } catch (const armstudy::scene::ModelError& e) {
    code = kExitBadInput;  // MuJoCo cannot load the arm the case describes
    error = e.what();
    line = "ERROR: " + name + " (" + c.info.path + "): " + armstudy::report::terminal_lines(error);
  } catch (const std::bad_alloc&) {
    code = kExitRuntime;
    error = "out of memory: the case's estimate is " + armstudy::cases::bytes_text(need) +
            " and the run's memory budget of " +
            armstudy::cases::bytes_text(armstudy::cases::kMemoryBudgetBytes) +
            " covers all its jobs (docs/budgets.md); run it with fewer --jobs or on a "
            "machine with more free memory";
    line = "ERROR: " + name + ": " + error;
  } catch (const std::exception& e) {
    code = kExitRuntime;
    error = e.what();
    line = "ERROR: " + name + ": " + armstudy::report::terminal_lines(error);
  }
  summary.update({{"result", "error"}, {"exit_code", code}, {"message", error}});
  return {code, line, error, summary};
}

// runs the cases on `jobs` threads, the longest first, each starting when its memory estimate
// fits the run's budget; the worst exit code; the cases that ended in an error in *errored
// (each case's answer on stdout; with --json, *summaries an array, its entry there instead)
int run_cases(std::vector<LoadedCase>& cases, const armstudy::app::RunOptions& options,
              const armstudy::app::RunOptions& case_options, int jobs,
              armstudy::cli::ProgressReporter& progress,
              std::vector<armstudy::cli::CaseOutput>* errored, nlohmann::json* summaries) {
  // the longest cases first, so that each core ends on a short one
  const std::vector<size_t> order =
      armstudy::app::longest_first(cases, options.render, options.sensitivity);
  std::atomic<size_t> next{0};
  std::mutex mu;
  int worst = kExitDone;
  // the run's memory budget covers all its jobs: a case starts when its estimate fits
  // beside the running ones' (a case beyond it alone, with --allow-large, runs alone)
  armstudy::app::MemoryGate memory(armstudy::cases::kMemoryBudgetBytes);
  auto worker = [&] {
    for (size_t i = next++; i < cases.size(); i = next++) {
      LoadedCase& c = cases[order[i]];
      const double need = armstudy::app::estimated_memory_bytes(c, options.render);
      memory.acquire(need);
      const CaseEnd end = run_one_case(c, case_options, progress, need);
      memory.release(need);
      // the answer on stdout (stderr when stdout is the --json summary); an error on stderr
      progress.line(end.line, end.error.empty() && summaries->is_null() ? stdout : stderr);
      std::lock_guard<std::mutex> lock(mu);
      if (!summaries->is_null()) summaries->push_back(end.summary);
      worst = std::max(worst, end.code);
      if (!end.error.empty())
        errored->push_back(armstudy::cli::failed_output(options.out_dir / c.info.name, c.info.name,
                                                        c.info.study, "error",
                                                        "the run ended in an error: " + end.error));
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
  return worst;
}

// summary.md and junit.xml over every case in the output folder (not only this run's), an
// errored case failed whatever an earlier run left in its folder; the worst exit code
int write_summaries(const std::filesystem::path& out_dir,
                    std::vector<armstudy::cli::CaseOutput> errored) {
  int worst = kExitDone;
  try {
    std::vector<std::string> warnings;
    auto outputs = armstudy::cli::collect_outputs({out_dir}, &warnings);
    // an errored case is failed, whatever an earlier run left in its folder
    for (auto& e : errored) {
      const auto it = std::find_if(outputs.begin(), outputs.end(), [&](const auto& o) {
        return o.record.case_info.name == e.record.case_info.name;
      });
      if (it != outputs.end())
        *it = std::move(e);
      else
        outputs.push_back(std::move(e));
    }
    std::sort(outputs.begin(), outputs.end(), [](const auto& a, const auto& b) {
      return a.record.case_info.name < b.record.case_info.name;
    });
    armstudy::cli::write_merged(outputs, out_dir);
  } catch (const armstudy::report::ForeignOutput& e) {
    std::fprintf(stderr, "armstudy: %s\n", armstudy::report::terminal_text(e.what()).c_str());
    worst = std::max(worst, kExitBadInput);
  } catch (const armstudy::cli::InputLimitError& e) {
    std::fprintf(stderr, "armstudy: no summary.md/junit.xml written: %s\n",
                 armstudy::report::terminal_text(e.what()).c_str());
    worst = std::max(worst, kExitBadInput);
  } catch (const armstudy::cases::InputFileError& e) {
    // a results.json in another folder of --out that is a FIFO, a device or a link
    std::fprintf(stderr, "armstudy: no summary.md/junit.xml written: %s\n",
                 armstudy::report::terminal_text(e.what()).c_str());
    worst = std::max(worst, e.runtime() ? kExitRuntime : kExitBadInput);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "armstudy: cannot write summary.md/junit.xml: %s\n", e.what());
    worst = std::max(worst, kExitRuntime);
  }
  return worst;
}

// whether run --json printed its summary (else main prints why no case ran)
bool g_run_json_printed = false;

// run --json: the run's summary on stdout, one JSON document (the cases sorted by name)
void print_run_json(const std::filesystem::path& out_dir, int exit_code, nlohmann::json cases,
                    const std::vector<std::string>& skipped) {
  std::sort(cases.begin(), cases.end(), [](const nlohmann::json& a, const nlohmann::json& b) {
    return a["name"].get<std::string>() < b["name"].get<std::string>();
  });
  const nlohmann::json j = {{"out", out_dir.string()},
                            {"exit_code", exit_code},
                            {"cases", std::move(cases)},
                            {"skipped", skipped},
                            {"summary_md", (out_dir / "summary.md").string()},
                            {"junit_xml", (out_dir / "junit.xml").string()},
                            {"index_html", (out_dir / "index.html").string()}};
  std::printf("%s\n", j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
  g_run_json_printed = true;
}

// `armstudy run`: load, shard, refuse foreign outputs, skip done cases, run, print and
// summarise (over 60 lines: the steps of a run in their order, each a call or a message)
int cmd_run(const std::vector<std::string>& paths, const armstudy::app::RunOptions& options,
            int jobs, const std::string& shard, bool force, bool allow_large,
            const std::vector<std::string>& run_paths, bool json) {
  std::vector<LoadedCase> cases;
  if (!load_all(paths, &cases, allow_large)) {
    armstudy::cli::say_refusal("nothing was written: fix the case files above");
    return kExitBadInput;
  }
  if (options.pdf && armstudy::report::find_chromium().empty()) {
    armstudy::cli::say_refusal("armstudy: " + armstudy::report::missing_chromium_text() +
                               "; nothing was written");
    return kExitRuntime;
  }
  // the report templates, read before anything is solved (a FIFO or a device among them)
  try {
    armstudy::report::check_templates();
  } catch (const armstudy::cases::InputFileError& e) {
    armstudy::cli::say_refusal("armstudy: " + armstudy::report::terminal_text(e.what()) +
                               "; nothing was run");
    return e.runtime() ? kExitRuntime : kExitBadInput;
  }
  // a stable subset: cases sorted by name, every N-th from I
  if (!take_shard(shard, &cases)) return kExitBadInput;
  // never over a folder or file armstudy did not write: a user's folder of a case's name,
  // a foreign index.html or summary.md (report/owned_output.hpp); nothing is written then
  std::vector<std::string> names;
  bool sweep_points = false;
  for (const auto& c : cases) {
    names.push_back(c.info.name);
    sweep_points |= !c.info.sweep_name.empty();
  }
  if (refuse_foreign_outputs(options.out_dir, names, run_level_names(false, sweep_points)))
    return kExitBadInput;
  if (const int code = copy_manifest(run_paths, options.out_dir); code != kExitDone) return code;
  // what killed runs on this host left behind (hidden temporary folders and files)
  report_stale_outputs(options.out_dir);
  std::vector<std::string> skipped;
  if (!force)
    if (const int code = skip_done_cases(&cases, options, &skipped); code >= 0) return code;
  // with --pdf, one browser prints each case's page as soon as the case is in place
  armstudy::app::RunOptions case_options = options;
  std::unique_ptr<armstudy::report::PdfPrinter> printer;
  if (options.pdf && !cases.empty()) {
    printer = std::make_unique<armstudy::report::PdfPrinter>(std::max(1, jobs));
    case_options.printer = printer.get();
  }
  armstudy::cli::ProgressReporter progress(stderr, armstudy::cli::stderr_is_terminal());
  // cases that ended in an error wrote no results.json: they are failed cases in summary.md
  // and junit.xml all the same
  std::vector<armstudy::cli::CaseOutput> errored;
  nlohmann::json summaries = json ? nlohmann::json::array() : nlohmann::json();
  int worst = run_cases(cases, options, case_options, jobs, progress, &errored, &summaries);
  progress.finish();
  if (printer) {
    const auto t0 = std::chrono::steady_clock::now();
    printer->finish();  // the pages still printing
    if (armstudy::scene::phase_times_enabled())
      std::fprintf(stderr, "phase-times: waited %.3f s for the last pages after the cases\n",
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  // the page of all cases and, with --pdf, every case's report.pdf
  for (const auto& problem : armstudy::app::finish_reports(options, jobs, names)) {
    std::fprintf(stderr, "armstudy: %s\n", problem.c_str());
    worst = std::max(worst, kExitRuntime);
  }
  // what CI reads, over every case in the output folder (not only this run's)
  worst = std::max(worst, write_summaries(options.out_dir, std::move(errored)));
  if (worst == kExitDone)
    std::fprintf(stderr, "all %zu case(s) done; output in %s\n", cases.size(),
                 options.out_dir.c_str());
  if (json) print_run_json(options.out_dir, worst, std::move(summaries), skipped);
  return worst;
}

int cmd_sweep_expand(const std::string& sweep_path, const std::string& out,
                     const std::vector<std::string>& base_dirs) {
  try {
    const auto sw = armstudy::cli::load_sweep(
        sweep_path, std::vector<std::filesystem::path>(base_dirs.begin(), base_dirs.end()));
    std::fprintf(stderr, "sweep %s: %zu case(s); writing them to %s\n", sw.name.c_str(),
                 sw.points.size(), out.c_str());
    const auto r = armstudy::cli::expand_sweep(sw, out);
    for (const auto& id : r.removed)
      std::fprintf(stderr, "removed %s.yaml: no longer a point of the sweep\n", id.c_str());
    std::fprintf(stderr, "sweep %s: %zu case(s), %zu file(s) written to %s\n", sw.name.c_str(),
                 sw.points.size(), r.written, out.c_str());
    return kExitDone;
  } catch (const armstudy::cases::CaseErrors& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  } catch (const armstudy::cli::ExpandRefused& e) {
    std::fprintf(stderr, "armstudy sweep expand: %s\n", e.what());
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

// says which of the folders to merge are missing or not folders; false when any is
bool merge_folders_exist(const std::vector<std::filesystem::path>& ds) {
  bool missing = false;
  for (const auto& d : ds) {
    std::error_code ec;
    if (!std::filesystem::is_directory(d, ec)) {
      std::fprintf(stderr, "armstudy merge: %s: %s; expected an output folder of 'armstudy run'\n",
                   d.c_str(), std::filesystem::exists(d, ec) ? "not a folder" : "no such folder");
      missing = true;
    }
  }
  return !missing;
}

// names the cases of the sweep without a result (the first ten)
void report_missing_cases(const std::vector<armstudy::cli::CaseOutput>& outputs,
                          size_t missing_cases, const armstudy::cli::SweepManifest& manifest,
                          const std::filesystem::path& manifest_at) {
  std::string names;
  size_t listed = 0;
  for (const auto& o : outputs)
    if (o.record.status == "missing" && listed++ < 10) names += "\n  " + o.record.case_info.name;
  if (missing_cases > 10) names += "\n  ... and " + std::to_string(missing_cases - 10) + " more";
  std::fprintf(stderr, "armstudy merge: %zu case(s) of sweep '%s' (%s) have no result:%s\n",
               missing_cases, armstudy::report::terminal_text(manifest.sweep).c_str(),
               manifest_at.c_str(), armstudy::report::terminal_text(names).c_str());
}

// the merged pages: the sweep report (when the cases are a sweep's) and the index; the exit
// code (kExitDone, or why not, said)
int write_merged_pages(const std::vector<armstudy::cli::CaseOutput>& outputs,
                       const std::string& out) {
  try {
    const armstudy::report::SweepTable table = armstudy::cli::sweep_table(outputs);
    if (!table.rows.empty()) {
      std::string name = "sweep";
      for (const auto& o : outputs)
        if (o.record.case_info.sweep) {
          name = o.record.case_info.sweep->name;
          break;
        }
      armstudy::report::check_run_level_output(out, "sweep");
      const int plots =
          armstudy::report::write_sweep_report(std::filesystem::path(out) / "sweep", table, name);
      std::fprintf(stderr, "sweep report: %s/sweep/index.html (%d plot(s))\n", out.c_str(), plots);
    }
    armstudy::report::write_index(out, armstudy::app::index_studies());
  } catch (const armstudy::report::ForeignOutput& e) {
    std::fprintf(stderr, "armstudy: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "armstudy: cannot write the pages: %s\n", e.what());
    return kExitRuntime;
  }
  return kExitDone;
}

// (over 60 lines, kept whole: the steps of a merge in order: collect, check, write the run-level
// files)
int cmd_merge(const std::vector<std::string>& dirs, std::string out,
              const std::string& manifest_file) {
  std::vector<std::filesystem::path> ds(dirs.begin(), dirs.end());
  if (!merge_folders_exist(ds)) {
    std::fprintf(stderr, "nothing was written\n");
    return kExitBadInput;
  }
  if (out.empty()) out = dirs.front();
  std::vector<std::string> warnings;
  std::vector<armstudy::cli::CaseOutput> outputs;
  // the sweep the folders are the result of: --manifest, else one found in a folder
  std::optional<armstudy::cli::SweepManifest> manifest;
  std::filesystem::path manifest_at = manifest_file;
  try {
    outputs = armstudy::cli::collect_outputs(ds, &warnings);
    if (!manifest_file.empty()) {
      manifest = armstudy::cli::read_manifest(manifest_file);
      if (!manifest)
        throw armstudy::cli::InputLimitError(manifest_file +
                                             ": no such file; expected the sweep manifest that "
                                             "'armstudy sweep expand' writes");
    }
    for (const auto& d : ds) {
      if (manifest) break;
      manifest_at = d / armstudy::cli::kManifestName;
      manifest = armstudy::cli::read_manifest(manifest_at);
    }
  } catch (const armstudy::cases::InputFileError& e) {
    std::fprintf(stderr, "armstudy merge: %s\nnothing was written\n",
                 armstudy::report::terminal_text(e.what()).c_str());
    return e.runtime() ? kExitRuntime : kExitBadInput;
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "armstudy merge: %s\nnothing was written\n",
                 armstudy::report::terminal_text(e.what()).c_str());
    return kExitBadInput;
  }
  size_t missing_cases = 0;
  if (manifest)
    missing_cases = armstudy::cli::apply_manifest(*manifest, manifest_at, &outputs, &warnings);
  for (const auto& w : warnings)
    std::fprintf(stderr, "warning: %s\n", armstudy::report::terminal_text(w).c_str());
  if (outputs.empty()) {
    std::fprintf(stderr,
                 "armstudy merge: no case folder with a results.json in the folder(s) given; "
                 "expected output folders of 'armstudy run'\nnothing was written\n");
    return kExitBadInput;
  }
  const bool sweep_points = std::any_of(outputs.begin(), outputs.end(), [](const auto& o) {
    return o.record.case_info.sweep.has_value();
  });
  if (refuse_foreign_outputs(out, {}, run_level_names(sweep_points, sweep_points)))
    return kExitBadInput;
  if (missing_cases) report_missing_cases(outputs, missing_cases, *manifest, manifest_at);
  size_t failed = 0;
  try {
    failed = armstudy::cli::write_merged(outputs, out);
  } catch (const armstudy::report::ForeignOutput& e) {
    std::fprintf(stderr, "armstudy: %s\n", armstudy::report::terminal_text(e.what()).c_str());
    return kExitBadInput;
  }
  std::fprintf(stderr, "merged %zu case(s) into %s (%zu failed)\n", outputs.size(), out.c_str(),
               failed);
  // the pages: every case folder inside `out`, and the sweep's plots over its axes
  if (const int code = write_merged_pages(outputs, out); code != kExitDone) return code;
  return failed ? kExitUnsolved : kExitDone;
}

// what the given command's output folder and open files allow: kExitDone, or the exit code
// having said why not
int check_before_running(const armstudy::cli::Commands& c, const armstudy::cli::Args& a) {
  // the output folder: "" or a file is bad usage, refused before anything is done
  const std::string* out_given = *c.run                             ? &a.out_dir
                                 : *c.expand                        ? &a.sweep_out
                                 : *c.diff                          ? &a.diff_out
                                 : *c.merge && c.merge_out->count() ? &a.merge_out
                                                                    : nullptr;
  if (out_given) {
    if (const std::string why = out_problem(*out_given); !why.empty()) {
      armstudy::cli::say_refusal("armstudy: " + why);
      return kExitBadInput;
    }
  }
  if (*c.run || *c.merge || *c.diff) {
    if (const std::string why = armstudy::cli::ensure_open_files(); !why.empty()) {
      armstudy::cli::say_refusal("armstudy: " + why);
      return kExitRuntime;
    }
  }
  return kExitDone;
}

// runs the command given; its exit code
int run_command(const armstudy::cli::Commands& c, armstudy::cli::Args& a) {
  if (*c.validate) return cmd_validate(a.validate_paths, a.allow_large);
  if (*c.init) return armstudy::cli::cmd_init(a.init_study, a.init_out);
  if (*c.expand) return cmd_sweep_expand(a.sweep_file, a.sweep_out, a.base_dirs);
  if (*c.list) return cmd_list(a.list_items, a.list_json);
  if (*c.merge) return cmd_merge(a.merge_dirs, a.merge_out, a.merge_manifest);
  if (*c.diff) {
    a.diff_options.base = a.diff_base;
    a.diff_options.now = a.diff_new;
    a.diff_options.out = a.diff_out;
    return armstudy::cli::run_diff(a.diff_options);
  }
  a.options.out_dir = a.out_dir;
  if (!c.run_out->count())  // the default, named: a user who forgot --out finds the output
    std::fprintf(stderr, "no --out given: the output goes to %s\n",
                 std::filesystem::absolute(a.out_dir).c_str());
  a.options.render = !a.no_render;
  a.options.sensitivity = !a.no_sensitivity;
  return cmd_run(case_files(a.run_paths), a.options, a.jobs, a.shard, a.force, a.allow_large,
                 a.run_paths, a.run_json);
}

// parses the command line and runs the command given; its exit code
int parse_and_run(CLI::App& app, const armstudy::cli::Commands& commands, armstudy::cli::Args& a,
                  int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // an unknown option first: not what it caused later ("Path does not exist: 2")
    if (const std::string unknown = armstudy::cli::unknown_option_message(app);
        !unknown.empty() && e.get_exit_code() != static_cast<int>(CLI::ExitCodes::Success)) {
      armstudy::cli::say_refusal(unknown);
      return kExitBadInput;
    }
    const int code = app.exit(e);  // prints help, version or the error
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return 0;
    armstudy::cli::keep_refusal(e.what());
    return code ? kExitBadInput : 0;
  }
  if (const int code = check_before_running(commands, a); code != kExitDone) return code;
  try {
    return run_command(commands, a);
  } catch (const std::exception& e) {
    armstudy::cli::say_refusal("armstudy: internal error: " + std::string(e.what()));
    return kExitRuntime;
  }
}

}  // namespace

int main(int argc, char** argv) {
  armstudy::cli::keep_freed_memory();          // before any thread: see process_memory.hpp
  armstudy::cli::install_interrupt_cleanup();  // first: every thread inherits its signal mask
  // a write to a pipe or socket whose reader is gone (a helper that died, a closed `| head`)
  // fails with EPIPE and is reported, instead of killing armstudy without a word
  std::signal(SIGPIPE, SIG_IGN);
  CLI::App app{
      "armstudy: energy-optimal placement, throwing and time-optimal studies of planar "
      "robot arms, from YAML case files to MuJoCo-rendered reports"};
  armstudy::cli::describe_app(app);
  armstudy::cli::Args a;
  const armstudy::cli::Commands commands = armstudy::cli::add_commands(app, a);
  int code = parse_and_run(app, commands, a, argc, argv);
  // run --json answers in JSON whatever stopped the run: a bad option, a missing case file
  if (code != kExitDone && !g_run_json_printed && armstudy::cli::run_json_requested(argc, argv))
    std::printf("%s\n", armstudy::cli::refusal_json(a.out_dir, code).c_str());
  // every write to standard output checked: `list --json > /dev/full` is a failure
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::fprintf(stderr, "armstudy: cannot write to standard output: %s\n", std::strerror(errno));
    code = std::max(code, kExitRuntime);
  }
  return code;
}
