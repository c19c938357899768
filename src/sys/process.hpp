// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Starting other programs: finding one on PATH and spawning it with its file descriptors,
/// process group, signal mask and (optionally) death signal set up. armstudy blocks the
/// termination signals in every thread and ignores SIGPIPE; a child starts with no signal
/// blocked and the signals it names back at their defaults.

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace armstudy::sys {

/// true when `p` is a regular file this process may execute.
bool is_executable(const std::filesystem::path& p);

/// The first of `names` found executable in a folder of PATH (each name is looked for in
/// every folder before the next name); an empty PATH entry is the current folder, and with
/// no PATH "/usr/local/bin:/usr/bin:/bin" is searched. "" when none is found.
std::string find_on_path(const std::vector<std::string>& names);

/// This process's environment, as "NAME=value" strings.
std::vector<std::string> current_environment();

/// A file the child gets open on some of its descriptors (one open file description: two
/// descriptors of a log share its offset).
struct ChildFile {
  std::filesystem::path path;
  int flags = 0;  ///< open(2) flags, e.g. O_WRONLY | O_CREAT | O_TRUNC
  mode_t mode = 0600;
  std::vector<int> child_fds;  ///< e.g. {1, 2}
};

struct SpawnOptions {
  std::vector<std::string> argv;  ///< argv[0] is the program's path (no PATH search)
  std::vector<std::string> env;   ///< the child's environment, "NAME=value"
  /// {descriptor of this process, descriptor number in the child}; the same descriptor may
  /// be given for several child numbers
  std::vector<std::pair<int, int>> fds;
  std::vector<ChildFile> files;      ///< opened for the child (after `fds`)
  std::vector<int> default_signals;  ///< set back to SIG_DFL in the child
  bool own_group = false;            ///< the child leads a new process group (killed whole)
  /// sent to the child when the thread that spawned it ends (PR_SET_PDEATHSIG; 0: none). A
  /// child with a death signal is started with fork and exec (only async-signal-safe calls
  /// in between), which also checks that its parent did not end before the signal was set.
  int death_signal = 0;
};

/// Seconds a helper process (the frame helper armstudy-frames, ffmpeg) may go without
/// progress (no answer, no input taken, not ended) before armstudy ends it:
/// $ARMSTUDY_HELPER_TIMEOUT_S when it is a number in [0.1, 86400], else 120.
double helper_timeout_seconds();

/// Starts the child; its pid, or -1 with *error set to the errno value. A child whose
/// program cannot be executed (after fork) exits with status 127.
pid_t spawn(const SpawnOptions& o, int* error);

}  // namespace armstudy::sys
