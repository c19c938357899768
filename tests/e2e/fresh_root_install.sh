#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
#
# The lean install of the Debian package on a fresh Debian bookworm root, as a new user
# would do it (docs/install.md): debootstrap a minimal root, install the package with
# `apt-get install --no-install-recommends`, say how many packages and megabytes that added,
# then, inside the root, start a case with `armstudy init`, validate and run it, and run a
# bundled case to a complete report (no --pdf: Chromium is only recommended). Not part of
# the test suite (it needs root, debootstrap, a Debian mirror and several minutes); run it
# before a release:
#
#   sudo tests/e2e/fresh_root_install.sh /tmp/pkg/armstudy_0.1.0-1_amd64.deb [MIRROR]
set -euo pipefail
deb=$(realpath "$1")
mirror=${2:-http://deb.debian.org/debian}
command -v debootstrap >/dev/null || { echo "needs debootstrap (apt-get install debootstrap)"; exit 2; }
root=$(mktemp -d /var/tmp/armstudy_fresh_root.XXXXXX)
cleanup() {
  umount -l "$root/proc" 2>/dev/null || true
  rm -rf "$root"
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

debootstrap --variant=minbase bookworm "$root" "$mirror" >"$root.debootstrap.log" 2>&1 ||
  { tail -20 "$root.debootstrap.log"; fail "debootstrap"; }
rm -f "$root.debootstrap.log"
mount -t proc proc "$root/proc"
in_root() { chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 "$@"; }
size_kb() { in_root dpkg-query -W -f '${Installed-Size}\n' | awk '{s += $1} END {print s}'; }
count() { in_root dpkg-query -W -f '${Package}\n' | wc -l; }

cp "$deb" "$root/tmp/"
packages_before=$(count)
kb_before=$(size_kb)
in_root apt-get update -qq
in_root apt-get install -y -qq --no-install-recommends "/tmp/$(basename "$deb")" >/dev/null
echo "the lean install added $(($(count) - packages_before)) packages," \
  "$(((($(size_kb) - kb_before) + 512) / 1024)) MB installed"

in_root armstudy --version
in_root sh -c 'cd /tmp && armstudy init pendulum -o p.yaml && armstudy validate p.yaml &&
  armstudy run p.yaml --out out --no-sensitivity' || fail "the init case did not run"
in_root sh -c 'cd /tmp && armstudy run \
  /usr/share/doc/armstudy/examples/cases/placement-example-2.yaml --out out' ||
  fail "the bundled case did not run"
for f in results.json index.html model.xml; do
  [ -s "$root/tmp/out/placement-example-2/$f" ] || fail "no out/placement-example-2/$f"
done
ls "$root"/tmp/out/placement-example-2/*.png >/dev/null || fail "no frames"
echo "a fresh bookworm root runs armstudy from its package: init, validate, run, frames"
