#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# armstudy set-up, command 1 of the README: installs every Debian package the project
# needs (only the missing ones; fast when all are there), builds in Release and renders
# every bundled case under reports/cases/ into reports/out/.
#
#   scripts/setup.sh              install, build, render the bundled reports
#   scripts/setup.sh --no-reports install and build only (used by scripts/test.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
reports=1
[ "${1:-}" = "--no-reports" ] && reports=0

# --- packages --------------------------------------------------------------------------
mapfile -t wanted < <(grep -v '^\s*#' scripts/packages.txt | sed '/^\s*$/d')
missing=()
for p in "${wanted[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${#missing[@]} package(s): ${missing[*]}"
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "setup: all ${#wanted[@]} packages already installed"
fi

# --- build -----------------------------------------------------------------------------
jobs=$(nproc 2>/dev/null || echo 2)
# ARMSTUDY_WERROR=ON (scripts/test.sh, the CI build): every compiler warning fails the build
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DARMSTUDY_WERROR="${ARMSTUDY_WERROR:-OFF}" >/dev/null
cmake --build build -j"$jobs"
echo "setup: built $root/build/armstudy"

# --- bundled reports -------------------------------------------------------------------
if [ "$reports" = 1 ]; then
  # LP_NUM_THREADS left to llvmpipe (one rasteriser thread per core): its threads are shared
  # by all the cases --jobs runs at once, and LP_NUM_THREADS=1 would give the whole run one
  status=0
  ./build/armstudy run reports/cases/*.yaml --out reports/out --pdf --jobs "$jobs" || status=$?
  echo "setup: reports in $root/reports/out/ (open $root/reports/out/index.html)"
  exit $status
fi
