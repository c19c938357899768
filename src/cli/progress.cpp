#include "cli/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>

namespace armstudy::app {
namespace {
std::string clock_text(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--:--";
  const long s = std::lround(seconds);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}
}  // namespace

bool stderr_is_terminal() {
  const char* term = std::getenv("TERM");
  return isatty(STDERR_FILENO) && !(term && std::string_view(term) == "dumb");
}

ProgressReporter::ProgressReporter(std::FILE* out, bool live, std::chrono::seconds period)
    : out_(out), live_(live), period_(period) {}

studies::ProgressFn ProgressReporter::task(std::string task) {
  const auto start = std::chrono::steady_clock::now();
  return [this, task = std::move(task), start](double f, std::string_view stage) {
    update(task, f, stage, start);
  };
}

void ProgressReporter::update(const std::string& task, double f, std::string_view stage,
                              std::chrono::steady_clock::time_point start) {
  const auto now = std::chrono::steady_clock::now();
  std::lock_guard<std::mutex> lock(mu_);
  const bool due = live_ ? now - last_print_ >= std::chrono::milliseconds(100)
                         : now - last_print_ >= period_;
  if (!due && f < 1.0) return;
  if (!live_ && f >= 1.0) return;  // the caller prints the outcome line
  last_print_ = now;
  f = std::clamp(f, 0.0, 1.0);
  const double elapsed = std::chrono::duration<double>(now - start).count();
  const double left = f > 0.01 ? elapsed * (1.0 - f) / f : NAN;
  if (live_) {
    const int width = 28, filled = static_cast<int>(f * width);
    std::string bar(filled, '#');
    bar += std::string(width - filled, '.');
    std::fprintf(out_, "\r\033[K%s [%s] %3.0f%% %.*s, %s left", task.c_str(), bar.c_str(), f * 100,
                 static_cast<int>(stage.size()), stage.data(), clock_text(left).c_str());
    bar_shown_ = true;
  } else {
    std::fprintf(out_, "%s: %3.0f%% %.*s (elapsed %s, about %s left)\n", task.c_str(), f * 100,
                 static_cast<int>(stage.size()), stage.data(), clock_text(elapsed).c_str(),
                 clock_text(left).c_str());
  }
  std::fflush(out_);
}

void ProgressReporter::line(std::string_view text) {
  std::lock_guard<std::mutex> lock(mu_);
  if (bar_shown_) std::fprintf(out_, "\r\033[K");
  bar_shown_ = false;
  std::fprintf(out_, "%.*s\n", static_cast<int>(text.size()), text.data());
  std::fflush(out_);
}

void ProgressReporter::finish() {
  std::lock_guard<std::mutex> lock(mu_);
  if (bar_shown_) std::fprintf(out_, "\r\033[K");
  bar_shown_ = false;
  std::fflush(out_);
}

}  // namespace armstudy::app
