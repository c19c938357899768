#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
"""Lists the functions in src/ longer than a limit, longest first (the house rule,
docs/architecture.md: no function over 120 lines, none over 60 without a reason in its
comment).

    scripts/function_lengths.py              every function over 60 lines, and a summary
    scripts/function_lengths.py --over 100   every function over 100 lines
    scripts/function_lengths.py --max 120    also exits 1 when any function is over 120

A function's length is its lines from the line its name is on to its closing brace, as
universal-ctags reports them (line: and end: fields). Lambdas (ctags names them __anon...)
are not listed on their own; their lines count in the function that holds them. Needs
universal-ctags (Debian package universal-ctags).
"""
import argparse
import os
import subprocess
import sys


def functions(root):
    """(length, file, line, name) of every function under root, lambdas left out."""
    out = subprocess.run(
        ["ctags", "--fields=+ne", "--c++-kinds=f", "--extras=-q", "-R", "-o", "-", root],
        check=True, capture_output=True, text=True).stdout
    found = []
    for row in out.splitlines():
        cols = row.split("\t")
        if len(cols) < 4 or cols[0].startswith("__anon"):
            continue
        name, path = cols[0], cols[1]
        fields = dict(c.split(":", 1) for c in cols[3:] if ":" in c)
        if "line" not in fields or "end" not in fields:
            continue
        start, end = int(fields["line"]), int(fields["end"])
        scope = ""
        for kind in ("class", "struct", "union", "function", "namespace"):
            if kind in fields:
                scope = fields[kind]
                break
        parts = [p for p in scope.split("::")
                 if p and not p.startswith("__anon") and p != "armstudy"]
        found.append((end - start + 1, path, start, "::".join(parts + [name])))
    found.sort(key=lambda f: (-f[0], f[1], f[2]))
    return found


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--over", type=int, default=60,
                    help="list the functions longer than this many lines (default 60)")
    ap.add_argument("--max", type=int, default=None,
                    help="exit 1 when any function is longer than this many lines")
    ap.add_argument("--root", default="src", help="folder to scan (default src)")
    args = ap.parse_args()
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", args.root) \
        if not os.path.isabs(args.root) and not os.path.isdir(args.root) else args.root
    found = functions(root)
    for length, path, line, name in found:
        if length > args.over:
            print(f"{length:5d}  {os.path.relpath(path)}:{line}  {name}")
    over60 = sum(1 for f in found if f[0] > 60)
    over120 = sum(1 for f in found if f[0] > 120)
    print(f"{len(found)} functions; {over60} over 60 lines, {over120} over 120"
          + (f"; longest {found[0][0]} lines" if found else ""))
    if args.max is not None:
        too_long = [f for f in found if f[0] > args.max]
        if too_long:
            print(f"function_lengths: {len(too_long)} function(s) over {args.max} lines",
                  file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
