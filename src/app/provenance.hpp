// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Where a result came from: versions, compiler, machine, and the files written.

#include <filesystem>

#include <string>
#include <vector>

#include "report/results_record.hpp"

namespace armstudy::app {

/// armstudy_version, git_commit (if known), mujoco_version, compiler, cpu_model.
report::ProvenanceRecord provenance();

/// Every regular file under `dir` (relative path, size, sha256), sorted by path,
/// except `skip` (relative), e.g. results.json itself.
std::vector<report::FileRecord> list_files(const std::filesystem::path& dir,
                                           const std::string& skip);

}  // namespace armstudy::app
