#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# armstudy as a Debian user gets it: the package CPack makes from this build
# (armstudy_<version>_amd64.deb), unpacked with dpkg-deb -x into a scratch root (nothing is
# installed into the system), then run from another folder, under strace, on a bundled case
# the package ships, to a complete report with --pdf:
#  - the file name, the Depends (the shared libraries by dpkg-shlibdeps and PLplot's cairo
#    driver) and Recommends (a headless Chromium, ffmpeg, the DejaVu fonts);
#  - lintian finds no error in it (its warnings are listed);
#  - the files: both programs, the templates, the schema, the docs and bundled cases, the
#    copyright and changelog (whose latest entry is the package's version), a gzipped man
#    page per command of `armstudy --help` (each formats without a groff warning and has
#    EXAMPLES) and the bash completion (it completes the commands);
#  - the run opens no path under the source tree or the build tree: it reads the package's
#    templates and starts the package's frame helper;
#  - --version of the installed program names the libraries.
#
# usage: install_test.sh SOURCE_DIR BUILD_DIR VERSION
set -euo pipefail
src=$(realpath "$1")
build=$(realpath "$2")
version=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/armstudy_install.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# --- the package ---------------------------------------------------------------------------
cpack --config "$build/CPackConfig.cmake" -B "$work/pkg" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log"; fail "cpack"; }
deb=$(echo "$work"/pkg/armstudy_"${version}"-*_amd64.deb)
[ -f "$deb" ] || { ls "$work/pkg"; fail "no $work/pkg/armstudy_${version}-<revision>_amd64.deb"; }
maintainer=$(dpkg-deb -f "$deb" Maintainer)
grep -qE '^[^<]+ <[^@ >]+@[^@ >]+>$' <<<"$maintainer" || fail "Maintainer without an address: $maintainer"
depends=$(dpkg-deb -f "$deb" Depends)
for lib in libmujoco libosmesa6 libyaml-cpp libnlopt libplplot libpng libssl plplot-driver-cairo; do
  grep -q "$lib" <<<"$depends" || fail "Depends lacks $lib: $depends"
done
[ "$(dpkg-deb -f "$deb" Recommends)" = "chromium-headless-shell | chromium, ffmpeg, fonts-dejavu-core" ] ||
  fail "Recommends: $(dpkg-deb -f "$deb" Recommends)"
echo "Depends: $depends"

# lintian: no error (as Debian's archive checks a package); its warnings are listed
lintian_status=0
lintian --tag-display-limit 0 --fail-on error --suppress-tags mail-contact \
  "$deb" >"$work/lintian.log" 2>&1 || lintian_status=$?
sed 's/^/lintian: /' "$work/lintian.log"
[ "$lintian_status" = 0 ] || fail "lintian found errors (exit $lintian_status)"

root=$work/root
dpkg-deb -x "$deb" "$root"
for f in bin/armstudy bin/armstudy-frames share/armstudy/templates/case.html \
  share/armstudy/templates/index.html share/armstudy/templates/report.css \
  share/armstudy/results.schema.json share/armstudy/junit.xsd share/doc/armstudy/README.md \
  share/doc/armstudy/docs/cli.md share/doc/armstudy/docs/install.md \
  share/doc/armstudy/examples/cases/placement-example-2.yaml \
  share/doc/armstudy/copyright share/doc/armstudy/changelog.Debian.gz \
  share/bash-completion/completions/armstudy share/man/man1/armstudy.1.gz; do
  [ -f "$root/usr/$f" ] || fail "the package has no /usr/$f"
done
bin=$root/usr/bin/armstudy
# the changelog's latest entry is this package's version
changelog_version=$(zcat "$root/usr/share/doc/armstudy/changelog.Debian.gz" | head -1 |
  sed -n 's/^armstudy (\([^)]*\)).*/\1/p')
[ "$changelog_version" = "$(dpkg-deb -f "$deb" Version)" ] ||
  fail "changelog.Debian.gz's latest entry is '$changelog_version', the package $(dpkg-deb -f "$deb" Version)"

# a man page per command and subcommand --help lists, each formatting without a warning
commands=$("$bin" --help | sed -n '/^Subcommands:/,/^$/p' | awk 'NR > 1 && NF {print $1}')
[ -n "$commands" ] || fail "no commands in --help"
pages=(armstudy)
for c in $commands; do
  pages+=("armstudy-$c")
  for s in $("$bin" "$c" --help | sed -n '/^Subcommands:/,/^$/p' | awk 'NR > 1 && NF {print $1}'); do
    pages+=("armstudy-$c-$s")
  done
done
for p in "${pages[@]}"; do
  man=$root/usr/share/man/man1/$p.1.gz
  [ -f "$man" ] || fail "no man page $p.1.gz"
  text=$(zcat "$man")
  warnings=$(groff -man -Tutf8 -ww -z <<<"$text" 2>&1)
  [ -z "$warnings" ] || fail "$p.1: $warnings"
  grep -q '^\.SH EXAMPLES$' <<<"$text" || fail "$p.1 has no EXAMPLES"
done
echo "man pages: ${pages[*]}"
run_help=$("$bin" run --help)
run_man=$(zcat "$root/usr/share/man/man1/armstudy-run.1.gz")
for o in $(grep -oE -- '--[a-z][a-z-]*' <<<"$run_help" | sort -u); do
  grep -qF -- "$(sed 's/-/\\-/g' <<<"$o")" <<<"$run_man" ||
    fail "armstudy-run.1 lacks $o"
done

# the completion: the commands after `armstudy `, run's options after `armstudy run --`
completed=$(bash -c 'source "$1"; COMP_WORDS=(armstudy ""); COMP_CWORD=1; _armstudy
  echo "${COMPREPLY[*]}"' _ "$root/usr/share/bash-completion/completions/armstudy")
[ "$(tr ' ' '\n' <<<"$completed" | sort)" = "$(sort <<<"$commands")" ] ||
  fail "completion of commands: '$completed'"
completed=$(bash -c 'source "$1"; COMP_WORDS=(armstudy run --p); COMP_CWORD=2; _armstudy
  echo "${COMPREPLY[*]}"' _ "$root/usr/share/bash-completion/completions/armstudy")
[ "$completed" = "--pdf" ] || fail "completion of 'armstudy run --p': '$completed'"

# --- the installed program, from another folder -------------------------------------------
mkdir "$work/run"
cp "$root/usr/share/doc/armstudy/examples/cases/placement-example-2.yaml" "$work/run/"
cd "$work/run"
"$bin" --version >"$work/version.txt"
grep -q "^armstudy $version (commit " "$work/version.txt" || fail "--version: $(cat "$work/version.txt")"
grep -q "^MuJoCo " "$work/version.txt" && grep -q "^OSMesa/Mesa .*Mesa" "$work/version.txt" ||
  fail "--version: $(cat "$work/version.txt")"
status=0
strace -f -qq -e trace=file,process -o "$work/trace" "$bin" run placement-example-2.yaml \
  --out out --pdf >"$work/run.log" 2>&1 || status=$?
[ "$status" = 0 ] || { cat "$work/run.log"; fail "run exit $status"; }
case_dir=out/placement-example-2
for f in results.json index.html report.pdf report.css model.xml; do
  [ -s "$case_dir/$f" ] || fail "no $case_dir/$f"
done
ls "$case_dir"/*.png >/dev/null 2>&1 || fail "no frames"
python3 - "$case_dir/results.json" <<'PY' || fail "results.json"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["status"] == "solved", r["status"]
assert r["frames"], "no frames"
PY
head -c 5 "$case_dir/report.pdf" | grep -q '%PDF-' || fail "report.pdf is no PDF"
# nothing under the source or build tree was opened, stat'ed, read or run
if grep -F -e "\"$src/" -e "\"$src\"" -e "\"$build/" -e "\"$build\"" "$work/trace" >"$work/hits"; then
  head -20 "$work/hits"
  fail "the installed armstudy touched the source or build tree"
fi
grep -q "\"$root/usr/share/armstudy/templates/case.html\"" "$work/trace" ||
  fail "the package's templates were not read"
grep -q "execve(\"$root/usr/bin/armstudy-frames\"" "$work/trace" ||
  fail "the package's frame helper was not started"
echo "installed armstudy: $(head -1 "$work/version.txt"); a complete report with --pdf" \
  "($(grep -c . "$work/trace") traced calls, none under $src or $build)"
