#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# core and studies are pure: no file or console I/O, no YAML, no MuJoCo, no system plumbing
# (src/sys: processes, files, locks) (docs/development.md, Layout).
# MuJoCo is its headers and calls (mujoco/..., mj_*): a results.json key such as
# "mujoco_replay" in a study's typed results (study_results.hpp) is data, not a use of it.
cd "$1" || exit 2
hits=$(grep -rnE '#include <(fstream|iostream)>|yaml-cpp|mujoco/|mujoco\.h|mj[A-Za-z]*_[a-z]|std::cout|std::cerr|printf\(|#include "sys/' src/core src/studies)
if [ -n "$hits" ]; then
  echo "impure includes or output in src/core or src/studies:"; echo "$hits"; exit 1
fi
echo "src/core and src/studies are pure"
