// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// SIGINT, SIGTERM and SIGHUP: armstudy stops at once, kills the browsers it started,
/// puts back any earlier report a folder swap had moved aside, removes its unfinished
/// output and exits 128 + the signal's number (130 for SIGINT), so that an interrupted run
/// leaves only complete reports behind.

namespace armstudy::cli {

/// Blocks those signals in the calling thread (call it first in main, before any thread
/// starts, so every thread inherits the mask) and starts the thread that waits for them.
void install_interrupt_cleanup();

}  // namespace armstudy::cli
