#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
"""Compare the results.json files of two runs of the same cases, e.g. before and after a
change of the number format or of the code that writes the file.

usage: compare_results.py BEFORE_DIR AFTER_DIR [CASE...]   (default: every case in both)

A number passes when the two are equal or when AFTER, rounded to as many significant
digits as BEFORE's shortest form has, gives BEFORE (so a file written in full precision
matches one rounded to 8 digits). Run times (keys and key figures with 'run_time' or
'seconds' in their name), provenance, git commits and the 'files' list are ignored.
Prints every difference; exits 1 if there is one.
"""
import json
import os
import sys


class Num(str):
    """A number kept as its text."""


IGNORED = ("provenance", "git_commit", "files")


def significant(text):
    digits = repr(float(text)).lower().lstrip("-").split("e")[0].replace(".", "")
    return max(1, len(digits.lstrip("0").rstrip("0")))


def volatile(path):
    return "run_time" in path or "seconds" in path


def compare(a, b, path, out):
    if isinstance(a, dict) and isinstance(b, dict):
        if isinstance(a.get("name"), str) and volatile(a["name"]):
            return
        for k in sorted(set(a) ^ set(b)):
            out.append(f"{path}/{k}: only in {'before' if k in a else 'after'}")
        for k in sorted(set(a) & set(b)):
            if k not in IGNORED and not volatile(k):
                compare(a[k], b[k], f"{path}/{k}", out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out.append(f"{path}: {len(a)} entries before, {len(b)} after")
            return
        for i, (x, y) in enumerate(zip(a, b)):
            compare(x, y, f"{path}/{i}", out)
    elif isinstance(a, Num) and isinstance(b, Num):
        x, y = float(a), float(b)
        if x != y and float("%.*g" % (significant(a), y)) != x:
            out.append(f"{path}: {a} before, {b} after")
    elif a != b:
        out.append(f"{path}: {str(a)[:80]!r} before, {str(b)[:80]!r} after")


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f, parse_float=Num, parse_int=Num)


def main(argv):
    if len(argv) < 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    before, after = argv[1], argv[2]
    cases = argv[3:] or sorted(
        n for n in os.listdir(before)
        if os.path.isfile(os.path.join(before, n, "results.json"))
        and os.path.isfile(os.path.join(after, n, "results.json")))
    problems = []
    for case in cases:
        a = load(os.path.join(before, case, "results.json"))
        b = load(os.path.join(after, case, "results.json"))
        compare(a, b, case, problems)
    for p in problems:
        print(p)
    print(f"{len(cases)} case(s) compared: {len(problems)} difference(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
