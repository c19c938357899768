#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
"""Checks an armstudy output folder after a run was killed, for the crash-safety tests.

usage: crash_check.py OUT CASE_NAME SHA_OLD SHA_NEW [--no-hidden]
       crash_check.py --serve


Passes (exit 0) when OUT/CASE_NAME is a complete report, the earlier one (its results.json
names the case file SHA_OLD) or the new one (SHA_NEW): results.json parses and every file
it lists is there with its size and sha256 (a missing folder fails). The run-level files
that exist are complete: junit.xml parses as XML, sweep.json and results.json as JSON,
index.html ends with </html>. With --no-hidden nothing hidden (a killed run's scratch
folder or an earlier version's .<case>.old-*) may be left in OUT, nor a *.part-* file in OUT
or the case folder. Prints what is wrong.
"""
import hashlib
import json
import pathlib
import sys
import xml.etree.ElementTree as ET


def problems(out, name, shas, no_hidden):
    found = []
    case = out / name
    rj = case / "results.json"
    if not rj.is_file():
        return [f"{case}: no results.json (the report is lost)"]
    try:
        j = json.loads(rj.read_text())
    except ValueError as e:
        return [f"{rj}: not JSON ({e})"]
    sha = j.get("case", {}).get("sha256")
    if sha not in shas:
        found.append(f"{rj}: case sha256 {sha} is neither the old nor the new case file")
    listed = {f["path"] for f in j.get("files", [])}
    for f in j.get("files", []):
        p = case / f["path"]
        if not p.is_file():
            found.append(f"{p}: listed in results.json, missing")
            continue
        data = p.read_bytes()
        if len(data) != f["bytes"] or hashlib.sha256(data).hexdigest() != f["sha256"]:
            found.append(f"{p}: not the file results.json lists (incomplete or mixed)")
    for p in case.rglob("*"):
        rel = p.relative_to(case).as_posix()
        if p.is_file() and rel not in listed and rel not in ("results.json", "report.pdf"):
            found.append(f"{p}: not listed in results.json")
    if (out / "junit.xml").exists():
        try:
            ET.parse(out / "junit.xml")
        except ET.ParseError as e:
            found.append(f"{out / 'junit.xml'}: half-written ({e})")
    if (out / "sweep.json").exists():
        try:
            json.loads((out / "sweep.json").read_text())
        except ValueError as e:
            found.append(f"{out / 'sweep.json'}: half-written ({e})")
    if (out / "index.html").exists() and not (out / "index.html").read_text().rstrip().endswith("</html>"):
        found.append(f"{out / 'index.html'}: half-written")
    if no_hidden:
        found += [f"{p}: left behind" for p in out.iterdir() if p.name.startswith(".")]
        # (a user's folder beside the cases may hold files of any name)
        found += [f"{p}: left behind" for p in out.glob("*.part-*")]
        found += [f"{p}: left behind" for p in case.rglob("*.part-*")]
    return found


def serve():
    for line in sys.stdin:
        out, name, old, new, *flags = line.rstrip("\n").split("\t")
        out = pathlib.Path(out)
        if not ("--aside-ok" in flags and not (out / name).exists()):
            for f in problems(out, name, {old, new}, "--no-hidden" in flags):
                print(f)
        print(".", flush=True)
    return 0


def main(argv):
    if argv[1:] == ["--serve"]:
        return serve()
    if len(argv) < 5:
        print(__doc__, file=sys.stderr)
        return 2
    out, name, old, new = pathlib.Path(argv[1]), argv[2], argv[3], argv[4]
    found = problems(out, name, {old, new}, "--no-hidden" in argv[5:])
    for f in found:
        print(f)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
