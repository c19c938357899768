// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/open_files.hpp"

#include <sys/resource.h>

#include <algorithm>

namespace armstudy::cli {

std::string ensure_open_files() {
  struct rlimit rl {};
  if (::getrlimit(RLIMIT_NOFILE, &rl) != 0) return "";
  constexpr rlim_t kWanted = 1024;
  if (rl.rlim_cur != RLIM_INFINITY && rl.rlim_cur < kWanted &&
      (rl.rlim_max == RLIM_INFINITY || rl.rlim_max > rl.rlim_cur)) {
    struct rlimit raised = rl;
    raised.rlim_cur = rl.rlim_max == RLIM_INFINITY ? kWanted : std::min(kWanted, rl.rlim_max);
    if (::setrlimit(RLIMIT_NOFILE, &raised) == 0) rl = raised;
  }
  if (rl.rlim_cur == RLIM_INFINITY || rl.rlim_cur >= static_cast<rlim_t>(kMinOpenFiles)) return "";
  return "the limit of open files (ulimit -n) is " + std::to_string(rl.rlim_cur) +
         "; armstudy needs at least " + std::to_string(kMinOpenFiles) +
         " (rendering holds frames, plots, pipes to ffmpeg and helpers open at once); "
         "nothing was written";
}

}  // namespace armstudy::cli
