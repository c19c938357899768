// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The one way armstudy reads a file it did not just write itself (a case or sweep file,
/// --tolerances, results.json in run's skip check, merge and diff, a frame read by diff):
/// only a regular file is read, at most a stated number of bytes, and opening or reading
/// never blocks (a FIFO without a writer, a device, a folder or a symlink loop is refused
/// at once, with a message that says what the path is and what was expected).

#include <cstddef>
#include <stdexcept>
#include <string>

namespace armstudy::cases {

/// results.json of one case: the bundled ones are below 1 MiB.
inline constexpr std::size_t kMaxResultsJsonBytes = std::size_t(16) << 20;
/// A frame (PNG) that diff compares: 640 x 480 frames are below 100 kB.
inline constexpr std::size_t kMaxFrameBytes = std::size_t(64) << 20;

struct InputFileRules {
  std::size_t max_bytes = 0;
  /// What the file should be, for messages ("expected a regular <kind>"): "YAML file",
  /// "results.json file", "PNG frame".
  std::string kind = "file";
  /// false: a symbolic link as the last part of the path is refused (files armstudy
  /// wrote into its own folders are never links; a user's case file may be one).
  bool follow_symlink = true;
};

/// Why a file could not be read. `runtime()` is true when the file is not at fault (out of
/// file descriptors or memory, an I/O error): exit 3; otherwise the input is: exit 2.
class InputFileError : public std::runtime_error {
 public:
  InputFileError(const std::string& what, bool runtime)
      : std::runtime_error(what), runtime_(runtime) {}
  bool runtime() const { return runtime_; }

 private:
  bool runtime_;
};

/// The bytes of `path` under `rules`; false and `*why` (the problem, without the path)
/// otherwise, `*runtime` as InputFileError::runtime().
bool read_input_file(const std::string& path, const InputFileRules& rules, std::string* bytes,
                     std::string* why, bool* runtime);

/// As above; @throws InputFileError "<path>: <why>".
std::string read_input_file(const std::string& path, const InputFileRules& rules);

/// An errno value as words, with a hint where it is the process's limit that ran out
/// (EMFILE names `ulimit -n` and the limit).
std::string errno_text(int err);

}  // namespace armstudy::cases
