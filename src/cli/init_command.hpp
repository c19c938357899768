// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// `armstudy init STUDY [-o FILE]`: a case of STUDY with every key at its default
/// (app/case_keys.hpp), on stdout or into FILE.

#include <string>

namespace armstudy::cli {

/// Prints the case on stdout (out_file empty) or writes it to out_file, atomically; a file
/// already there is replaced only when it is exactly what `armstudy init` writes (for any
/// study), never a file armstudy did not write or one edited since. Returns the exit code:
/// 0 written, 2 an unknown study or a file that is not armstudy's, 3 a write that failed.
int cmd_init(const std::string& study, const std::string& out_file);

}  // namespace armstudy::cli
