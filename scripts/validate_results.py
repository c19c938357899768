#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
"""Validates results.json files against results.schema.json (JSON Schema 2020-12).

usage: validate_results.py SCHEMA FILE_OR_DIR...   (a folder is searched for results.json)
Prints one line per invalid file with the first error; exit 0 if all valid, 1 otherwise,
2 if no file was found.
"""
import json
import pathlib
import sys

import jsonschema


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    schema = json.loads(pathlib.Path(argv[1]).read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    files = []
    for item in argv[2:]:
        p = pathlib.Path(item)
        files += sorted(p.rglob("results.json")) if p.is_dir() else [p]
    if not files:
        print("no results.json found", file=sys.stderr)
        return 2
    bad = 0
    for f in files:
        errors = sorted(validator.iter_errors(json.loads(f.read_text())), key=lambda e: list(e.path))
        if errors:
            bad += 1
            e = errors[0]
            where = "/".join(str(x) for x in e.path) or "(root)"
            print(f"{f}: invalid at {where}: {e.message}")
    print(f"{len(files) - bad} valid, {bad} invalid of {len(files)} results.json")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
