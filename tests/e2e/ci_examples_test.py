#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
"""The CI examples users copy, read as their CI would read them (YAML, python3-yaml):
examples/ci/study-reports.yml (GitHub Actions) and examples/ci/gitlab-ci.yml (GitLab CI).
Each must be a mapping of the keys its CI requires, run the set-up, validate results.json,
keep the report folder, hand junit.xml to the CI and diff against the main branch with
examples/ci/diff-tolerances.yaml; every armstudy command in them must name only options
that command has (its --help, from the armstudy under test), and every repository file they
name must exist.

usage: ci_examples_test.py SOURCE_DIR ARMSTUDY
"""
import os
import re
import shlex
import subprocess
import sys

import yaml

src, armstudy = sys.argv[1], sys.argv[2]
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


def commands_of(text):
    """Each armstudy command line of a script (continuation lines joined)."""
    text = text.replace("\\\n", " ")
    out = []
    for line in text.split("\n"):
        for segment in re.split(r"&&|\|\||[;|]", line):
            try:
                words = shlex.split(segment, comments=True)
            except ValueError:
                continue
            if words and os.path.basename(words[0]) == "armstudy":
                out.append(words[1:])
    return out


def check_commands(name, script):
    """The armstudy commands in `script` use only options their command has."""
    found = commands_of(script)
    for words in found:
        command = [w for w in words[:2] if not w.startswith("-")][:1]
        if words[:2] == ["sweep", "expand"]:
            command = ["sweep", "expand"]
        help_text = subprocess.run([armstudy] + command + ["--help"], capture_output=True,
                                   text=True, check=False).stdout
        check("Usage" in help_text, f"{name}: 'armstudy {' '.join(command)}' is no command")
        for w in words:
            if w.startswith("--"):
                option = w.split("=")[0]
                check(re.search(re.escape(option) + r"\b", help_text) is not None,
                      f"{name}: armstudy {' '.join(command)} has no option {option}")
    return found


def check_paths(name, script):
    """Repository files the script names exist."""
    for path in re.findall(r"\b((?:scripts|examples)/[\w./-]+)", script):
        check(os.path.exists(os.path.join(src, path)), f"{name}: names {path}, which is missing")


# --- GitHub Actions ----------------------------------------------------------------------
name = "examples/ci/study-reports.yml"
gh = yaml.safe_load(open(os.path.join(src, name)))
check(isinstance(gh, dict), f"{name}: not a mapping")
# YAML 1.1 reads the key `on` as true
check("on" in gh or True in gh, f"{name}: no 'on' trigger")
jobs = gh.get("jobs", {})
check(len(jobs) >= 1, f"{name}: no jobs")
steps = [s for job in jobs.values() for s in job.get("steps", [])]
for job_name, job in jobs.items():
    check("runs-on" in job, f"{name}: job {job_name} has no runs-on")
    for s in job.get("steps", []):
        check(("run" in s) != ("uses" in s), f"{name}: step {s.get('name')} needs run or uses")
gh_script = "\n".join(s.get("run", "") for s in steps)
gh_uses = [s.get("uses", "") for s in steps]
check("scripts/setup.sh" in gh_script, f"{name}: no set-up")
check("scripts/validate_results.py results.schema.json reports/out" in gh_script,
      f"{name}: results.json is not validated")
check(any(u.startswith("actions/upload-artifact@") for u in gh_uses), f"{name}: no upload")
check(any("junit" in u for u in gh_uses) and "reports/out/junit.xml" in yaml.safe_dump(gh),
      f"{name}: junit.xml is not handed to the CI")
gh_commands = check_commands(name, gh_script)
check(any(c[:1] == ["diff"] and "examples/ci/diff-tolerances.yaml" in c for c in gh_commands),
      f"{name}: no diff with examples/ci/diff-tolerances.yaml")
check_paths(name, gh_script)

# --- GitLab CI ---------------------------------------------------------------------------
name = "examples/ci/gitlab-ci.yml"
gl = yaml.safe_load(open(os.path.join(src, name)))
check(isinstance(gl, dict), f"{name}: not a mapping")
reserved = {"stages", "variables", "default", "workflow", "include", "image", "services",
            "cache", "before_script", "after_script"}
gl_jobs = {k: v for k, v in gl.items() if k not in reserved and not k.startswith(".")}
check(len(gl_jobs) >= 1, f"{name}: no jobs")
for job_name, job in gl_jobs.items():
    check(isinstance(job.get("script"), list) and job["script"],
          f"{name}: job {job_name} has no script")
    check(job.get("stage", "test") in gl.get("stages", ["build", "test", "deploy"]),
          f"{name}: job {job_name}'s stage is not among the stages")
gl_script = "\n".join(line for job in gl_jobs.values() for line in job.get("script", []))
check("scripts/setup.sh" in gl_script, f"{name}: no set-up")
check("scripts/validate_results.py results.schema.json reports/out" in gl_script,
      f"{name}: results.json is not validated")
artifacts = [job.get("artifacts", {}) for job in gl_jobs.values()]
check(any("reports/out/" in a.get("paths", []) for a in artifacts), f"{name}: no artefact")
check(any(a.get("reports", {}).get("junit") == "reports/out/junit.xml" for a in artifacts),
      f"{name}: junit.xml is not the test report")
check(any(a.get("when") == "always" for a in artifacts),
      f"{name}: the reports are not kept when a case fails")
gl_commands = check_commands(name, gl_script)
check(any(c[:1] == ["diff"] and "examples/ci/diff-tolerances.yaml" in c for c in gl_commands),
      f"{name}: no diff with examples/ci/diff-tolerances.yaml")
check_paths(name, gl_script)

for f in failures:
    print("FAIL:", f)
if failures:
    sys.exit(1)
print(f"both CI examples parse; {len(gh_commands) + len(gl_commands)} armstudy command(s) "
      "use only options their command has")
