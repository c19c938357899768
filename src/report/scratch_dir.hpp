#pragma once
/// Where armstudy keeps what it has not finished writing in an output folder: a hidden
/// scratch folder `.armstudy-<tag>` (tag: host, pid and a random number, unique to the
/// process) holding a file `lock` that the process keeps flock()ed while it lives. A case
/// is built in `<scratch>/new/<case>/`; an earlier report being replaced waits in
/// `<scratch>/old/<case>/` (only where the file system cannot exchange two folders in one
/// step). Another process tells a live scratch folder from one a killed run left behind by
/// trying its lock: that works across hosts sharing the folder and across pid namespaces
/// (containers), where host name plus pid does not. A scratch folder is removed by first
/// renaming it to `.armstudy-<tag>.removing`, which anyone may remove.

#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

namespace armstudy::report {

/// "<host>-<pid>-<8 hex digits>", the same for the whole life of this process.
const std::string& process_tag();

/// This process's scratch folder in `dir`, created and locked on first use (`dir` must
/// exist). Removed when the process exits normally (or by remove_own_scratch()).
/// @throws std::runtime_error naming the folder and the system's reason.
std::filesystem::path scratch_dir(const std::filesystem::path& dir);

/// From now on no scratch folder is made: a thread that asks for one waits until the process
/// ends. A signal's clean-up calls it first, so that another thread (one that the stopped
/// browser let go on, say) cannot make a folder after remove_own_scratch() and before the
/// exit.
void stop_scratch();

/// Empties and removes every scratch folder of this process, first moving each earlier
/// report waiting in `old/` back into place when no report of that name is there. Takes
/// swap_mutex(), so a folder swap is never cut in two.
void remove_own_scratch();

/// What remove_stale_scratch() did.
struct StaleCleanup {
  size_t removed = 0;                 ///< scratch folders and temporary files removed
  std::vector<std::string> restored;  ///< case folders put back from a killed run's `old/`
};

/// In `dir` and each of its sub-folders that armstudy wrote (a case folder, the sweep
/// report: report/owned_output.hpp): removes the scratch folders whose lock no process
/// holds (after moving each report of their `old/` back into `dir` when `dir` has none of
/// that name). Also handles what earlier armstudy versions left: hidden
/// `.<name>.old-<host>-<pid>` folders are put back the same way, and
/// `.<name>.tmp-<host>-<pid>` entries and `<file>.part-<pid>-<n>` files older than ten
/// minutes are removed (directly in `dir` only those of a run-level file). Only entries of
/// those names that are real folders or files are touched, each through its open folder
/// (report/safe_remove.hpp): a link is never followed nor removed, a user's folder never
/// entered.
StaleCleanup remove_stale_scratch(const std::filesystem::path& dir);

/// Held while a case folder is swapped into place and while a signal's clean-up runs.
std::mutex& swap_mutex();

/// Writes `text` to `path` through its temporary sibling (part_path) and a rename. On any
/// failure the temporary file is removed and the error says why ("No space left on
/// device", "Permission denied").
/// @throws std::runtime_error "cannot write <path>: <reason>"
void write_file_atomic(const std::filesystem::path& path, const std::string& text);

/// "cannot <what> <path>: <strerror(err)>"
std::string system_error_text(const std::string& what, const std::filesystem::path& path, int err);

}  // namespace armstudy::report
