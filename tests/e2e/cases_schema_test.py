#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
"""Every bundled case (reports/cases, the sweep's base case) and the case `armstudy init`
prints for every study validate against case.schema.json as an editor reads them (YAML by
python3-yaml, JSON Schema draft-07 by python3-jsonschema), and each bundled case names the
schema on its first line; a case with a misspelt key, a number as text or a value out of
range does not validate (the schema is no empty promise).

usage: cases_schema_test.py SOURCE_DIR ARMSTUDY
"""
import copy
import glob
import json
import os
import subprocess
import sys

import jsonschema
import yaml

src, armstudy = sys.argv[1], sys.argv[2]
schema = json.load(open(os.path.join(src, "case.schema.json")))
validator = jsonschema.Draft7Validator(schema)
failures = []


def errors_of(case):
    return [f"{'/'.join(map(str, e.absolute_path))}: {e.message}"
            for e in validator.iter_errors(case)]


bundled = sorted(glob.glob(os.path.join(src, "reports/cases/*.yaml")) +
                 [os.path.join(src, "reports/sweeps/placement-link-ratio-base.yaml")])
for path in bundled:
    text = open(path).read()
    if not text.startswith("# yaml-language-server: $schema=../../case.schema.json\n"):
        failures.append(f"{path}: does not name the schema on its first line")
    for e in errors_of(yaml.safe_load(text)):
        failures.append(f"{path}: {e}")

studies = schema["properties"]["study"]["enum"]
inits = {}
for study in studies:
    r = subprocess.run([armstudy, "init", study], capture_output=True, text=True, check=False)
    if r.returncode != 0:
        failures.append(f"armstudy init {study}: exit {r.returncode}: {r.stderr}")
        continue
    inits[study] = yaml.safe_load(r.stdout)
    for e in errors_of(inits[study]):
        failures.append(f"armstudy init {study}: {e}")

# what the schema refuses
example = yaml.safe_load(open(os.path.join(src, "reports/cases/placement-example-2.yaml")))
broken = []
case = copy.deepcopy(example)
case["placement"]["duration"] = 1.0  # misspelt
broken.append(("a misspelt key", case))
case = copy.deepcopy(example)
case["placement"]["duration_s"] = "1.0"  # text
broken.append(("a number as text", case))
case = copy.deepcopy(example)
case["render"] = {"frames": 100}  # beyond 24
broken.append(("frames out of range", case))
case = copy.deepcopy(example)
case["study"] = "placment"
broken.append(("an unknown study", case))
for what, case in broken:
    if not errors_of(case):
        failures.append(f"the schema accepts {what}")

for f in failures:
    print("FAIL:", f)
if failures:
    sys.exit(1)
print(f"{len(bundled)} bundled case(s) and {len(inits)} init case(s) validate against "
      f"case.schema.json; {len(broken)} broken cases do not")
