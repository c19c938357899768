// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The benchmarks run under armstudy's memory policy (cli/process_memory.hpp), which
// armstudy's main sets first thing: set here before main, for every benchmark alike.
#include "cli/process_memory.hpp"

namespace {
const bool kMemoryPolicy = (armstudy::cli::keep_freed_memory(), true);
}  // namespace
