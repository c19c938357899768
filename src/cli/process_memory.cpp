// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/process_memory.hpp"

#include <cstdlib>  // (defines __GLIBC__ on glibc)

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace armstudy::cli {

void keep_freed_memory() {
#if defined(__GLIBC__)
  // fixed thresholds (mallopt turns glibc's dynamic ones off): no block below 32 MiB is
  // mapped on its own, and the heap's free top (every arena's) is trimmed above 1 GiB
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

}  // namespace armstudy::cli
