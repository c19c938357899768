#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
#
# The lean install of the Debian package on a fresh Debian bookworm root, as a new user
# would do it (docs/install.md): debootstrap a minimal root (with bookworm's updates and
# security archives, as an installed system has), install the package with
# `apt-get install --no-install-recommends`, say how many packages and megabytes that added,
# then, inside the root, start a case with `armstudy init`, validate and run it, run a bundled
# case to a complete report, check that `run --pdf` without Chromium writes nothing and names
# the package, then add chromium-headless-shell (--no-install-recommends; its packages and
# megabytes said) and print that bundled case's report.pdf. Not part of the test suite (it
# needs root, debootstrap, a Debian mirror and several minutes); run it before a release and
# note the result in docs/install.md:
#
#   sudo tests/e2e/fresh_root_install.sh /tmp/pkg/armstudy_0.1.0-1_amd64.deb [MIRROR [SECURITY]]
set -euo pipefail
deb=$(realpath "$1")
mirror=${2:-http://deb.debian.org/debian}
security=${3:-http://deb.debian.org/debian-security}
command -v debootstrap >/dev/null || { echo "needs debootstrap (apt-get install debootstrap)"; exit 2; }
root=$(mktemp -d /var/tmp/armstudy_fresh_root.XXXXXX)
cleanup() {
  umount -l "$root/proc" 2>/dev/null || true
  umount -l "$root/dev/shm" 2>/dev/null || true
  rm -rf --one-file-system "$root"
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
# Chromium keeps its shared memory in /dev/shm, a tmpfs on every installed system
mkdir -p "$root/dev/shm"
mount -t tmpfs -o mode=1777 shm "$root/dev/shm"
printf 'deb %s bookworm main\ndeb %s bookworm-updates main\ndeb %s bookworm-security main\n' \
  "$mirror" "$mirror" "$security" >"$root/etc/apt/sources.list"
in_root() { chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
  DEBIAN_FRONTEND=noninteractive "$@"; }
size_kb() { in_root dpkg-query -W -f '${Installed-Size}\n' | awk '{s += $1} END {print s}'; }
count() { in_root dpkg-query -W -f '${Package}\n' | wc -l; }

cp "$deb" "$root/tmp/"
in_root apt-get update -qq
packages_before=$(count)
kb_before=$(size_kb)
in_root apt-get install -y -qq --no-install-recommends "/tmp/$(basename "$deb")" >/dev/null
packages_lean=$(count)
kb_lean=$(size_kb)
echo "the lean install added $((packages_lean - packages_before)) packages," \
  "$((((kb_lean - kb_before) + 512) / 1024)) MB installed"
if in_root dpkg -s chromium-headless-shell >/dev/null 2>&1 ||
  in_root dpkg -s chromium >/dev/null 2>&1; then
  fail "the lean install brought Chromium (a Recommends, not a Depends)"
fi

in_root armstudy --version
in_root sh -c 'cd /tmp && armstudy init pendulum -o p.yaml && armstudy validate p.yaml &&
  armstudy run p.yaml --out out --no-sensitivity' || fail "the init case did not run"
bundled=/usr/share/doc/armstudy/examples/cases/placement-example-2.yaml
in_root sh -c "cd /tmp && armstudy run $bundled --out out" || fail "the bundled case did not run"
for f in results.json index.html model.xml; do
  [ -s "$root/tmp/out/placement-example-2/$f" ] || fail "no out/placement-example-2/$f"
done
ls "$root"/tmp/out/placement-example-2/*.png >/dev/null || fail "no frames"
echo "a fresh bookworm root runs armstudy from its package: init, validate, run, frames"

# --pdf without Chromium: nothing written, exit 3, the package named
status=0
in_root sh -c "cd /tmp && armstudy run $bundled --out out-nopdf --pdf" >"$root.nopdf.log" 2>&1 ||
  status=$?
if [ "$status" != 3 ] || ! grep -q "apt-get install chromium-headless-shell" "$root.nopdf.log" ||
  [ -e "$root/tmp/out-nopdf" ]; then
  cat "$root.nopdf.log"
  fail "run --pdf without Chromium: exit $status"
fi
rm -f "$root.nopdf.log"
echo "run --pdf without Chromium: exit 3, nothing written, chromium-headless-shell named"

# the PDF: Chromium's headless shell, lean too
in_root apt-get install -y -qq --no-install-recommends chromium-headless-shell >/dev/null
echo "chromium-headless-shell (--no-install-recommends) added $(($(count) - packages_lean))" \
  "packages, $(((($(size_kb) - kb_lean) + 512) / 1024)) MB installed"
in_root sh -c "cd /tmp && armstudy run $bundled --out out --pdf" || fail "the bundled case's --pdf"
pdf=$root/tmp/out/placement-example-2/report.pdf
[ "$(head -c 5 "$pdf" 2>/dev/null)" = "%PDF-" ] || fail "no report.pdf"
pages=$(pdfinfo "$pdf" 2>/dev/null | awk '/^Pages:/ {print $2}') # (this machine's poppler-utils)
echo "report.pdf printed: ${pages:-?} page(s), $(($(stat -c %s "$pdf") / 1024)) KiB"
echo "in all: $(($(count) - packages_before)) packages," \
  "$(((($(size_kb) - kb_before) + 512) / 1024)) MB installed"
