#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# model.xml opened in MuJoCo's own viewer, `mujoco-simulate model.xml` (Debian's
# libmujoco-samples), on a virtual X display (Xvfb), for both arms: a placement case
# (placement-example-2, the horizontal 2-link arm) and a throwing case (throwing, the arm
# with the passive tray and the ball), each run with --no-render. For each model the viewer
# is started twice, on model.xml and on a copy whose link geoms are transparent (rgba alpha
# 0); each time the test waits (polling, with a deadline) until the window shows the
# model's light wall, grabs the window (ffmpeg x11grab) and reads its pixels (ffmpeg to raw
# RGB, counted in Python). It checks that the screenshot is not blank (many colours, the
# wall, the viewer's panels) and that it shows the arm: many pixels differ from the
# transparent-link copy's screenshot, and many of those have the hue of a link's rgba in
# model.xml. The screenshots stay in ARTIFACTS (model.png, no_links.png, diff.png per case).
# Skipped (exit 77, saying why) only when Xvfb or mujoco-simulate cannot start at all.
#
# usage: simulate_viewer_test.sh SOURCE_DIR ARMSTUDY ARTIFACTS
set -euo pipefail
src=$1
bin=$2
artifacts=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/armstudy_viewer.XXXXXX")
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${pids[@]}"; do wait "$p" 2>/dev/null || true; done
  rm -rf "$work"
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
skip() {
  echo "SKIPPED: $*"
  exit 77
}
command -v Xvfb >/dev/null || skip "Xvfb is not installed (package xvfb, scripts/packages.txt)"
command -v mujoco-simulate >/dev/null ||
  skip "mujoco-simulate is not installed (package libmujoco-samples, scripts/packages.txt)"
for tool in ffmpeg xwininfo xdpyinfo python3; do
  command -v $tool >/dev/null || fail "$tool is missing (scripts/packages.txt)"
done
export LP_NUM_THREADS=1
mkdir -p "$artifacts"
rm -f "$artifacts"/*.png

# model.xml does not depend on the answer: the throw is solved on its first control grid only
# and neither case runs its sensitivity part (the run was most of this test's time)
mkdir -p "$work/cases"
sed 's/^    refinements: [0-9]* /    refinements: 0 /' "$src/reports/cases/throwing.yaml" >"$work/cases/throwing.yaml"
grep -q '^    refinements: 0 ' "$work/cases/throwing.yaml" || fail "throwing.yaml has no grid.refinements line"
"$bin" run --no-render --no-sensitivity --jobs 2 --out "$work/out" \
  "$src/reports/cases/placement-example-2.yaml" "$work/cases/throwing.yaml" >"$work/run.log" 2>&1 ||
  { tail -30 "$work/run.log"; fail "the run of the two cases"; }

# --- a virtual display on a free display number (Xvfb picks it: -displayfd) -------------------
exec 3>"$work/display"
Xvfb -displayfd 3 -screen 0 1920x1200x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
pids+=($!)
exec 3>&-
deadline=$((SECONDS + 20))
until [ -s "$work/display" ]; do
  kill -0 "${pids[0]}" 2>/dev/null || skip "Xvfb does not start: $(tail -5 "$work/xvfb.log")"
  [ $SECONDS -lt $deadline ] || skip "Xvfb gave no display within 20 s: $(tail -5 "$work/xvfb.log")"
  sleep 0.1
done
export DISPLAY=:$(head -1 "$work/display")
until xdpyinfo >/dev/null 2>&1; do
  [ $SECONDS -lt $deadline ] || skip "Xvfb's display $DISPLAY does not answer: $(tail -5 "$work/xvfb.log")"
  sleep 0.1
done
echo "Xvfb on $DISPLAY"

# stats.py PNG: the grabbed window's pixel statistics as JSON (no numpy, no PIL)
cat >"$work/stats.py" <<'PY'
import json, subprocess, sys
raw = subprocess.run(["ffmpeg", "-loglevel", "error", "-i", sys.argv[1], "-f", "rawvideo",
                      "-pix_fmt", "rgb24", "-"], check=True, capture_output=True).stdout
px = [raw[i:i + 3] for i in range(0, len(raw), 3)]
print(json.dumps({"pixels": len(px), "colours": len(set(px)),
                  "light": sum(1 for p in px if min(p) >= 200),
                  "dark": sum(1 for p in px if max(p) <= 16)}))
PY

# view MODEL NAME: starts mujoco-simulate on MODEL, waits until its window shows the model's
# light wall, grabs the window into $work/NAME.png, stops the viewer
view() {
  local model=$1 name=$2 sim geometry=""
  mujoco-simulate "$model" >"$work/$name.log" 2>&1 &
  sim=$!
  pids+=($sim)
  local deadline=$((SECONDS + 60))
  while :; do
    if ! kill -0 $sim 2>/dev/null; then
      # no window at all: the viewer cannot run here (no GLX, no OpenGL); a window that then
      # closes is a failure of the model
      [ -n "$geometry" ] || skip "mujoco-simulate does not start on $DISPLAY: $(tail -5 "$work/$name.log")"
      fail "$name: mujoco-simulate exited: $(tail -5 "$work/$name.log")"
    fi
    [ $SECONDS -lt $deadline ] || fail "$name: the viewer's window shows no model within 60 s"
    # the window: '0x... "Simulate : <model>": ("Simulate" "Simulate")  WxH+X+Y  +X+Y'
    geometry=$(xwininfo -root -tree 2>/dev/null |
      sed -n 's/^ *0x[0-9a-f]* "Simulate[^"]*":.*  \([0-9]*x[0-9]*\)+\([0-9]*\)+\([0-9]*\) .*/\1 \2,\3/p' |
      head -1) || geometry=""
    if [ -n "$geometry" ]; then
      ffmpeg -loglevel error -y -f x11grab -video_size "${geometry% *}" -i "$DISPLAY+${geometry#* }" \
        -frames:v 1 "$work/$name.png" 2>>"$work/$name.ffmpeg.log" || true
      if [ -s "$work/$name.png" ]; then
        # drawn: a tenth of the window is the light wall (the viewer's own background is dark)
        python3 - "$work/$name.png" "$work/stats.py" <<'PY' && break
import json, subprocess, sys
s = json.loads(subprocess.run([sys.executable, sys.argv[2], sys.argv[1]], check=True,
                              capture_output=True, text=True).stdout)
sys.exit(0 if s["light"] >= s["pixels"] // 10 else 1)
PY
      fi
    fi
    sleep 0.2
  done
  kill $sim 2>/dev/null || true
  wait $sim 2>/dev/null || true
}

for case in placement-example-2 throwing; do
  model=$work/out/$case/model.xml
  [ -f "$model" ] || fail "$case: no model.xml"
  # the copy without the arm: every link geom transparent
  sed -E 's/(name="link[0-9]+_geom"[^>]* rgba="[^"]* )[0-9.]+"/\10"/' "$model" >"$work/$case.no_links.xml"
  [ "$(grep -c 'name="link[0-9]*_geom"[^>]* rgba="[^"]* 0"' "$work/$case.no_links.xml")" -ge 2 ] ||
    fail "$case: the link geoms' rgba not found in model.xml"
  start=$SECONDS
  view "$model" "$case.model"
  view "$work/$case.no_links.xml" "$case.no_links"
  cp "$work/$case.model.png" "$artifacts/$case.model.png"
  cp "$work/$case.no_links.png" "$artifacts/$case.no_links.png"
  python3 - "$model" "$work/$case.model.png" "$work/$case.no_links.png" "$artifacts/$case.diff.png" \
    "$case" "$((SECONDS - start))" <<'PY' || fail "$case: the viewer does not show the arm"
import colorsys, re, subprocess, sys

model, shot, bare, diff_out, case, secs = sys.argv[1:]

def rgb(png):
    out = subprocess.run(["ffprobe", "-v", "error", "-select_streams", "v:0", "-show_entries",
                          "stream=width,height", "-of", "csv=p=0", png],
                         check=True, capture_output=True, text=True).stdout
    w, h = map(int, out.strip().split(","))
    raw = subprocess.run(["ffmpeg", "-loglevel", "error", "-i", png, "-f", "rawvideo",
                          "-pix_fmt", "rgb24", "-"], check=True, capture_output=True).stdout
    return w, h, [tuple(raw[i:i + 3]) for i in range(0, len(raw), 3)]

w, h, a = rgb(shot)
w2, h2, b = rgb(bare)
if (w, h) != (w2, h2):
    sys.exit(f"{case}: the two windows differ in size ({w}x{h}, {w2}x{h2})")
# the links' colours in model.xml, as hue, saturation, value: the visible, coloured ones
# (the blue link 1 and the green link 2 of both arms; the tray is grey, the ball's radius
# transparent)
links = {}
for m in re.finditer(r'name="(link\d+)_geom"[^>]*rgba="([^"]+)"', open(model).read()):
    r, g, bl, alpha = map(float, m.group(2).split())
    hsv = colorsys.rgb_to_hsv(r, g, bl)
    if alpha > 0 and hsv[1] >= 0.5:
        links[m.group(1)] = hsv
if len(links) < 2:
    sys.exit(f"{case}: fewer than two coloured links in model.xml")
hue_of = lambda p: colorsys.rgb_to_hsv(*(c / 255 for c in p))

def link_of(p):
    """the link whose rgba has this pixel's hue (within 0.04 of the circle) and a like
    saturation: shading changes a lit colour's value, not its hue"""
    hh, ss, vv = hue_of(p)
    if ss < 0.35 or vv < 0.15:
        return None
    for name, (lh, ls, lv) in links.items():
        dh = abs(hh - lh)
        if min(dh, 1 - dh) < 0.04 and abs(ss - ls) < 0.3:
            return name
    return None

colours = len(set(a))
light = sum(1 for p in a if min(p) >= 200)
changed = [i for i in range(len(a)) if sum(abs(x - y) for x, y in zip(a[i], b[i])) > 60]
per_link = {n: 0 for n in links}
for i in changed:
    n = link_of(a[i])
    if n:
        per_link[n] += 1
in_bare = sum(1 for p in b if link_of(p))
# the difference image: changed pixels white on black
mark = bytearray(len(a) * 3)
for i in changed:
    mark[3 * i:3 * i + 3] = b"\xff\xff\xff"
subprocess.run(["ffmpeg", "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24",
                "-video_size", f"{w}x{h}", "-i", "-", diff_out], input=bytes(mark), check=True)
print(f"{case}: window {w}x{h}, {colours} colours, {light} light pixels; {len(changed)} pixels "
      f"differ from the transparent-link copy, of them in the links' hues "
      + ", ".join(f"{n} {c}" for n, c in per_link.items())
      + f"; link-hued pixels without the links: {in_bare} ({secs} s)")
bad = []
if colours < 50 or light < w * h // 10:
    bad.append("blank: too few colours or no light wall")
# the arm in view covers thousands of pixels in a window of ~450 000 (measured: docs)
if len(changed) < 2000:
    bad.append(f"only {len(changed)} pixels change without the links")
if sum(per_link.values()) < 1000 or max(per_link.values()) < 500:
    bad.append("too few of the changed pixels have a link's colour")
if in_bare > sum(per_link.values()) // 10:
    bad.append("the transparent-link copy still shows link colours")
if bad:
    sys.exit("; ".join(bad))
PY
done
echo "mujoco-simulate shows both arms (screenshots in $artifacts)"
