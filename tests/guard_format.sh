#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# The code follows the project's .clang-format: every tracked C++ file is as clang-format
# (Debian's clang-format 14, scripts/packages.txt) would write it. Format a file with
# `clang-format -i FILE` before committing.
cd "$1" || exit 2
command -v clang-format >/dev/null 2>&1 || { echo "clang-format is not installed (scripts/packages.txt)"; exit 1; }
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  files=$(git ls-files '*.cpp' '*.hpp' '*.h')
else
  files=$(find src tests scripts -name '*.cpp' -o -name '*.hpp' -o -name '*.h')
fi
# 40 files a clang-format process, two at a time (one process a file took about a minute);
# a batch that fails is checked file by file to name the files
bad=$(printf '%s\n' $files | xargs -P 2 -n 40 sh -c \
  'clang-format --dry-run --Werror "$@" >/dev/null 2>&1 ||
   for f in "$@"; do clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || echo "$f"; done' sh)
if [ -n "$bad" ]; then
  echo "files not formatted as .clang-format says (run clang-format -i on them):"
  for f in $bad; do echo "  $f"; done
  exit 1
fi
echo "every C++ file follows .clang-format"
