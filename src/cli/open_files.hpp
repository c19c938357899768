// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The open files (file descriptors) a run needs. A run holds case files, PNGs, SVGs,
/// results.json, the frame helpers' sockets, ffmpeg's pipe and the browser's at once; with
/// too few (`ulimit -n 10`) PLplot found no driver, ffmpeg failed and a write to its pipe
/// killed armstudy with SIGPIPE. Checked once at the start instead: clear, and before
/// anything is written.

#include <string>

namespace armstudy::cli {

/// The least limit of open files that run, merge and diff accept: placement-example-2
/// with frames and videos ran at 12 and lost its videos at 10; a browser and --jobs need
/// more.
inline constexpr long kMinOpenFiles = 64;

/// Raises the soft limit of open files towards 1024 where the hard limit allows it (a
/// low soft limit is a default, not a choice); returns "" if the limit is then at least
/// kMinOpenFiles, otherwise the message saying so (for an exit 3).
std::string ensure_open_files();

}  // namespace armstudy::cli
