// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// libFuzzer target for the case and sweep loaders: every input goes through
// fuzz::case_and_sweep_loaders (fuzz_entries.hpp: as a case file, as a sweep file and as a
// sweep's base case) and fuzz::template_folder_reader (as a report template of an
// ARMSTUDY_TEMPLATE_DIR folder). A loader may refuse an input only with cases::CaseErrors, each
// error with a message; anything else (another exception, a crash, a leak, undefined behaviour, a
// hang, a runaway allocation) is a finding.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz/fuzz_entries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::string problem = armstudy::fuzz::case_and_sweep_loaders(input);
  if (problem.empty()) problem = armstudy::fuzz::template_folder_reader(input);
  if (!problem.empty()) {
    std::fprintf(stderr, "finding: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
