// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
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
#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace armstudy::sys {

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

/// What of an output folder remove_stale_scratch() may look into: the caller's knowledge
/// of which entries it wrote (this layer knows none).
struct StaleRules {
  /// true when `dir`/`name` is a sub-folder the caller wrote (its scratch folders and part
  /// files are cleaned too)
  std::function<bool(const std::filesystem::path& dir, const std::string& name)> own_sub_folder;
  /// true when `base` (a file name directly in `dir`) is one of the caller's files, so that an
  /// old-style part file `<base>.part-<pid>-<n>` beside it may be removed
  std::function<bool(const std::string& base)> run_level_file;
};

/// In `dir` and each of its sub-folders that the caller wrote (`rules.own_sub_folder`;
/// armstudy's: report::remove_stale_scratch, report/owned_output.hpp): removes the scratch folders
/// whose lock no process holds (after moving each report of their `old/` back into `dir` when `dir`
/// has none of that name). Also handles what earlier armstudy versions left: hidden
/// `.<name>.old-<host>-<pid>` folders are put back the same way, and
/// `.<name>.tmp-<host>-<pid>` entries and `<file>.part-<pid>-<n>` files older than ten
/// minutes are removed (directly in `dir` only those of a file `rules.run_level_file` names). Only
/// entries of those names that are real folders or files are touched, each through its open folder
/// (sys/safe_remove.hpp): a link is never followed nor removed, a user's folder never
/// entered.
StaleCleanup remove_stale_scratch(const std::filesystem::path& dir, const StaleRules& rules);

/// Held while a case folder is swapped into place and while a signal's clean-up runs.
std::mutex& swap_mutex();

}  // namespace armstudy::sys
