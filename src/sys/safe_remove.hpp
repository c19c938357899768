// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Removing what armstudy named itself, never through a symbolic link: every step works on
/// an open folder (openat, unlinkat with O_NOFOLLOW), so that a link put where a scratch
/// folder or a Chromium profile is expected (or swapped in while it is removed) is removed
/// itself and whatever it points to stays untouched.

#include <sys/stat.h>

#include <filesystem>
#include <string>
#include <vector>

namespace armstudy::sys {

/// The entry `name` of the open folder `dir_fd`, and everything under it when it is a real
/// folder; a symbolic link is removed, never followed. Returns the entries removed (0 when
/// it was missing or could not be removed).
size_t remove_tree_at(int dir_fd, const std::string& name);

/// The folder `path` opened for openat (O_DIRECTORY | O_NOFOLLOW: its last component must
/// not be a link), or -1 with errno set.
int open_folder(const std::filesystem::path& path);

/// The names in the open folder `dir_fd` (without "." and "..").
std::vector<std::string> list_folder(int dir_fd);

/// The sub-folder `name` of `dir_fd` opened for openat, never through a link; -1 if it is
/// not a real folder.
int open_folder_at(int dir_fd, const std::string& name);

/// The entry `name` of `dir_fd` as lstat sees it; false when it is missing.
bool stat_at(int dir_fd, const std::string& name, struct stat* st);

}  // namespace armstudy::sys
