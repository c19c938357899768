#pragma once
/// Progress of long work on stderr: a live bar with time left on a terminal, plain
/// periodic lines otherwise (CI logs). Thread-safe; one line per task.

#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>
#include <string_view>

#include "studies/common.hpp"

namespace armstudy::app {

class ProgressReporter {
 public:
  /// `live`: redraw one line in place (a terminal); otherwise print a line every `period`.
  ProgressReporter(std::FILE* out, bool live, std::chrono::seconds period = std::chrono::seconds(5));
  /// A callback for one task named `task` (e.g. the case name).
  studies::ProgressFn task(std::string task);
  /// Prints a whole line (clearing a live bar first).
  void line(std::string_view text);
  /// Ends the live bar, if any.
  void finish();

 private:
  void update(const std::string& task, double fraction, std::string_view stage,
              std::chrono::steady_clock::time_point start);
  std::FILE* out_;
  bool live_;
  std::chrono::seconds period_;
  std::mutex mu_;
  std::chrono::steady_clock::time_point last_print_{};
  bool bar_shown_ = false;
};

/// True when stderr is a terminal and TERM is not "dumb".
bool stderr_is_terminal();

}  // namespace armstudy::app
