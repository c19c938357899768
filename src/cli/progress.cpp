// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace armstudy::cli {
namespace {
std::string clock_text(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--:--";
  const long s = std::lround(seconds);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

// a task's registration: removed when the last copy of its callback goes
struct Registration {
  std::function<void()> on_last_copy;
  ~Registration() {
    if (on_last_copy) on_last_copy();
  }
};
}  // namespace

bool stderr_is_terminal() {
  const char* term = std::getenv("TERM");
  return isatty(STDERR_FILENO) && !(term && std::string_view(term) == "dumb");
}

ProgressReporter::ProgressReporter(std::FILE* out, bool live, std::chrono::seconds period)
    : ProgressReporter(out, live, period, [] { return Clock::now(); }) {
  heartbeat_ = std::thread([this] {
    std::unique_lock<std::mutex> lock(mu_);
    while (!stop_) {
      wake_.wait_for(lock, std::chrono::seconds(1));  // heartbeat() judges what is due
      if (stop_) break;
      lock.unlock();
      heartbeat();
      lock.lock();
    }
  });
}

ProgressReporter::ProgressReporter(std::FILE* out, bool live, std::chrono::seconds period,
                                   std::function<Clock::time_point()> clock)
    : out_(out), live_(live), period_(period), clock_(std::move(clock)) {}

ProgressReporter::~ProgressReporter() { finish(); }

std::chrono::milliseconds ProgressReporter::redraw_period() const {
  return live_ ? std::chrono::milliseconds(1000)
               : std::chrono::duration_cast<std::chrono::milliseconds>(period_);
}

studies::ProgressFn ProgressReporter::task(std::string task) {
  int id = 0;
  {
    std::lock_guard<std::mutex> lock(mu_);
    id = next_id_++;
    const auto now = clock_();
    Task t;
    t.name = std::move(task);
    t.start = now;
    t.last_report = now;
    tasks_[id] = std::move(t);
  }
  auto reg = std::make_shared<Registration>();
  reg->on_last_copy = [this, id] { remove(id); };
  return [this, id, reg](double f, std::string_view stage) { update(id, f, stage); };
}

void ProgressReporter::remove(int id) {
  std::lock_guard<std::mutex> lock(mu_);
  tasks_.erase(id);
}

std::string ProgressReporter::status_text(double f, std::string_view stage, double elapsed,
                                          double since_report) {
  f = std::clamp(f, 0.0, 1.0);
  // extrapolated from the time elapsed now: a stage that reports nothing makes it grow
  const bool known = f >= 0.02 && elapsed >= 3.0;
  const double left = known ? elapsed * (1.0 - f) / f : NAN;
  char pct[16];
  std::snprintf(pct, sizeof pct, "%3.0f %%", std::floor(f * 100));
  std::string s = pct;
  if (!stage.empty()) s += " " + std::string(stage);
  s += ", " + clock_text(elapsed) + " elapsed, ";
  s += known ? "about " + clock_text(left) + " left" : std::string("time left unknown");
  if (since_report >= 30) s += " (last report " + clock_text(since_report) + " ago)";
  return s;
}

void ProgressReporter::print_locked(Task& t, Clock::time_point now) {
  const double elapsed = std::chrono::duration<double>(now - t.start).count();
  const double since = std::chrono::duration<double>(now - t.last_report).count();
  const std::string status = status_text(t.fraction, t.stage, elapsed, since);
  if (live_) {
    const int width = 28, filled = static_cast<int>(std::clamp(t.fraction, 0.0, 1.0) * width);
    std::string bar(filled, '#');
    bar += std::string(width - filled, '.');
    std::fprintf(out_, "\r\033[K%s [%s] %s", t.name.c_str(), bar.c_str(), status.c_str());
    bar_shown_ = true;
  } else {
    std::fprintf(out_, "%s: %s\n", t.name.c_str(), status.c_str());
  }
  std::fflush(out_);
  last_print_ = now;
  t.last_print = now;
}

void ProgressReporter::update(int id, double f, std::string_view stage) {
  std::lock_guard<std::mutex> lock(mu_);
  const auto it = tasks_.find(id);
  if (it == tasks_.end()) return;
  Task& t = it->second;
  const auto now = clock_();
  t.fraction = std::clamp(f, 0.0, 1.0);
  t.stage.assign(stage.data(), stage.size());
  t.last_report = now;
  if (f >= 1.0) {  // done: the caller prints the outcome line
    tasks_.erase(it);
    return;
  }
  const bool due =
      live_ ? now - last_print_ >= std::chrono::milliseconds(100) : now - t.last_print >= period_;
  if (due) print_locked(t, now);
}

void ProgressReporter::heartbeat() {
  std::lock_guard<std::mutex> lock(mu_);
  if (stop_ || tasks_.empty()) return;
  const auto now = clock_();
  if (live_) {
    if (now - last_print_ < redraw_period()) return;
    // the task reported last (a live bar is one line)
    Task* latest = &tasks_.begin()->second;
    for (auto& [id, t] : tasks_)
      if (t.last_report > latest->last_report) latest = &t;
    print_locked(*latest, now);
  } else {
    for (auto& [id, t] : tasks_)
      if (now - t.last_print >= period_) print_locked(t, now);
  }
}

void ProgressReporter::line(std::string_view text) { line(text, out_); }

void ProgressReporter::line(std::string_view text, std::FILE* to) {
  std::lock_guard<std::mutex> lock(mu_);
  if (bar_shown_) std::fprintf(out_, "\r\033[K");
  std::fflush(out_);
  bar_shown_ = false;
  std::fprintf(to, "%.*s\n", static_cast<int>(text.size()), text.data());
  std::fflush(to);
}

void ProgressReporter::finish() {
  {
    std::lock_guard<std::mutex> lock(mu_);
    stop_ = true;
    if (bar_shown_) std::fprintf(out_, "\r\033[K");
    bar_shown_ = false;
    std::fflush(out_);
  }
  wake_.notify_all();
  if (heartbeat_.joinable()) heartbeat_.join();
}

}  // namespace armstudy::cli
