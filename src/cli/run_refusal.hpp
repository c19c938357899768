// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Why a command refused to start (bad usage, a bad case file, an output folder it will not
/// write over), said on stderr and kept, so that `run --json` still prints one JSON document
/// when no case ran.

#include <string>

namespace armstudy::cli {

/// Prints `text` and a newline to stderr and keeps it for refusal_json().
void say_refusal(const std::string& text);

/// Keeps `text` for refusal_json() without printing it (what a library printed itself).
void keep_refusal(const std::string& text);

/// Whether the command line is `armstudy run ... --json`, read from argv itself (so that it is
/// known when the parse failed before reaching --json).
bool run_json_requested(int argc, const char* const* argv);

/// The document `run --json` prints when it stopped before any case ran: the output folder,
/// the exit code, the error (every refusal said, in order, one per line) and no cases.
std::string refusal_json(const std::string& out_dir, int exit_code);

}  // namespace armstudy::cli
