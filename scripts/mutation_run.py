#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
"""A small mutation run: a handful of hand-made mutants of the physics and the checks, each
applied alone to a scratch copy of the tree, built, and the quick tier's core and studies
tests run on it (ctest -L quick -L '^(core|studies)$'). A mutant is killed when a test fails
(or the build does), and survives when every test passes. Not part of CI (each mutant is a
rebuild and a test run: minutes each); docs/testing.md has the last score.

  scripts/mutation_run.py                   every mutant
  scripts/mutation_run.py contact_margin    the mutants named
  scripts/mutation_run.py --check           only checks that each mutant's text is in its
                                            file exactly once (no copy, build or test)

Environment: ARMSTUDY_MUTATION_DIR (the scratch copy, default build/mutation of this tree, which
git ignores: under the same folder as the tree, ccache with CCACHE_BASEDIR finds most of the
libraries' objects of an earlier build; its files are replaced by the tree's on every run),
JOBS (build and test jobs, default 2). The tests stop at the first failure.
"""
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# (name, file, the text replaced (exactly once in the file), its replacement, what it breaks)
MUTANTS = [
    ("contact_margin", "src/app/throwing_pipeline.cpp",
     "sp.contact_margin - e.min_normal_force, 0.0", "-e.min_normal_force, 0.0",
     "the throw's contact check ignores the contact margin (N >= 0 instead of N >= margin)"),
    ("core_rk4_stage", "src/core/integrators.hpp",
     "const State k3 = f(t + 0.5 * h, State(x + 0.5 * h * k2));",
     "const State k3 = f(t + 0.5 * h, State(x + 0.5 * h * k1));",
     "core::rk4_step's third stage from k1 (the throw's Planner and kernel both step with it)"),
    # the Planner and the kernel have no RK4 stages of their own: their mutants break how they
    # hand core::rk4_step their right-hand side (each is then no longer the other's twin)
    ("planner_rk4_stage", "src/studies/throwing/simulate.cpp",
     "planner.eval(stage, t, y, kj);", "planner.eval(stage, t, x, kj);",
     "the throw Planner's RK4: core::rk4_step's stages evaluated at the step's start state"),
    ("kernel_rk4_stage", "src/studies/throwing/simulate_kernel.cpp",
     "K.eval(k, t, y, kj);", "K.eval(k, t, x, kj);",
     "the throw kernel's RK4: core::rk4_step's stages evaluated at the step's start state"),
    ("richardson_safety", "src/studies/time_optimal/result.hpp",
     "kExtrapolationSafety = 4.0", "kExtrapolationSafety = 1.0",
     "the Richardson error's safety factor 1 (was 4)"),
    ("printed_limit_sign", "src/studies/placement/printed_limits.cpp",
     "const double x = peak / limit - 1;", "const double x = 1 - peak / limit;",
     "the sign of the placement's torque and power limit check"),
    ("core_motor_friction", "src/core/dc_motor.cpp",
     "b3 * tau + b3 * m.tau_f * sign(qd);", "b3 * tau - b3 * m.tau_f * sign(qd);",
     "core::motor_sample's Coulomb friction with the wrong sign"),
    ("kernel_motor_friction", "src/studies/throwing/simulate_kernel.cpp",
     "c_f[m] = b * mo.tau_f;", "c_f[m] = -b * mo.tau_f;",
     "the throw kernel's motor: Coulomb friction with the wrong sign"),
    ("block_lateral_sign", "src/studies/placement/arm2_block.cpp",
     "const double gp = -A * s2 - B * c2;", "const double gp = -A * s2 + B * c2;",
     "the blocked placement evaluator's Coriolis term with a lateral centre of mass"),
    ("coarse_tolerance", "src/studies/time_optimal/solve.cpp",
     "out.value = std::max(kExactTolerance, err);",
     "out.value = std::max(kCoarseViolationTolerance, err);",
     "the exact time-optimal solution held only to the coarse solvers' 1e-3"),
    ("pendulum_drift_tolerance", "src/app/pendulum_pipeline.cpp",
     "result.energy_drift_rel, spec.drift_tolerance", "result.energy_drift_rel, 1e-6",
     "the pendulum's drift check against 1e-6 instead of the case's tolerance"),
]


def run(cmd, cwd, log):
    with open(log, "a") as f:
        f.write("$ " + " ".join(cmd) + "\n")
        f.flush()
        return subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT).returncode


def build_and_test(scratch, jobs, log):
    """0: every selected test passed; 1: a test failed; 2: the build failed."""
    targets = ["--target", "core_tests", "studies_tests"]
    if run(["nice", "cmake", "--build", "build", "-j", jobs] + targets, scratch, log) != 0:
        return 2
    ctest = ["ctest", "--test-dir", "build", "-j", jobs, "-L", "quick", "-L", "^(core|studies)$",
             "--timeout", "600", "--stop-on-failure"]
    return 0 if run(ctest, scratch, log) == 0 else 1


def check():
    """Each mutant's text exactly once in this tree's file: 0, else 1 (nothing built)."""
    bad = 0
    for name, rel, old, _, what in MUTANTS:
        path = os.path.join(ROOT, rel)
        n = open(path).read().count(old) if os.path.isfile(path) else 0
        print(f"{name}: {'found once' if n == 1 else f'found {n} times'} in {rel}: {what}")
        bad += n != 1
    print(f"{len(MUTANTS) - bad} of {len(MUTANTS)} mutants apply")
    return 1 if bad else 0


def main():
    names = sys.argv[1:]
    if names in (["-h"], ["--help"]):
        print(__doc__)
        return 0
    if names == ["--check"]:
        return check()
    unknown = [n for n in names if n not in [m[0] for m in MUTANTS]]
    if unknown:
        print(f"no mutant named {', '.join(unknown)} (--check lists them)")
        return 2
    mutants = [m for m in MUTANTS if not names or m[0] in names]
    scratch = os.environ.get("ARMSTUDY_MUTATION_DIR", os.path.join(ROOT, "build", "mutation"))
    jobs = os.environ.get("JOBS", "2")
    t0 = time.time()
    # the tree as it is (tracked and new files, not the ignored ones) in the scratch folder,
    # over an earlier copy (its build folder kept: only what changed is built again)
    files = subprocess.run(["git", "ls-files", "-co", "--exclude-standard"], cwd=ROOT,
                           check=True, capture_output=True, text=True).stdout.split("\n")
    for rel in filter(None, files):
        src = os.path.join(ROOT, rel)
        if not os.path.isfile(src):
            continue
        dst = os.path.join(scratch, rel)
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        if not os.path.exists(dst) or open(src, "rb").read() != open(dst, "rb").read():
            shutil.copy2(src, dst)
    log = os.path.join(scratch, "mutation.log")
    open(log, "w").close()
    configure = ["cmake", "-S", ".", "-B", "build", "-DCMAKE_BUILD_TYPE=Release",
                 "-DARMSTUDY_BUILD_BENCH=OFF", "-DARMSTUDY_WERROR=ON"]
    if shutil.which("ccache"):
        configure += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"]
    if run(configure, scratch, log) != 0 or build_and_test(scratch, jobs, log) != 0:
        print(f"the unmutated tree does not build or pass its tests: see {log}")
        return 2
    print(f"baseline built and passed in {time.time() - t0:.0f} s")
    rows = []
    for name, rel, old, new, what in mutants:
        path = os.path.join(scratch, rel)
        text = open(path).read()
        if text.count(old) != 1:
            print(f"{name}: the text to mutate is not in {rel} exactly once; skipped")
            rows.append((name, "not applied", what, 0))
            continue
        start = time.time()
        with open(log, "a") as f:
            f.write(f"\n=== mutant {name}: {what}\n")
        open(path, "w").write(text.replace(old, new))
        try:
            outcome = build_and_test(scratch, jobs, log)
        finally:
            open(path, "w").write(text)
        verdict = {0: "SURVIVED", 1: "killed", 2: "killed (build)"}[outcome]
        rows.append((name, verdict, what, time.time() - start))
        print(f"{name}: {verdict} ({time.time() - start:.0f} s): {what}", flush=True)
    applied = [r for r in rows if r[1] != "not applied"]
    killed = [r for r in applied if r[1].startswith("killed")]
    print(f"\nscore: {len(killed)} of {len(applied)} mutants killed in {time.time() - t0:.0f} s")
    for r in applied:
        if r[1] == "SURVIVED":
            print(f"  survived: {r[0]}: {r[2]}")
    print(f"log: {log}")
    return 0 if len(killed) == len(applied) else 1


if __name__ == "__main__":
    sys.exit(main())
