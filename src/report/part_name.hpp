#pragma once
/// Names of files being written, renamed into place when complete, so that processes and
/// threads writing the same output folder (shards of a sweep finishing together, say)
/// never write into each other's temporary file, and a killed run's leftovers are only
/// ever inside its own scratch folder (report/scratch_dir.hpp), which the next run removes.

#include <filesystem>

#include "report/scratch_dir.hpp"

namespace armstudy::report {

/// The temporary file for `path` for this process and thread: `<file>.part-<thread>` in
/// this process's scratch folder of `path`'s folder (created on first use), or beside
/// `path` when that folder is itself inside one of this process's scratch folders.
/// @throws std::runtime_error when the scratch folder cannot be made (saying why).
std::filesystem::path part_path(const std::filesystem::path& path);

}  // namespace armstudy::report
