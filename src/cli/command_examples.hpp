// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The "Examples:" each command's --help ends with (scripts/cli_docs.py makes them the man
/// pages' EXAMPLES section).

#include <CLI/CLI.hpp>

namespace armstudy::cli {

/// Appends its examples to the footer of armstudy and of every command of `app`.
void add_examples(CLI::App& app);

}  // namespace armstudy::cli
