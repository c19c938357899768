// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// `armstudy --version`: armstudy's version and commit, then the libraries it runs with and
/// the browser --pdf would use.

#include <string>

namespace armstudy::cli {

/// Lines "armstudy VERSION (commit C)", then MuJoCo, OSMesa/Mesa (from a 1 x 1 context's
/// GL_VERSION and GL_RENDERER), Eigen, yaml-cpp, NLopt and the browser (its own --version,
/// given `browser_timeout_ms` before it is killed); "not found" for what is absent.
/// No newline at the end. Never throws.
std::string version_text(int browser_timeout_ms = 5000);

/// The first line `program --version` prints on its standard output, or "" when it cannot
/// start, prints nothing, fails, or has not ended within `timeout_ms` (then it is killed
/// with its process group). Never waits longer than `timeout_ms` plus a kill.
std::string program_version_line(const std::string& program, int timeout_ms);

}  // namespace armstudy::cli
