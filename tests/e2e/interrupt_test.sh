#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# The browser armstudy starts for --pdf is tied to it. A stand-in for Chromium (it starts a
# helper process in its group and hangs; for the last run it answers the DevTools protocol
# and prints) makes the timing deterministic:
#  - SIGINT during the print: exit 130, the browser and its helper are gone, its profile
#    is removed, no report.pdf, no .part file, no scratch folder; the report is complete.
#  - SIGKILL of armstudy during the print: the browser dies with it (PR_SET_PDEATHSIG),
#    and the next run removes the profile and scratch folder the kill left and prints.
#
# usage: interrupt_test.sh SOURCE_DIR ARMSTUDY
set -euo pipefail
src=$1
bin=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/armstudy_interrupt.XXXXXX")
state=$work/state
mkdir -p "$state" "$work/tmp"
cleanup() {
  for f in "$state"/*.pid; do [ -f "$f" ] && kill -9 "$(cat "$f")" 2>/dev/null || true; done
  rm -rf "$work"
}
trap cleanup EXIT
export LP_NUM_THREADS=1 FAKE_STATE=$state TMPDIR=$work/tmp
cat > "$work/fake-devtools.py" <<'EOF'
# answers the DevTools messages armstudy sends on fd 3 (each ended by NUL) on fd 4, as
# headless Chromium does, and prints every page as a minimal PDF
import base64, json, os
buf = b""
while True:
    data = os.read(3, 65536)
    if not data:
        break
    buf += data
    while b"\0" in buf:
        raw, buf = buf.split(b"\0", 1)
        m = json.loads(raw)
        result, events = {}, []
        method = m.get("method")
        if method == "Browser.close":
            raise SystemExit(0)
        if method == "Target.createTarget":
            result = {"targetId": "t1"}
        elif method == "Target.attachToTarget":
            result = {"sessionId": "s1"}
        elif method == "Page.navigate":
            result = {"frameId": "f1"}
            events = [{"method": "Page.loadEventFired", "params": {}, "sessionId": "s1"}]
        elif method == "Page.printToPDF":
            result = {"data": base64.b64encode(b"%PDF-1.4\n%%EOF\n").decode()}
        answer = {"id": m["id"], "result": result}
        if "sessionId" in m:
            answer["sessionId"] = m["sessionId"]
        for x in [answer] + events:
            os.write(4, json.dumps(x).encode() + b"\0")
EOF
cat > "$work/fake-chromium" <<'EOF'
#!/bin/sh
# stands in for headless Chromium: FAKE_MODE=hang waits forever (with a helper in its
# process group); FAKE_MODE=print speaks the DevTools protocol and prints every page
if [ "${FAKE_MODE:-hang}" = print ]; then
  exec python3 "$(dirname "$0")/fake-devtools.py"
fi
sleep 600 &
echo $! > "$FAKE_STATE/helper.pid"
echo $$ > "$FAKE_STATE/browser.pid.tmp" && mv "$FAKE_STATE/browser.pid.tmp" "$FAKE_STATE/browser.pid"
wait
EOF
chmod +x "$work/fake-chromium"
export ARMSTUDY_CHROMIUM=$work/fake-chromium
sed 's/^name: .*/name: pdf-case/' "$src/reports/cases/placement-example-2.yaml" > "$work/case.yaml"
out=$work/out
fail=0
bad() { echo "FAIL: $*"; fail=1; }

alive() {  # pid: running (a zombie nobody reaped counts as gone)
  [ -r "/proc/$1/stat" ] || return 1
  local s
  s=$(sed 's/.*) //' "/proc/$1/stat" | cut -d' ' -f1)
  [ "$s" != Z ]
}
wait_for_browser() {
  for _ in $(seq 1 1200); do
    [ -f "$state/browser.pid" ] && return 0
    kill -0 "$1" 2>/dev/null || return 1
    sleep 0.05
  done
  return 1
}
gone_within() {  # seconds pid...
  local t=$1; shift
  for _ in $(seq 1 $((t * 20))); do
    local any=0
    for p in "$@"; do alive "$p" && any=1; done
    [ $any = 0 ] && return 0
    sleep 0.05
  done
  return 1
}
leftovers() {  # what a stopped run must not leave
  find "$out" -name '*.part*' -o -name '.armstudy-*' | sed 's/^/  /'
  find "$work/tmp" -mindepth 1 -maxdepth 1 | sed 's/^/  /'  # anything in the browser's temporary folder
}

# --- SIGINT while the browser prints ---------------------------------------------------
"$bin" run --pdf --no-render --out "$out" "$work/case.yaml" > "$work/int.log" 2>&1 &
pid=$!
wait_for_browser $pid || { cat "$work/int.log"; bad "the stand-in browser never started"; exit 1; }
browser=$(cat "$state/browser.pid")
helper=$(cat "$state/helper.pid")
kill -INT $pid
code=0
wait $pid || code=$?
[ $code = 130 ] || bad "SIGINT: exit $code, expected 130"
grep -q "stopped by SIGINT" "$work/int.log" || bad "SIGINT: no message: $(cat "$work/int.log")"
gone_within 5 "$browser" "$helper" || bad "SIGINT: the browser ($browser) or its helper ($helper) outlived armstudy"
[ -z "$(leftovers)" ] || bad "SIGINT left: $(leftovers)"
[ ! -e "$out/pdf-case/report.pdf" ] || bad "SIGINT: a report.pdf was written"
python3 "$src/tests/e2e/crash_check.py" "$out" pdf-case "$(sha256sum "$work/case.yaml" | cut -d' ' -f1)" - --no-hidden ||
  bad "SIGINT: the case report is not complete"
rm -f "$state"/*.pid

# --- SIGKILL while the browser prints, then the next run ---------------------------------
"$bin" run --pdf --no-render --force --out "$out" "$work/case.yaml" > "$work/kill.log" 2>&1 &
pid=$!
wait_for_browser $pid || { cat "$work/kill.log"; bad "the stand-in browser never started"; exit 1; }
browser=$(cat "$state/browser.pid")
helper=$(cat "$state/helper.pid")
kill -KILL $pid
wait $pid 2>/dev/null || true
gone_within 5 "$browser" || bad "SIGKILL: the browser ($browser) outlived armstudy"
kill -9 "$helper" 2>/dev/null || true  # (Chromium's own helpers exit with the browser)
[ -n "$(find "$work/tmp" -maxdepth 1 -name 'armstudy-chromium-*')" ] || bad "SIGKILL: expected the killed run's profile"
find "$out/pdf-case" -name '*.part*' | grep -q . && bad "SIGKILL: a .part file in the case folder"
FAKE_MODE=print "$bin" run --pdf --no-render --out "$out" "$work/case.yaml" > "$work/next.log" 2>&1 ||
  bad "the next run failed: $(cat "$work/next.log")"
[ -z "$(leftovers)" ] || bad "the next run left: $(leftovers)"
head -c 4 "$out/pdf-case/report.pdf" | grep -q '%PDF' || bad "the next run printed no report.pdf"
[ $fail = 0 ] && echo "interrupt: SIGINT and SIGKILL during a print leave nothing behind"
exit $fail
