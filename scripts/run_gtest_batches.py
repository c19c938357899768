#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
"""Runs the tests CTest selects, GoogleTests batched: several tests per process.

CTest runs each GoogleTest in its own process (gtest_discover_tests). Under AddressSanitizer
a process costs about 0.35 to 0.55 CPU-s before its test runs and when it exits (the shadow
memory of armstudy's large libraries, LeakSanitizer's scan at exit), about half of it in
the kernel: over the sanitizer tier's 448 tests that is about 200 CPU-s of the tier's 464.
This runner asks CTest which tests a selection holds (`ctest --show-only=json-v1 ARGS`),
runs the GoogleTests of each executable in batches (`--gtest_filter=A:B:...`, the test's own
working folder and environment), the others (scripts) one by one through CTest, JOBS at a
time, and prints CTest's summary lines. A batch that fails prints its whole output (the
sanitizer's report names the test: GoogleTest prints `[ RUN      ] Suite.Name` first); a
batch that crashes counts each of its tests that did not pass as failed.

usage: run_gtest_batches.py BUILD_DIR JOBS TIMEOUT [ctest selection arguments...]
"""
import concurrent.futures
import json
import os
import re
import subprocess
import sys
import time

BATCH = 24  # GoogleTests per process: enough to spread the slow suites over the batches
# the executables whose tests run armstudy itself (seconds each, instrumented): smaller
# batches, started first, so that the last batch to end is a short one
SLOW = {"e2e_tests": 6, "cli_tests": 8}


def selection(build, args):
    out = subprocess.run(["ctest", "--test-dir", build, "--show-only=json-v1", *args],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)["tests"]


def props(test):
    return {p["name"]: p["value"] for p in test.get("properties", [])}


def gtest_name(test):
    cmd = test.get("command") or []
    if len(cmd) >= 2 and cmd[1].startswith("--gtest_filter="):
        return cmd[1][len("--gtest_filter="):]
    return None


def batches(tests):
    """(label, command, cwd, env, names) per process: GoogleTests grouped by executable and
    environment, dealt round-robin into batches of about BATCH so that one suite's slow tests
    spread over several; every other test alone through CTest."""
    groups, alone = {}, []
    for t in tests:
        p = props(t)
        name = gtest_name(t)
        if name is None or p.get("DISABLED"):
            alone.append(t)
            continue
        env = tuple(p.get("ENVIRONMENT", []))
        key = (t["command"][0], p.get("WORKING_DIRECTORY", ""), env)
        groups.setdefault(key, []).append(name)
    out = []
    for (exe, cwd, env), names in groups.items():
        n = max(1, round(len(names) / SLOW.get(os.path.basename(exe), BATCH)))
        for i in range(n):
            part = names[i::n]
            out.append((f"{os.path.basename(exe)} [{i + 1}/{n}]",
                        [exe, "--gtest_filter=" + ":".join(part)], cwd, env, part))
    out.sort(key=lambda b: os.path.basename(b[1][0]) not in SLOW)  # stable: slow ones first
    return out, alone


def run_batch(batch, timeout, logdir):
    label, cmd, cwd, env, names = batch
    environ = dict(os.environ)
    for kv in env:
        k, _, v = kv.partition("=")
        environ[k] = v
    log = os.path.join(logdir, re.sub(r"[^A-Za-z0-9]+", "_", label) + ".log")
    start = time.time()
    with open(log, "w") as f:
        try:
            code = subprocess.run(cmd, cwd=cwd or None, env=environ, stdout=f,
                                  stderr=subprocess.STDOUT, timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            code = "timeout"
    text = open(log, errors="replace").read()
    # a test GoogleTest skipped (GTEST_SKIP) is not a failure, as CTest counts it
    passed = set(re.findall(r"^\[ {7}OK \] (\S+)|^\[  SKIPPED \] (\S+)", text, re.M))
    passed = {a or b for a, b in passed}
    failed = [n for n in names if n not in passed]
    if code == 0 and failed:  # a test the filter matched did not run: count it failed
        code = "missing"
    return label, code, failed, time.time() - start, text


def run_alone(test, build, timeout):
    start = time.time()
    r = subprocess.run(["ctest", "--test-dir", build, "--output-on-failure", "--timeout",
                        str(timeout), "-R", "^" + re.escape(test["name"]) + "$"],
                       capture_output=True, text=True)
    return test["name"], r.returncode, [test["name"]] if r.returncode else [], \
        time.time() - start, r.stdout + r.stderr


def main():
    build, jobs, timeout, args = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4:]
    tests = selection(build, args)
    grouped, alone = batches(tests)
    logdir = os.path.join(build, "batches")
    os.makedirs(logdir, exist_ok=True)
    total = sum(len(b[4]) for b in grouped) + len(alone)
    print(f"batches: {total} tests, {sum(len(b[4]) for b in grouped)} GoogleTests in "
          f"{len(grouped)} processes, {len(alone)} others through CTest", flush=True)
    failed, start = [], time.time()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        # the scripts first (each one process, often the longest), then the batches
        futures = [pool.submit(run_alone, t, build, timeout) for t in alone]
        # a batch's timeout: the per-test timeout for its longest test, twice over
        futures += [pool.submit(run_batch, b, 2 * timeout, logdir) for b in grouped]
        for f in concurrent.futures.as_completed(futures):
            label, code, bad, seconds, text = f.result()
            verdict = "Passed" if code == 0 else f"***Failed ({code})"
            print(f"    {label} ... {verdict} {seconds:.2f} sec", flush=True)
            if code != 0:
                failed += bad or [label]
                print(text[-30000:], flush=True)
    passed = total - len(failed)
    print(f"\n{100 * passed // max(total, 1)}% tests passed, {len(failed)} tests failed out of "
          f"{total}\n\nTotal Test time (real) = {time.time() - start:.2f} sec")
    if failed:
        print("\nThe following tests FAILED:")
        for n in failed:
            print(f"\t{n} (Failed)")
        sys.exit(8)


if __name__ == "__main__":
    main()
