#pragma once
/// Names of files being written: `<file>.part-<pid>-<thread>`, renamed into place when
/// complete, so that processes and threads writing the same output folder (shards of a
/// sweep finishing together, say) never write into each other's temporary file.

#include <unistd.h>

#include <filesystem>
#include <functional>
#include <string>
#include <thread>

namespace armstudy::report {

/// The temporary sibling of `path` for this process and thread.
inline std::filesystem::path part_path(const std::filesystem::path& path) {
  const size_t thread = std::hash<std::thread::id>{}(std::this_thread::get_id()) % 1000000;
  return path.string() + ".part-" + std::to_string(::getpid()) + "-" + std::to_string(thread);
}

}  // namespace armstudy::report
