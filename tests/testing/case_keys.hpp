// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
// The keys of a case file's root that the CLI reads itself (app::load_case), for tests that
// load one study's section of a bundled case directly with its loader.

#include "cases/yaml_reader.hpp"

namespace armstudy::testing {

/// Marks study, name, description, expect, render, sweep, source and sensitivity as known in
/// `root`, so that root.finish() judges only the study's own keys.
inline void mark_cli_keys(cases::Map& root) {
  for (const char* k :
       {"study", "name", "description", "expect", "render", "sweep", "source", "sensitivity"})
    root.get(k);
}

}  // namespace armstudy::testing
