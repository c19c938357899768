// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "app/run_case.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <iterator>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include "app/json_numbers.hpp"
#include "app/provenance.hpp"
#include "app/sensitivity.hpp"
#include "cases/case_info.hpp"
#include "cases/case_inputs.hpp"
#include "cases/input_file.hpp"
#include "report/case_report.hpp"
#include "report/owned_output.hpp"
#include "report/source_comparison.hpp"
#include "scene/osmesa_context.hpp"
#include "scene/phase_times.hpp"
#include "scene/rendered.hpp"
#include "sys/atomic_file.hpp"
#include "sys/scratch_dir.hpp"
#include "version.hpp"

namespace armstudy::app {
namespace fs = std::filesystem;

void write_file_atomic(const fs::path& path, const std::string& text) {
  sys::write_file_atomic(path, text);
}

report::ResultsRecord results_header(const cases::CaseInfo& info, studies::Status status,
                                     const std::string& message,
                                     const std::vector<studies::Check>& checks) {
  report::ResultsRecord r;
  r.schema_version = report::kSchemaVersion;
  r.armstudy_version = kVersion;
  if (*git_commit()) r.git_commit = git_commit();
  r.study = info.study;
  r.case_info.name = info.name;
  r.case_info.path = info.path;
  r.case_info.sha256 = info.sha256;
  r.case_info.inputs = cases::case_inputs(info.yaml);
  if (!info.description.empty()) r.case_info.description = info.description;
  if (info.expect_unsolvable) r.case_info.expect = "unsolvable";
  if (!info.sweep_name.empty() || !info.sweep_point.empty()) {
    report::CaseRecord::Sweep sweep;
    sweep.name = info.sweep_name;
    for (const auto& [path, value] : info.sweep_point) sweep.point[path] = value;
    r.case_info.sweep = std::move(sweep);
  }
  r.provenance = provenance();
  r.status = status == studies::Status::kSolved ? "solved" : "unsolvable";
  r.message = message;
  for (const auto& c : checks)
    r.checks.push_back({c.name, c.description, c.value, c.tolerance, c.passed});
  return r;
}

std::string process_tag() { return sys::process_tag(); }

sys::StaleCleanup remove_stale_outputs(const fs::path& out_dir) {
  return report::remove_stale_scratch(out_dir);
}

namespace {

bool exchange_unsupported(int e) { return e == EINVAL || e == ENOSYS || e == EOPNOTSUPP; }

// Puts the complete folder `fresh` at `target`, where an earlier report may be. Where the
// file system can (ext4, xfs, btrfs, tmpfs), both are exchanged in one step
// (renameat2 RENAME_EXCHANGE), so `target` is never missing; elsewhere (NFS) the earlier
// report first moves to `old_slot` in the scratch folder, which a later run (or this one's
// signal clean-up) moves back if a kill comes between the two renames.
// Only a case folder armstudy wrote for this case is ever replaced: anything else at
// `target` (a user's folder or file of the case's name) is refused, checked before the swap
// and, for one that appeared meanwhile, after the exchange or the move aside (which is then
// undone).
void swap_into_place(const fs::path& fresh, const fs::path& target, const fs::path& old_slot,
                     const std::string& name) {
  std::error_code ec;
  std::lock_guard<std::mutex> lock(sys::swap_mutex());
  const auto refuse = [&](const std::string& why) {
    throw report::ForeignOutput(target.string() + ": " + why + "; armstudy leaves it as it is");
  };
  for (int attempt = 0; attempt < 8; ++attempt) {
    if (const std::string why = report::foreign_case_folder(target, name); !why.empty())
      refuse(why);
    if (::renameat2(AT_FDCWD, fresh.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0) {
      // now the earlier report, unless something else was put there since the check
      if (const std::string why = report::foreign_case_folder(fresh, name); !why.empty()) {
        ::renameat2(AT_FDCWD, fresh.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE);
        refuse(why);
      }
      fs::remove_all(fresh, ec);
      return;
    }
    int e = errno;
    if (e == ENOENT) {  // no earlier report
      if (::rename(fresh.c_str(), target.c_str()) == 0) return;
      e = errno;
      if (e == EEXIST || e == ENOTEMPTY) continue;  // another run put one there meanwhile
      throw std::runtime_error(sys::system_error_text("move the new report to", target, e));
    }
    if (!exchange_unsupported(e))
      throw std::runtime_error(sys::system_error_text("move the new report to", target, e));
    fs::create_directories(old_slot.parent_path());
    fs::remove_all(old_slot);
    if (::rename(target.c_str(), old_slot.c_str()) != 0) {
      e = errno;
      if (e == ENOENT) continue;
      throw std::runtime_error(
          sys::system_error_text("move the earlier report aside from", target, e));
    }
    if (const std::string why = report::foreign_case_folder(old_slot, name); !why.empty()) {
      ::rename(old_slot.c_str(), target.c_str());  // put there since the check: back
      refuse(why);
    }
    if (::rename(fresh.c_str(), target.c_str()) != 0) {
      e = errno;
      ::rename(old_slot.c_str(), target.c_str());  // the earlier report back
      if (e == EEXIST || e == ENOTEMPTY) continue;
      throw std::runtime_error(sys::system_error_text("move the new report to", target, e));
    }
    fs::remove_all(old_slot, ec);
    return;
  }
  throw std::runtime_error("cannot move the new report to " + target.string() +
                           ": other runs kept replacing the folder");
}

}  // namespace

namespace {

// the render step's animations (scene/rendered.hpp) as results.json "animations", sorted by
// name
std::vector<report::AnimationRecord> animation_records(std::vector<scene::Animation> animations) {
  std::sort(animations.begin(), animations.end(),
            [](const scene::Animation& a, const scene::Animation& b) { return a.name < b.name; });
  std::vector<report::AnimationRecord> out;
  for (const scene::Animation& a : animations) {
    report::AnimationRecord& r = out.emplace_back();
    r.name = a.name;
    r.title = a.title;
    r.sprite = a.sprite;
    r.still = a.still;
    if (!a.video.empty()) r.video = a.video;
    r.frames = a.frames;
    r.columns = a.columns;
    r.frame_width_px = a.frame_width;
    r.frame_height_px = a.frame_height;
    r.fps = a.fps;
    r.duration_s = a.duration_s;
    r.video_duration_s = a.frames / a.fps;
    if (!a.note.empty()) r.note = a.note;
  }
  return out;
}

// a solved case's frames (unless --no-render), exports and animations into `r`, their files
// into `dir`; the videos encode while the exports are written, and every one is done when
// this returns or throws (a pending animation waits for its video when it goes)
void render_and_export(LoadedCase& c, const RunOptions& options, const fs::path& dir,
                       const studies::ProgressFn& progress, report::ResultsRecord& r) {
  scene::Rendered rendered;
  if (options.render) {
    if (progress) progress(0.99, "rendering");
    scene::PhaseScope phase("render");
    rendered = c.run->render(dir, c.info);
    r.frames = std::move(rendered.frames);
  }
  {
    // files other tools open (model.xml, motion CSVs), listed under "files" as well
    scene::PhaseScope phase("exports");
    r.exports = c.run->write_exports(dir, c.info);
  }
  r.animations = animation_records(scene::finish_animations(rendered.animations));
}

// results.json but its "files": the shared record and the study's section; for a case with a
// source, the source's printed figures beside armstudy's (read from this very JSON) and
// their check added to `r` first
nlohmann::json results_json(const LoadedCase& c, const nlohmann::json& section,
                            report::ResultsRecord& r) {
  nlohmann::json j = report::write_record(r);
  j[c.info.study] = section;
  if (c.info.source.empty()) return j;
  r.source = report::compare_with_source(c.info.source, j);
  r.checks.push_back(report::source_explained_check(*r.source));
  j = report::write_record(r);
  j[c.info.study] = section;
  return j;
}

// the names of the failed checks, comma-separated (empty: every check passed)
std::string failed_checks(const std::vector<report::CheckRecord>& checks) {
  std::string failed;
  for (const auto& ch : checks)
    if (!ch.passed) failed += (failed.empty() ? "" : ", ") + ch.name;
  return failed;
}

// the renderer and Mesa version the frames were made with
void set_gl_provenance(report::ResultsRecord& r) {
  const scene::GlInfo gl = scene::gl_info();
  r.provenance.gl_renderer = gl.renderer;
  r.provenance.gl_version = gl.version;
  if (const size_t at = gl.version.find("Mesa "); at != std::string::npos)
    r.provenance.mesa_version = gl.version.substr(at + 5, gl.version.find(' ', at + 5) - at - 5);
}

// the case's page printed in the scratch folder, renamed into the case folder (a failure is
// printed again, and reported, by finish_reports)
void queue_pdf(report::PdfPrinter& printer, const fs::path& out_dir, const fs::path& final_dir,
               const std::string& name) {
  const fs::path printed = sys::scratch_dir(out_dir) / "pdf" / (name + ".pdf");
  fs::create_directories(printed.parent_path());
  printer.add({final_dir / "index.html", printed}, [printed, final_dir](const std::string& error) {
    std::error_code ec;
    if (!error.empty() || ::rename(printed.c_str(), (final_dir / "report.pdf").c_str()) != 0)
      fs::remove(printed, ec);
  });
}

// the case's exit code and one-line message: solved or not, as it expects, checks passed
void set_verdict(const LoadedCase& c, studies::Status status, const std::string& failed,
                 CaseOutcome& outcome) {
  if (status != studies::Status::kSolved && c.info.expect_unsolvable) {
    outcome.message = "could not be solved, as the case expects: " + c.run->message();
  } else if (status != studies::Status::kSolved) {
    outcome.exit_code = 1;
    outcome.message = "could not be solved: " + c.run->message();
  } else if (c.info.expect_unsolvable) {
    outcome.exit_code = 1;
    outcome.message = "solved, but the case expects it to be unsolvable ('expect: unsolvable'): " +
                      c.run->message();
  } else if (!failed.empty()) {
    outcome.exit_code = 1;
    outcome.message = "failed its checks: " + failed;
  } else {
    outcome.message = c.run->message();
  }
}

// the solved (or not) case's header, key figures and typed section into `r` and `section`
// (again after a second solve: everything but what the caller adds later)
void record_answer(const LoadedCase& c, const RunOptions& options, studies::Status status,
                   report::ResultsRecord& r, nlohmann::json& section) {
  r = results_header(c.info, status, c.run->message(), c.run->checks());
  section = c.run->results();
  if (status == studies::Status::kSolved)
    for (const auto& k : c.run->key_figures())
      r.key_figures.push_back({k.name, k.value, k.unit, k.label.empty() ? k.name : k.label});
  // what decides whether a later run may keep this output (main.cpp, already_done)
  r.run_options.render = options.render;
}

}  // namespace

// the stages of one case in order (solve, sensitivity, render and exports, report,
// results.json, swap), under one try that removes the scratch folder
CaseOutcome run_case(LoadedCase& c, const RunOptions& options,
                     const studies::ProgressFn& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  CaseOutcome outcome;
  const fs::path final_dir = options.out_dir / c.info.name;
  outcome.folder = final_dir;
  fs::path tmp_dir;
  try {
    fs::create_directories(options.out_dir);
    tmp_dir = sys::scratch_dir(options.out_dir) / "new" / c.info.name;
    fs::remove_all(tmp_dir);
    fs::create_directories(tmp_dir);

    // solve
    scene::take_phase_times();  // ARMSTUDY_PHASE_TIMES: this case's phases only
    std::optional<scene::PhaseScope> solve_phase(std::in_place, "solve");
    studies::Status status = c.run->solve(progress);
    solve_phase.reset();
    report::ResultsRecord r;
    nlohmann::json section;
    record_answer(c, options, status, r, section);
    // the sensitivity part: the case re-solved at each key's steps (no rendering)
    if (status == studies::Status::kSolved && options.sensitivity && !c.info.sensitivity.empty()) {
      scene::PhaseScope phase("sensitivity");
      r.sensitivity = run_sensitivity(c, progress, 0.975, 0.985);  // after the studies' 0.97
      // a step's answer met the case's own limits for less (StudyRun::offer_start): the case
      // is solved again with it as a start, and the sensitivity part is redone around that
      // answer; what a second round still finds below it is said, and fails a check
      const std::string offered = c.run->offered();
      if (r.sensitivity && !offered.empty()) {
        const auto first_round = r.sensitivity;
        status = c.run->solve([&](double f, std::string_view what) {
          if (progress)
            progress(0.985 + 0.005 * f, "solved again from a step's answer: " + std::string(what));
        });
        record_answer(c, options, status, r, section);
        r.sensitivity = status == studies::Status::kSolved
                            ? run_sensitivity(c, progress, 0.99, 0.995)
                            : first_round;
        if (r.sensitivity) {
          r.sensitivity->resolved_from = offered;
          const std::string still = c.run->offered();
          if (!still.empty()) r.sensitivity->undercut = still;
          r.checks.push_back(report::CheckRecord{
              "sensitivity_steps_do_not_undercut_the_answer",
              "no sensitivity step's answer meets the case's own limits for less than the "
              "answer (after one more solve from such answers): 1 when one does",
              still.empty() ? 0.0 : 1.0, 0.0, still.empty()});
        }
      }
    }
    // render and export only what was solved
    if (status == studies::Status::kSolved) render_and_export(c, options, tmp_dir, progress, r);
    if (!r.frames.empty()) set_gl_provenance(r);
    nlohmann::json j = results_json(c, section, r);
    {
      scene::PhaseScope phase("report");
      report::write_case_report(tmp_dir, c.info, j, c.entry->report, c.entry->answer);
    }
    // results.json last, listing every file written beside it with its sha256
    j["run_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    j["files"] = report::to_json(list_files(tmp_dir, "results.json"));
    const std::string text = results_text(j);  // shortest round-trip numbers
    // never a results.json this armstudy would refuse to read back (the folder would be
    // "not armstudy's" from then on): the earlier report stays
    if (text.size() > cases::kMaxResultsJsonBytes)
      throw std::runtime_error(
          "results.json of case '" + c.info.name + "' would be " + std::to_string(text.size()) +
          " bytes, beyond the " + std::to_string(cases::kMaxResultsJsonBytes) +
          " bytes armstudy reads back (docs/budgets.md); nothing was written: please report "
          "this case");
    write_file_atomic(tmp_dir / "results.json", text);

    swap_into_place(tmp_dir, final_dir, tmp_dir.parent_path().parent_path() / "old" / c.info.name,
                    c.info.name);
    if (options.printer) queue_pdf(*options.printer, options.out_dir, final_dir, c.info.name);
    // the verdict over every check, the study's and the source comparison's
    set_verdict(c, status, failed_checks(r.checks), outcome);
  } catch (...) {
    std::error_code ec;
    if (!tmp_dir.empty()) fs::remove_all(tmp_dir, ec);
    throw;
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (scene::phase_times_enabled())
    std::fprintf(stderr, "phase-times: %s: %.3f s: %s\n", c.info.name.c_str(), outcome.seconds,
                 scene::take_phase_times().c_str());
  return outcome;
}

namespace {

// the case page in `dir` is the one armstudy wrote: results.json (armstudy's, for `name`)
// lists index.html with the sha256 it has now; a page edited or replaced since is not printed
bool page_as_written(const fs::path& dir, const std::string& name) {
  if (!report::foreign_case_folder(dir, name).empty()) return false;
  try {
    std::ifstream in(dir / "results.json", std::ios::binary);
    const report::ResultsRecord r = report::read_record(nlohmann::json::parse(in));
    std::ifstream page(dir / "index.html", std::ios::binary);
    if (!fs::is_regular_file(fs::symlink_status(dir / "index.html")) || !page) return false;
    const std::string bytes{std::istreambuf_iterator<char>(page), {}};
    for (const report::FileRecord& f : r.files)
      if (f.path == "index.html") return f.sha256 == cases::sha256_hex(bytes);
  } catch (const std::exception&) {
  }
  return false;
}

}  // namespace

std::vector<std::string> finish_reports(const RunOptions& options, int jobs,
                                        const std::vector<std::string>& cases) {
  std::vector<std::string> problems;
  if (options.pdf) {
    // the page of every case of this run without an up-to-date pdf, including cases skipped
    // as already done; only pages armstudy wrote (page_as_written)
    std::vector<fs::path> todo;
    for (const std::string& name : cases) {
      const fs::path dir = options.out_dir / name;
      const fs::path html = dir / "index.html", pdf = dir / "report.pdf";
      std::error_code ec;
      if (!fs::exists(html, ec) || !page_as_written(dir, name)) continue;
      if (!fs::exists(pdf) || fs::last_write_time(pdf) < fs::last_write_time(html))
        todo.push_back(dir);
    }
    std::sort(todo.begin(), todo.end());
    report::remove_stale_profiles();  // what killed runs' browsers left in /tmp
    // one browser prints every page, `jobs` at a time, into the scratch folder; each PDF
    // is then renamed into its case folder: a kill never leaves a half-written report.pdf
    // (or its temporary file) beside the report
    std::vector<report::PdfJob> prints;
    for (const fs::path& d : todo) {
      const fs::path dir = sys::scratch_dir(options.out_dir) / "pdf";
      fs::create_directories(dir);
      prints.push_back({d / "index.html", dir / (d.filename().string() + ".pdf")});
    }
    const auto p0 = std::chrono::steady_clock::now();
    std::vector<std::string> failed(prints.size());
    try {
      failed = report::print_pdfs(prints, std::max(1, jobs));
    } catch (const std::exception& e) {  // no Chromium: every page says so
      for (std::string& f : failed) f = e.what();
    }
    if (scene::phase_times_enabled())
      std::fprintf(stderr, "phase-times: pdf: %zu pages %.3f s\n", prints.size(),
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - p0).count());
    for (size_t i = 0; i < todo.size(); ++i) {
      if (failed[i].empty() &&
          ::rename(prints[i].pdf.c_str(), (todo[i] / "report.pdf").c_str()) != 0) {
        const int e = errno;
        std::error_code ec;
        fs::remove(prints[i].pdf, ec);
        problems.push_back(todo[i].filename().string() + ": no report.pdf: " +
                           sys::system_error_text("write", todo[i] / "report.pdf", e));
      } else if (!failed[i].empty()) {
        problems.push_back(todo[i].filename().string() + ": no report.pdf: " + failed[i]);
      }
    }
  }
  try {
    report::write_index(options.out_dir, index_studies());
  } catch (const std::exception& e) {
    problems.push_back(std::string("cannot write the index page: ") + e.what());
  }
  return problems;
}

}  // namespace armstudy::app
