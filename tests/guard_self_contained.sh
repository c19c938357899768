#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# The repository stands on its own: no tracked file (code, comments, README, docs, case
# files, models, templates, report text, tests) may point outside it. Forbidden: paths to a
# shared folder beside the clone (../shared, /work/shared, seeds/), the planning notes
# (SEEDS.md, DESIGN.md, STYLE.md), the source documents' catalogue file names
# (NNN_<16 hex digits>.txt) and issue-tracker numbers ("issue 4"). Cite docs/ instead,
# e.g. "eq. 5-7 of Sato et al. (docs/sources.md)". This script is the only exception.
cd "$1" || exit 2
pattern='\.\./shared|/work/shared|seeds/|SEEDS\.md|DESIGN\.md|STYLE\.md|\b[0-9]{3}_[0-9a-f]{16}\.txt|\b[Ii]ssues? #?[0-9]+'
self=tests/guard_self_contained.sh
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  hits=$(git grep -n -I -E "$pattern" -- . ":(exclude)$self")
else
  # a source tree without git (e.g. an unpacked archive): every file but generated output
  hits=$(grep -rnIE --exclude-dir=.git --exclude-dir=build --exclude-dir=out "$pattern" . |
         grep -v "^\./$self:")
fi
if [ -n "$hits" ]; then
  echo "files that point outside the repository (cite docs/ instead):"; echo "$hits"; exit 1
fi
echo "no tracked file points outside the repository"
