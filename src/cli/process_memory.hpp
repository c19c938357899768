// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// How the process keeps the memory it frees. On this project's virtual machines a page
/// fault costs far more than on bare metal, and glibc's defaults hand large freed blocks
/// (frames, tiled strips, PNG bands: 1-17 MB each) back to the kernel at once, so that
/// the next frame or strip faults its pages in again: a 16-frame strip compressed on two
/// threads spent more time in page faults than in zlib (BM_Strip16Frames640x480).

namespace armstudy::cli {

/// Keeps freed memory in the process for reuse: blocks up to 32 MiB (glibc's largest
/// mmap threshold) come from the heap, and the heap is given back to the kernel only when
/// more than 1 GiB of it is free. Peak memory is unchanged; memory freed after the peak
/// stays with the process until it ends. Call once, first thing in main, before any
/// thread starts. A no-op where the C library has no mallopt.
void keep_freed_memory();

}  // namespace armstudy::cli
