#include "cli/run_case.hpp"

#include <signal.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "cli/json_numbers.hpp"
#include "cli/provenance.hpp"
#include "scene/osmesa_context.hpp"
#include "report/case_report.hpp"
#include "version.hpp"

namespace armstudy::app {
namespace fs = std::filesystem;

void write_file_atomic(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.parent_path() / ("." + path.filename().string() + ".tmp-" + process_tag());
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  fs::rename(tmp, path);
}

nlohmann::json results_header(const cases::CaseInfo& info, studies::Status status,
                              const std::string& message,
                              const std::vector<studies::Check>& checks) {
  nlohmann::json j;
  j["schema_version"] = 1;
  j["armstudy_version"] = kVersion;
  if (*git_commit()) j["git_commit"] = git_commit();
  j["study"] = info.study;
  j["case"] = {{"name", info.name}, {"path", info.path}, {"sha256", info.sha256}};
  if (!info.description.empty()) j["case"]["description"] = info.description;
  if (info.expect_unsolvable) j["case"]["expect"] = "unsolvable";
  if (!info.sweep_name.empty() || !info.sweep_point.empty()) {
    nlohmann::json point = nlohmann::json::object();
    for (const auto& [path, value] : info.sweep_point) point[path] = value;
    j["case"]["sweep"] = {{"name", info.sweep_name}, {"point", point}};
  }
  j["provenance"] = provenance();
  j["status"] = status == studies::Status::kSolved ? "solved" : "unsolvable";
  j["message"] = message;
  nlohmann::json cj = nlohmann::json::array();
  for (const auto& c : checks) {
    cj.push_back({{"name", c.name}, {"description", c.description}, {"value", c.value},
                  {"tolerance", c.tolerance}, {"passed", c.passed}});
  }
  j["checks"] = cj;
  return j;
}

namespace {
// a process that is gone, or a zombie nobody has reaped yet (kill(pid, 0) still succeeds)
bool process_gone(pid_t pid) {
  if (::kill(pid, 0) != 0) return errno == ESRCH;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return false;
  const size_t paren = line.rfind(')');
  return paren != std::string::npos && paren + 2 < line.size() && line[paren + 2] == 'Z';
}
}  // namespace

std::string process_tag() {
  char host[256] = {0};
  if (::gethostname(host, sizeof host - 1) != 0 || !host[0]) std::snprintf(host, sizeof host, "host");
  std::string h;
  for (const char* c = host; *c; ++c) h += (std::isalnum(static_cast<unsigned char>(*c)) || *c == '.') ? *c : '_';
  return h + "-" + std::to_string(::getpid());
}

size_t remove_stale_outputs(const fs::path& out_dir) {
  std::error_code ec;
  if (!fs::is_directory(out_dir, ec)) return 0;
  const std::string mine = process_tag();
  const std::string host = mine.substr(0, mine.rfind('-') + 1);  // "<host>-"
  size_t removed = 0;
  for (const auto& e : fs::directory_iterator(out_dir, ec)) {
    const std::string f = e.path().filename().string();
    if (f.empty() || f[0] != '.') continue;
    for (const char* kind : {".tmp-", ".old-"}) {
      const size_t at = f.rfind(kind);
      if (at == std::string::npos || f.compare(at + 5, host.size(), host) != 0) continue;
      const std::string pid_text = f.substr(at + 5 + host.size());
      if (pid_text.empty() || pid_text.find_first_not_of("0123456789") != std::string::npos) continue;
      const pid_t pid = static_cast<pid_t>(std::stol(pid_text));
      if (pid != ::getpid() && process_gone(pid)) removed += fs::remove_all(e.path(), ec) > 0;
    }
  }
  return removed;
}

CaseOutcome run_case(LoadedCase& c, const RunOptions& options, const studies::ProgressFn& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  CaseOutcome outcome;
  const fs::path final_dir = options.out_dir / c.info.name;
  outcome.folder = final_dir;
  const std::string tag = process_tag();
  const fs::path tmp_dir = options.out_dir / ("." + c.info.name + ".tmp-" + tag);
  try {
    fs::create_directories(options.out_dir);
    fs::remove_all(tmp_dir);
    fs::create_directories(tmp_dir);

    // solve
    const studies::Status status = c.run->solve(progress);
    const auto checks = c.run->checks();
    nlohmann::json j = results_header(c.info, status, c.run->message(), checks);
    j[c.info.study] = c.run->results();
    nlohmann::json kf = nlohmann::json::array();
    if (status == studies::Status::kSolved)
      for (const auto& k : c.run->key_figures())
        kf.push_back({{"name", k.name}, {"value", k.value}, {"unit", k.unit}});
    j["key_figures"] = kf;
    bool checks_ok = true;
    std::string failed;
    for (const auto& ch : checks) {
      if (!ch.passed) {
        checks_ok = false;
        failed += (failed.empty() ? "" : ", ") + ch.name;
      }
    }
    // render and report only what was solved
    std::vector<std::string> frames;
    if (status == studies::Status::kSolved && options.render) {
      if (progress) progress(0.99, "rendering");
      frames = c.run->render(tmp_dir, c.info);
    }
    j["frames"] = frames;
    if (!frames.empty()) {
      const scene::GlInfo gl = scene::gl_info();
      j["provenance"]["gl_renderer"] = gl.renderer;
      j["provenance"]["gl_version"] = gl.version;
      if (const size_t at = gl.version.find("Mesa "); at != std::string::npos)
        j["provenance"]["mesa_version"] = gl.version.substr(at + 5, gl.version.find(' ', at + 5) - at - 5);
    }
    c.run->report(tmp_dir, c.info, j);
    // results.json last, listing every file written beside it with its sha256
    j["files"] = list_files(tmp_dir, "results.json");
    write_file_atomic(tmp_dir / "results.json", results_text(j));  // shortest round-trip numbers

    // swap into place
    if (fs::exists(final_dir)) {
      const fs::path old_dir = options.out_dir / ("." + c.info.name + ".old-" + tag);
      fs::remove_all(old_dir);
      fs::rename(final_dir, old_dir);
      fs::rename(tmp_dir, final_dir);
      fs::remove_all(old_dir);
    } else {
      fs::rename(tmp_dir, final_dir);
    }
    if (status != studies::Status::kSolved && c.info.expect_unsolvable) {
      outcome.message = "could not be solved, as the case expects: " + c.run->message();
    } else if (status != studies::Status::kSolved) {
      outcome.exit_code = 1;
      outcome.message = "could not be solved: " + c.run->message();
    } else if (c.info.expect_unsolvable) {
      outcome.exit_code = 1;
      outcome.message = "solved, but the case expects it to be unsolvable ('expect: unsolvable'): " +
                        c.run->message();
    } else if (!checks_ok) {
      outcome.exit_code = 1;
      outcome.message = "failed its checks: " + failed;
    } else {
      outcome.message = c.run->message();
    }
  } catch (...) {
    std::error_code ec;
    fs::remove_all(tmp_dir, ec);
    throw;
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return outcome;
}

std::vector<std::string> finish_reports(const RunOptions& options, int jobs) {
  std::vector<std::string> problems;
  if (options.pdf) {
    // every case page without an up-to-date pdf, including cases skipped as already done
    std::vector<fs::path> todo;
    if (fs::is_directory(options.out_dir))
      for (const auto& e : fs::directory_iterator(options.out_dir)) {
        const fs::path html = e.path() / "index.html", pdf = e.path() / "report.pdf";
        if (!e.is_directory() || e.path().filename().string().starts_with(".") || !fs::exists(html))
          continue;
        if (!fs::exists(pdf) || fs::last_write_time(pdf) < fs::last_write_time(html))
          todo.push_back(e.path());
      }
    std::sort(todo.begin(), todo.end());
    std::atomic<size_t> next{0};
    std::mutex mu;
    auto worker = [&] {
      for (size_t i = next++; i < todo.size(); i = next++) {
        try {
          report::print_pdf(todo[i] / "index.html", todo[i] / "report.pdf");
        } catch (const std::exception& e) {
          std::lock_guard<std::mutex> lock(mu);
          problems.push_back(todo[i].filename().string() + ": no report.pdf: " + e.what());
        }
      }
    };
    std::vector<std::thread> pool;
    const size_t n = std::min<size_t>(std::max(1, jobs), std::max<size_t>(1, todo.size()));
    for (size_t k = 1; k < n; ++k) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
  }
  try {
    report::write_index(options.out_dir);
  } catch (const std::exception& e) {
    problems.push_back(std::string("cannot write the index page: ") + e.what());
  }
  return problems;
}

}  // namespace armstudy::app
