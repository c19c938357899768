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
#include "cli/confined_path.hpp"
#include "cli/diff.hpp"
#include "cli/interrupt.hpp"
#include "cli/merge.hpp"
#include "cli/open_files.hpp"
#include "cli/process_memory.hpp"
#include "cli/progress.hpp"
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

// every file results.json lists is there, in the case folder, a regular file of its size,
// and (up to 4 MiB each, where hashing is cheap) of its sha256
bool listed_files_intact(const std::filesystem::path& folder,
                         const armstudy::report::ResultsRecord& r) {
  namespace fs = std::filesystem;
  constexpr long long kHashedBytes = 4ll << 20;
  std::vector<std::string> frames = r.frames;
  for (const auto& f : r.files) {
    if (!armstudy::app::confined_problem(folder, f.path).empty()) return false;
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
    if (!armstudy::app::confined_problem(folder, f).empty() || !fs::is_regular_file(folder / f, ec))
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
           armstudy::app::case_passed(r) && listed_files_intact(out_dir / c.info.name, r);
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
  for (const std::string& f : foreign) std::fprintf(stderr, "armstudy: %s\n", f.c_str());
  if (!foreign.empty())
    std::fprintf(stderr,
                 "nothing was written: armstudy replaces only what it wrote; move these "
                 "away or choose another --out\n");
  return !foreign.empty();
}

// the manifest of the sweep whose case folder is run, copied into the output folder, where
// merge finds it (an earlier sweep's is replaced; a file armstudy did not write is not)
int copy_manifest(const std::vector<std::string>& run_paths, const std::filesystem::path& out) {
  namespace fs = std::filesystem;
  for (const auto& p : run_paths) {
    if (!fs::is_directory(p)) continue;
    try {
      const auto m = armstudy::app::read_manifest(fs::path(p) / armstudy::app::kManifestName);
      if (!m) continue;
      const fs::path dst = out / armstudy::app::kManifestName;
      armstudy::app::read_manifest(dst);  // throws for a file that is not a manifest
      fs::create_directories(out);
      armstudy::app::write_file_atomic(dst, armstudy::app::manifest_text(*m));
      return kExitDone;
    } catch (const std::runtime_error& e) {
      std::fprintf(stderr, "armstudy: %s; nothing was written\n",
                   armstudy::report::terminal_text(e.what()).c_str());
      return kExitBadInput;
    }
  }
  return kExitDone;
}

int cmd_run(const std::vector<std::string>& paths, const armstudy::app::RunOptions& options,
            int jobs, const std::string& shard, bool force, bool allow_large,
            const std::vector<std::string>& run_paths) {
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
  // cases that ended in an error wrote no results.json: they are failed cases in summary.md
  // and junit.xml all the same
  std::vector<armstudy::app::CaseOutput> errored;
  // the run's memory budget covers all its jobs: a case starts when its estimate fits
  // beside the running ones' (a case beyond it alone, with --allow-large, runs alone)
  armstudy::app::MemoryGate memory(armstudy::cases::kMemoryBudgetBytes);
  auto worker = [&] {
    for (size_t i = next++; i < cases.size(); i = next++) {
      LoadedCase& c = cases[order[i]];
      const double need = armstudy::app::estimated_memory_bytes(c, options.render);
      memory.acquire(need);
      int code = kExitDone;
      std::string line, error;
      const std::string name = armstudy::report::terminal_text(c.info.name);
      try {
        const auto o = armstudy::app::run_case(c, case_options, progress.task(c.info.name));
        code = o.exit_code;
        char secs[32];
        std::snprintf(secs, sizeof secs, "%.1f s", o.seconds);
        line = (code == 0 ? "done: " : "FAILED: ") + name + " (" + c.info.study + ", " + secs +
               ") -> " + o.folder.string() +
               (o.message.empty() ? "" : "\n  " + armstudy::report::terminal_text(o.message));
      } catch (const armstudy::report::ForeignOutput& e) {
        code = kExitBadInput;  // a user's folder of the case's name appeared during the run
        error = e.what();
        line = "ERROR: " + name + ": " + armstudy::report::terminal_text(error);
      } catch (const armstudy::scene::ModelError& e) {
        code = kExitBadInput;  // MuJoCo cannot load the arm the case describes
        error = e.what();
        line =
            "ERROR: " + name + " (" + c.info.path + "): " + armstudy::report::terminal_text(error);
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
        line = "ERROR: " + name + ": " + armstudy::report::terminal_text(error);
      }
      memory.release(need);
      progress.line(line);
      std::lock_guard<std::mutex> lock(mu);
      worst = std::max(worst, code);
      if (!error.empty())
        errored.push_back(armstudy::app::failed_output(options.out_dir / c.info.name, c.info.name,
                                                       c.info.study, "error",
                                                       "the run ended in an error: " + error));
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
  for (const auto& problem : armstudy::app::finish_reports(options, jobs, names)) {
    std::fprintf(stderr, "armstudy: %s\n", problem.c_str());
    worst = std::max(worst, kExitRuntime);
  }
  // what CI reads, over every case in the output folder (not only this run's)
  try {
    std::vector<std::string> warnings;
    auto outputs = armstudy::app::collect_outputs({options.out_dir}, &warnings);
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
    armstudy::app::write_merged(outputs, options.out_dir);
  } catch (const armstudy::report::ForeignOutput& e) {
    std::fprintf(stderr, "armstudy: %s\n", armstudy::report::terminal_text(e.what()).c_str());
    worst = std::max(worst, kExitBadInput);
  } catch (const armstudy::app::InputLimitError& e) {
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
  if (worst == kExitDone)
    std::fprintf(stderr, "all %zu case(s) done; output in %s\n", cases.size(),
                 options.out_dir.c_str());
  return worst;
}

int cmd_sweep_expand(const std::string& sweep_path, const std::string& out,
                     const std::vector<std::string>& base_dirs) {
  try {
    const auto sw = armstudy::app::load_sweep(
        sweep_path, std::vector<std::filesystem::path>(base_dirs.begin(), base_dirs.end()));
    std::fprintf(stderr, "sweep %s: %zu case(s); writing them to %s\n", sw.name.c_str(),
                 sw.points.size(), out.c_str());
    const auto r = armstudy::app::expand_sweep(sw, out);
    for (const auto& id : r.removed)
      std::fprintf(stderr, "removed %s.yaml: no longer a point of the sweep\n", id.c_str());
    std::fprintf(stderr, "sweep %s: %zu case(s), %zu file(s) written to %s\n", sw.name.c_str(),
                 sw.points.size(), r.written, out.c_str());
    return kExitDone;
  } catch (const armstudy::cases::CaseErrors& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  } catch (const armstudy::app::ExpandRefused& e) {
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

int cmd_merge(const std::vector<std::string>& dirs, std::string out,
              const std::string& manifest_file) {
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
  // the sweep the folders are the result of: --manifest, else one found in a folder
  std::optional<armstudy::app::SweepManifest> manifest;
  std::filesystem::path manifest_at = manifest_file;
  try {
    outputs = armstudy::app::collect_outputs(ds, &warnings);
    if (!manifest_file.empty()) {
      manifest = armstudy::app::read_manifest(manifest_file);
      if (!manifest)
        throw armstudy::app::InputLimitError(manifest_file +
                                             ": no such file; expected the sweep manifest that "
                                             "'armstudy sweep expand' writes");
    }
    for (const auto& d : ds) {
      if (manifest) break;
      manifest_at = d / armstudy::app::kManifestName;
      manifest = armstudy::app::read_manifest(manifest_at);
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
    missing_cases = armstudy::app::apply_manifest(*manifest, manifest_at, &outputs, &warnings);
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
  if (missing_cases) {
    std::string names;
    size_t listed = 0;
    for (const auto& o : outputs)
      if (o.record.status == "missing" && listed++ < 10) names += "\n  " + o.record.case_info.name;
    if (missing_cases > 10) names += "\n  ... and " + std::to_string(missing_cases - 10) + " more";
    std::fprintf(stderr, "armstudy merge: %zu case(s) of sweep '%s' (%s) have no result:%s\n",
                 missing_cases, armstudy::report::terminal_text(manifest->sweep).c_str(),
                 manifest_at.c_str(), armstudy::report::terminal_text(names).c_str());
  }
  size_t failed = 0;
  try {
    failed = armstudy::app::write_merged(outputs, out);
  } catch (const armstudy::report::ForeignOutput& e) {
    std::fprintf(stderr, "armstudy: %s\n", armstudy::report::terminal_text(e.what()).c_str());
    return kExitBadInput;
  }
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
  app.set_version_flag(
      "--version", [] { return armstudy::cli::version_text(); },
      "Print armstudy's version and commit, the versions of the libraries it "
      "runs with and the browser --pdf would use, and exit");
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
  bool no_sensitivity = false;
  run->add_flag("--no-sensitivity", no_sensitivity,
                "Skip the re-solves of each case's sensitivity: part (docs/sensitivity.md)");
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
  std::vector<std::string> base_dirs;
  expand
      ->add_option("--base-dir", base_dirs,
                   "A folder the sweep's base case may also be in (default: only the sweep "
                   "file's folder)")
      ->check(CLI::ExistingDirectory);

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
  std::string merge_manifest;
  merge->add_option("--manifest", merge_manifest,
                    "The sweep's sweep-manifest.json (default: one in a merged folder); a case "
                    "of the sweep without a result fails the merge");
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
      code = cmd_sweep_expand(sweep_file, sweep_out, base_dirs);
    else if (*list)
      code = cmd_list(list_items, list_json);
    else if (*merge)
      code = cmd_merge(merge_dirs, merge_out, merge_manifest);
    else if (*diff) {
      diff_options.base = diff_base;
      diff_options.now = diff_new;
      diff_options.out = diff_out;
      code = armstudy::app::run_diff(diff_options);
    } else {
      options.out_dir = out_dir;
      options.render = !no_render;
      options.sensitivity = !no_sensitivity;
      code = cmd_run(case_files(run_paths), options, jobs, shard, force, allow_large, run_paths);
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
