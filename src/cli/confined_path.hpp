// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Paths taken from files armstudy reads (a sweep's `base:`, the `frames` and `files` of a
/// results.json) stay in their place: inside a given folder, symlinks resolved.

#include <filesystem>
#include <string>

namespace armstudy::cli {

/// True if `path` (made absolute, symlinks resolved as far as it exists) lies in `root`
/// (resolved the same way) or is `root`.
bool lies_inside(const std::filesystem::path& path, const std::filesystem::path& root);

/// Why `rel`, a path a results.json gives relative to its case folder, may not be read
/// ("" if it may): empty, absolute, with a `..`, or leading out of `folder` through a
/// symlink.
std::string confined_problem(const std::filesystem::path& folder, const std::string& rel);

}  // namespace armstudy::cli
