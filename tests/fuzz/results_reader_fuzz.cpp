// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// libFuzzer target for the readers of run output: every input goes through
// fuzz::results_and_tolerances_readers (fuzz_entries.hpp: as a case's results.json the way
// `armstudy merge` and `armstudy diff` read it, with the merged tables written from it, and
// as a `diff --tolerances` file). A file that cannot be used must become a failed case or
// a CaseErrors with messages; anything else (another exception, a crash, a leak, undefined
// behaviour, a hang, a runaway allocation) is a finding.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz/fuzz_entries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string problem = armstudy::fuzz::results_and_tolerances_readers(
      std::string(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "finding: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
