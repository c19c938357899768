// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Progress of long work on stderr: a live bar with time left on a terminal, plain
/// periodic lines otherwise (CI logs). Thread-safe; one line per task.
///
/// Progress is real: the time left is extrapolated from the time elapsed *now* (so it grows
/// while a stage reports nothing, instead of standing at "0:00 left"), is shown only once
/// there is something to extrapolate from (2 % done and 3 s elapsed: "time left unknown"
/// before), and a heartbeat redraws every running task at least once a `period` even
/// when no stage reports, saying how long ago the last report was.

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

#include "studies/common.hpp"

namespace armstudy::cli {

class ProgressReporter {
 public:
  using Clock = std::chrono::steady_clock;
  /// `live`: redraw one line in place (a terminal); otherwise print a line every `period`.
  /// Starts the heartbeat thread.
  ProgressReporter(std::FILE* out, bool live,
                   std::chrono::seconds period = std::chrono::seconds(5));
  /// For tests: time from `clock`, no heartbeat thread (call heartbeat() instead).
  ProgressReporter(std::FILE* out, bool live, std::chrono::seconds period,
                   std::function<Clock::time_point()> clock);
  ~ProgressReporter();
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  /// A callback for one task named `task` (e.g. the case name). The task runs until its
  /// callback (and every copy of it) is destroyed or reports a fraction of 1.
  studies::ProgressFn task(std::string task);
  /// Prints a whole line (clearing a live bar first).
  void line(std::string_view text);
  /// Prints a whole line to `to` (e.g. stdout, the answers), clearing a live bar first.
  void line(std::string_view text, std::FILE* to);
  /// Ends the live bar, if any, and stops the heartbeat.
  void finish();
  /// Redraws the running tasks if nothing was printed for a period (live: a second).
  void heartbeat();

  /// "45 % integrating, 1:10 elapsed, about 1:25 left" (no task name); for tests.
  static std::string status_text(double fraction, std::string_view stage, double elapsed_s,
                                 double since_report_s);

 private:
  struct Task {
    std::string name;
    Clock::time_point start;
    Clock::time_point last_report;
    Clock::time_point last_print{};  ///< of this task (a log line each, a live bar shared)
    double fraction = 0;
    std::string stage;
  };
  void update(int id, double fraction, std::string_view stage);
  void remove(int id);
  void print_locked(Task& t, Clock::time_point now);
  std::chrono::milliseconds redraw_period() const;

  std::FILE* out_;
  bool live_;
  std::chrono::seconds period_;
  std::function<Clock::time_point()> clock_;
  std::mutex mu_;
  std::condition_variable wake_;
  std::map<int, Task> tasks_;
  int next_id_ = 0;
  Clock::time_point last_print_{};
  bool bar_shown_ = false;
  bool stop_ = false;
  std::thread heartbeat_;
};

/// True when stderr is a terminal and TERM is not "dumb".
bool stderr_is_terminal();

}  // namespace armstudy::cli
