// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Names of files being written, renamed into place when complete, so that processes and
/// threads writing the same output folder (shards of a sweep finishing together, say)
/// never write into each other's temporary file, and a killed run's leftovers are only
/// ever inside its own scratch folder (sys/scratch_dir.hpp), which the next run removes.

#include <filesystem>

#include <string>

namespace armstudy::sys {

/// The temporary file for `path` for this process and thread: `<file>.part-<thread>` in
/// this process's scratch folder of `path`'s folder (created on first use), or beside
/// `path` when that folder is itself inside one of this process's scratch folders.
/// @throws std::runtime_error when the scratch folder cannot be made (saying why).
std::filesystem::path part_path(const std::filesystem::path& path);

/// Writes `text` to `path` through its temporary sibling (part_path) and a rename. On any
/// failure the temporary file is removed and the error says why ("No space left on
/// device", "Permission denied").
/// @throws std::runtime_error "cannot write <path>: <reason>"
void write_file_atomic(const std::filesystem::path& path, const std::string& text);

/// "cannot <what> <path>: <strerror(err)>"
std::string system_error_text(const std::string& what, const std::filesystem::path& path, int err);

}  // namespace armstudy::sys
