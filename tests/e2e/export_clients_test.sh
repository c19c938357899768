#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
# armstudy's exports opened by the programs users open them with, on every bundled case
# (reports/cases/, run with --no-render: the exports are the same):
#  - junit.xml, of the run and of a merge that adds a case failing its `expect` and an
#    unreadable results.json (the two ways a case fails in junit.xml), beside the bundled
#    expected-unsolvable placement-example-1, is valid against junit.xsd (xmllint), and a
#    junit.xml with a misnamed element is not;
#  - every motion CSV reads with Python's csv module: the header is results.json's
#    `columns`, each column `name [unit]` with the unit its quantity has (docs/cli.md),
#    as many rows as `rows`, every field a finite number, time from 0 increasing;
#  - every model.xml passes MuJoCo's own tools (Debian's libmujoco-samples): testxml (load,
#    save, reload, compare: the saved copy reloads and differs by less than 1e-4, or only
#    in the flag geom_sameframe, see below) and
#    compile to .mjb, whose print is the XML's; and
#    keyframe_poses (plain libmujoco) finds at each keyframe's time the joint angles of one
#    of the case's motion CSVs.
# results.json against results.schema.json for every bundled case is
# BrowserReport.BundledResultsValidateAndCiFilesCountEveryCheck.
#
# usage: export_clients_test.sh SOURCE_DIR ARMSTUDY KEYFRAME_POSES
set -euo pipefail
src=$1
bin=$2
poses=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/armstudy_exports.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
for tool in xmllint mujoco-testxml mujoco-compile; do
  command -v $tool >/dev/null || fail "$tool is missing (scripts/packages.txt)"
done
export LP_NUM_THREADS=1

# --- every bundled case ---------------------------------------------------------------------
# the exports do not depend on the answer's grid: the two throws are solved on their first
# control grid only (their runs on three grids were most of this test's CPU)
mkdir -p "$work/throws"
bundled=()
for case in "$src"/reports/cases/*.yaml; do
  case $(basename "$case") in
    throwing*.yaml)
      copy=$work/throws/$(basename "$case")
      if grep -q '^  grid:' "$case"; then
        sed 's/^    refinements: [0-9]* /    refinements: 0 /' "$case" >"$copy"
      else
        sed 's/^throwing:$/throwing:\n  grid: {refinements: 0}/' "$case" >"$copy"
      fi
      grep -q '^    refinements: 0 \|^  grid: {refinements: 0}$' "$copy" ||
        fail "$(basename "$case"): its throwing.grid.refinements could not be set to 0"
      bundled+=("$copy") ;;
    *) bundled+=("$case") ;;
  esac
done
"$bin" run --no-render --no-sensitivity --jobs 2 --out "$work/out" "${bundled[@]}" >"$work/run.log" 2>&1 ||
  { tail -30 "$work/run.log"; fail "the bundled run"; }

# --- junit.xml ------------------------------------------------------------------------------
xsd=$src/junit.xsd
xmllint --noout --schema "$xsd" "$work/out/junit.xml" 2>"$work/xmllint.log" ||
  { cat "$work/xmllint.log"; fail "the bundled run's junit.xml"; }
# a case that fails its expect (placement-example-1 expected solved), an unreadable result
mkdir -p "$work/cases" "$work/more/unreadable"
sed -e 's/^name: placement-example-1/name: placement-expect-solved/' -e '/^expect:/d' \
  "$src/reports/cases/placement-example-1.yaml" >"$work/cases/placement-expect-solved.yaml"
status=0
"$bin" run --no-render --out "$work/more" "$work/cases/placement-expect-solved.yaml" \
  >"$work/more.log" 2>&1 || status=$?
[ "$status" = 1 ] || { cat "$work/more.log"; fail "the failing case exited $status, not 1"; }
printf '{"schema_version": 2, "study": "placement"' >"$work/more/unreadable/results.json"
status=0
"$bin" merge "$work/out" "$work/more" --out "$work/merged" >"$work/merge.log" 2>&1 || status=$?
[ "$status" = 1 ] || { cat "$work/merge.log"; fail "merge exited $status, not 1"; }
junit=$work/merged/junit.xml
xmllint --noout --schema "$xsd" "$junit" 2>"$work/xmllint.log" ||
  { cat "$work/xmllint.log"; fail "the merged junit.xml"; }
grep -q 'classname="placement.placement-expect-solved" name="solve" time="[0-9.]*"><failure ' "$junit" ||
  fail "no failure for the failing case"
grep -q 'classname="[a-z_]*\.unreadable" name="solve" time="[0-9.]*"><failure ' "$junit" ||
  fail "no failure for the unreadable case"
grep -q 'classname="placement.placement-example-1" name="solve" time="[0-9.]*"/>' "$junit" ||
  fail "the expected-unsolvable case is not a pass"
sed 's/<testcase /<testcaze /' "$junit" >"$work/bad.xml"
if xmllint --noout --schema "$xsd" "$work/bad.xml" 2>/dev/null; then
  fail "junit.xsd accepts a misnamed element"
fi
echo "junit.xml valid against junit.xsd: the run's and the merge's" \
  "($(grep -c '<testcase ' "$junit") testcases, $(grep -c '<failure ' "$junit") failures)"

# --- the motion CSVs, the models --------------------------------------------------------------
checked=0
worst=0
for dir in "$work"/out/*/; do
  [ -f "$dir/results.json" ] || continue
  name=$(basename "$dir")
  [ -f "$dir/model.xml" ] || continue
  # testxml loads model.xml, saves it with MuJoCo's XML writer, reloads the saved copy and
  # compares the two compiled models: the copy must load (a massless body's stand-in mass
  # and inertia, scene/mjcf_writer.hpp, are above the 1e-12 below which the writer writes 0)
  # and match. The writer prints 6 significant digits, so a number of the model below 100
  # (keyframe angles and rates, times, lengths, masses) comes back within 5e-5; the bundled
  # models differ by 4e-6 at most (key_qvel, body_invweight0), the bound is 1e-4
  log=$(cd "$work" && mujoco-testxml "$dir/model.xml" 2>&1)
  grep -q "Comparison of original and saved model" <<<"$log" || fail "$name: testxml: $log"
  diff=$(sed -n 's/^ *Max difference *: *//p' <<<"$log")
  field=$(sed -n 's/^ *Field name *: *//p' <<<"$log")
  if [[ "$field" =~ ^(geom|site)_sameframe$ ]]; then
    # a flag, not a number: whether a geom's (site's) frame is exactly its body's inertial
    # frame. A point mass at the tip puts the inertial at 0.39999999999999997 beside a
    # payload geom at 0.4; written with 6 digits both are 0.4 and the flag turns on. The rest
    # of such a model: the compiled prints of model.xml and of the copy MuJoCo saves
    # (compile to .xml, the same writer) differ in nothing else but numbers within the same
    # 1e-4 (a keyframe's qvel of 5e-16 is written as 0 and its all-zero row left out)
    mujoco-compile "$dir/model.xml" "$work/$name.saved.xml" >/dev/null &&
      mujoco-compile "$dir/model.xml" "$work/$name.orig.txt" >/dev/null &&
      mujoco-compile "$work/$name.saved.xml" "$work/$name.saved.txt" >/dev/null ||
      fail "$name: compile of the saved copy"
    other=$(python3 - "$work/$name.orig.txt" "$work/$name.saved.txt" <<'PY'
import sys
def num(t):
    try:
        return float(t)
    except ValueError:
        return None
def kept(l):
    # a row whose numbers are all within 1e-4 of 0 may be left out of the saved copy
    # (MuJoCo's writer writes 5e-16 as 0 and omits an all-zero keyframe qvel)
    nums = [num(t) for t in l.split()[1:]]
    return "_sameframe" not in l and not (nums and all(x is not None and abs(x) <= 1e-4 for x in nums))
a = [l for l in open(sys.argv[1]) if kept(l)]
b = [l for l in open(sys.argv[2]) if kept(l)]
def same(x, y):
    if x == y:
        return True
    try:
        return abs(float(x) - float(y)) <= 1e-4
    except ValueError:
        return False
bad = [f"{p.strip()} | {q.strip()}" for p, q in zip(a, b)
       if len(p.split()) != len(q.split()) or not all(map(same, p.split(), q.split()))]
if len(a) != len(b):
    bad.append(f"{len(a)} against {len(b)} lines")
print("\n".join(bad[:5]))
PY
)
    [ -z "$other" ] || fail "$name: the saved copy differs beyond $field: $other"
    echo "$name: testxml: MuJoCo's saved copy reloads, differs in $field (a flag, see above)" \
      "and prints the same otherwise"
  else
    python3 -c "import sys; sys.exit(0 if float('$diff') < 1e-4 else 1)" ||
      fail "$name: testxml: the saved model differs by $diff: $log"
    echo "$name: testxml: MuJoCo's saved copy reloads, max difference $diff"
    worst=$(python3 -c "print(max(float('$worst'), float('$diff')))")
  fi
  for target in model.mjb from_xml.txt; do
    log=$(mujoco-compile "$dir/model.xml" "$work/$name.$target" 2>&1)
    [ -s "$work/$name.$target" ] && grep -q "^Done" <<<"$log" || fail "$name: compile $target: $log"
  done
  log=$(mujoco-compile "$work/$name.model.mjb" "$work/$name.from_mjb.txt" 2>&1)
  [ -s "$work/$name.from_mjb.txt" ] || fail "$name: compile model.mjb: $log"
  cmp -s "$work/$name.from_xml.txt" "$work/$name.from_mjb.txt" ||
    fail "$name: the compiled model.mjb prints otherwise than model.xml"
  "$poses" "$dir/model.xml" >"$work/$name.keys.json" || fail "$name: keyframe_poses"
  checked=$((checked + 1))
done
[ "$checked" -ge 10 ] || fail "only $checked models"

python3 - "$work/out" "$work" <<'PY'
import csv, json, math, os, re, sys

out, work = sys.argv[1], sys.argv[2]
# the unit of each quantity a motion CSV may hold (docs/cli.md: time, q, q', q'',
# torques, motor voltages and currents, powers, energy, tip and ball positions, forces; the
# path parameter s is a length along a tip path, an angle along a joint-space path)
UNITS = [(r"t", "s"), (r"s", ("m", "rad")), (r"sd", ("m/s", "rad/s")),
         (r"sdd", ("m/s^2", "rad/s^2")),
         (r"q\d+", "rad"), (r"qd\d+", "rad/s"), (r"qdd\d+", "rad/s^2"),
         (r"(tau|motor_torque)\d+", "N m"), (r"voltage\d+", "V"), (r"current\d+", "A"),
         (r"power\d+", "W"), (r"((kinetic|potential|total)_)?energy", "J"), (r"(tip|ball)_[xy]", "m"),
         (r"(normal|tangential)_force", "N")]
bad, csvs, keys = [], 0, 0
for name in sorted(os.listdir(out)):
    path = os.path.join(out, name, "results.json")
    if not os.path.isfile(path):
        continue
    r = json.load(open(path))
    motions = {}
    for e in r.get("exports", []):
        if e["kind"] != "motion_csv":
            continue
        csvs += 1
        where = f"{name}/{e['file']}"
        with open(os.path.join(out, name, e["file"]), newline="") as f:
            rows = list(csv.reader(f))
        header, body = rows[0], rows[1:]
        if header != e["columns"]:
            bad.append(f"{where}: header {header} is not results.json's {e['columns']}")
        for col in header:
            m = re.fullmatch(r"([a-z_0-9]+) \[([^\]]+)\]", col)
            unit = next((u for p, u in UNITS if m and re.fullmatch(p, m.group(1))), None)
            if not m or m.group(2) not in ((unit,) if isinstance(unit, str) else unit or ()):
                bad.append(f"{where}: column '{col}' (expected 'name [unit]', unit {unit})")
        if len(body) != e["rows"]:
            bad.append(f"{where}: {len(body)} rows, results.json says {e['rows']}")
        try:
            table = [[float(x) for x in row] for row in body]
        except ValueError as err:
            bad.append(f"{where}: {err}")
            continue
        if any(len(row) != len(header) or not all(map(math.isfinite, row)) for row in table):
            bad.append(f"{where}: a row of the wrong length or not finite")
        t = [row[0] for row in table]
        # a throw's stage boundary is a row of each stage (its "what" says so): time from 0,
        # never back, no time thrice
        if (header[0] != "t [s]" or t[0] != 0 or any(b < a for a, b in zip(t, t[1:]))
                or any(a == c for a, c in zip(t, t[2:]))):
            bad.append(f"{where}: time does not start at 0 and increase")
        motions[e["file"]] = (header, table)
    # the model's keyframes are the poses of one of the motions at the keys' times
    kp = os.path.join(work, name + ".keys.json")
    if not os.path.isfile(kp):
        continue
    poses = json.load(open(kp))
    if poses["nkey"] < 2 or not all(k["finite"] for k in poses["keys"]):
        bad.append(f"{name}/model.xml: {poses['nkey']} keyframes, or one not finite")
    model = next(e for e in r["exports"] if e["kind"] == "mjcf")
    if [k["time"] for k in poses["keys"]] != model["keyframe_times_s"]:
        bad.append(f"{name}/model.xml: key times are not results.json's keyframe_times_s")

    # the angle of column q<n> at time tk: the row's own value when a row is at tk (to
    # 1e-9 rad), else cubic Hermite between the rows around it from q and qd (its error is
    # of the order of dt^4 times the angle's fourth derivative: within 1e-6 rad here)
    def angle_at(header, table, n, tk):
        qc, qdc = header.index(f"q{n} [rad]"), header.index(f"qd{n} [rad/s]")
        t = [row[0] for row in table]
        i = min(range(len(t)), key=lambda i: abs(t[i] - tk))
        if abs(t[i] - tk) <= 1e-12 * max(1.0, abs(tk)):
            return table[i][qc], 1e-9
        i = max(0, min(len(t) - 2, i if t[i] <= tk else i - 1))
        h = t[i + 1] - t[i]
        u = (tk - t[i]) / h
        a, b = table[i], table[i + 1]
        h00, h10 = 2 * u**3 - 3 * u**2 + 1, u**3 - 2 * u**2 + u
        h01, h11 = -2 * u**3 + 3 * u**2, u**3 - u**2
        return h00 * a[qc] + h10 * h * a[qdc] + h01 * b[qc] + h11 * h * b[qdc], 1e-6

    def matches(header, table):
        compared = 0
        for k in poses["keys"]:
            for joint, angle in k["joints"].items():
                m = re.fullmatch(r"joint(\d+)", joint)
                if not m or f"q{m.group(1)} [rad]" not in header:
                    continue
                value, tol = angle_at(header, table, m.group(1), k["time"])
                if abs(value - angle) > tol:
                    return False
                compared += 1
        return compared > 0

    found = [f for f, (h, tb) in motions.items() if matches(h, tb)]
    if not found:
        bad.append(f"{name}/model.xml: no motion CSV has its keyframes' joint angles")
    else:
        keys += poses["nkey"]
        print(f"{name}: {poses['nkey']} keyframes are {found[0]} at their times")
print(f"{csvs} motion CSVs read; {keys} keyframes checked")
if bad:
    print("\n".join("FAIL: " + b for b in bad))
    sys.exit(1)
PY
echo "$checked models load and compile to .mjb in MuJoCo's tools; testxml's save and reload" \
  "matches for all of them (max difference $worst)"
