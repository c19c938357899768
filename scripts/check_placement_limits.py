#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
"""Independent check of limit-bound placement optima: pure Python, no code shared with
armstudy (the model and the energy quadrature are the sibling scripts'
check_placement_optimum.py and check_placement_energy.py, themselves independent of it).

A torque or power limit is a limit on the motion, not on its samples. For every optimum of
the given results.json files this script
  1. finds the peak of each limited |torque| and |power| of the printed line on the
     continuous motion (a 2000-point scan, then golden section around every scan maximum
     within 1 % of the largest, to 1e-12 of the duration) and fails when a peak is above its
     limit by more than 1e-12 relative;
  2. when the optimum names a limit among its active constraints (decided_by.active; a
     clearance may be active too, a corner), searches the least energy on that limit's boundary itself: for each phi
     the x_s with peak = limit (secant, then bisection, to 1e-15 m), the energy there by
     tanh-sinh quadrature (check_placement_energy.py), golden section over phi within
     +-0.3 deg of the printed phi to 1e-9 deg, keeping the clearance margin; and fails when
     armstudy's energy lies further from this minimum than the two error estimates
     together (armstudy's energy_error_J and this search's: its quadrature error plus the
     energy's change over the last golden bracket).

usage: check_placement_limits.py [results.json ...]
  without arguments it runs build/armstudy (or $ARMSTUDY) with --no-render on the limit
  cases tests/studies/cases/placement-limit-*.yaml into a temporary directory. Exit status 1
  when a check fails, 2 on a usage or run error."""
import glob
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_placement_energy as quad  # noqa: E402  (Line, energy)
import check_placement_optimum as arm  # noqa: E402  (clearance)

GOLDEN = 0.5 * (math.sqrt(5.0) - 1.0)


def quantity(line, kind, joint):
    """|torque| or |power| of joint 0 (root) or 1 (elbow) as a function of t."""
    def f(t):
        M1, M2, r1, r2 = line.state(t)
        m, r = (M1, r1) if joint == 0 else (M2, r2)
        return abs(m) if kind == "torque" else abs(m * r)
    return f


def peak(line, kind, joint, n=2000):
    f = quantity(line, kind, joint)
    ts = [line.T * k / (n - 1) for k in range(n)]
    vs = [f(t) for t in ts]
    top = max(vs)
    best = top
    for k, v in enumerate(vs):
        if v < 0.99 * top or (k > 0 and vs[k - 1] > v) or (k < n - 1 and vs[k + 1] > v):
            continue
        a, b = ts[max(k - 1, 0)], ts[min(k + 1, n - 1)]
        c, e = b - GOLDEN * (b - a), a + GOLDEN * (b - a)
        fc, fe = f(c), f(e)
        while b - a > 1e-12 * line.T:
            if fc >= fe:
                b, e, fe = e, c, fc
                c = b - GOLDEN * (b - a)
                fc = f(c)
            else:
                a, c, fc = c, e, fe
                e = a + GOLDEN * (b - a)
                fe = f(e)
        best = max(best, fc, fe)
    return best


class Problem:
    def __init__(self, pl, o, kind, joint, limit):
        self.L, self.T, self.prog, self.conf = pl["length_m"], pl["duration_s"], o["program"], \
            o["configuration"]
        self.kind, self.joint, self.limit = kind, joint, limit
        self.margin = pl["singularity_margin_m"]

    def line(self, xs, phi_deg):
        return quad.Line(xs, phi_deg, self.L, self.T, self.prog, self.conf)

    def g(self, xs, phi_deg):
        return peak(self.line(xs, phi_deg), self.kind, self.joint, 600) / self.limit - 1

    def xs_on_limit(self, phi_deg, guess):
        """x_s with peak = limit at phi: secant from the guess, then bisection on the
        admissible side (g <= 0)."""
        a, b = guess, guess + 1e-6
        ga, gb = self.g(a, phi_deg), self.g(b, phi_deg)
        for _ in range(30):
            if gb == ga:
                break
            c = b - gb * (b - a) / (gb - ga)
            a, ga, b, gb = b, gb, c, self.g(c, phi_deg)
            if abs(b - a) < 1e-13:
                break
        lo, hi, glo = b - 1e-9, b + 1e-9, self.g(b - 1e-9, phi_deg)
        ghi = self.g(hi, phi_deg)
        if (glo <= 0) == (ghi <= 0):
            return b   # no sign change bracketed: the secant's root
        while hi - lo > 1e-15:
            mid = 0.5 * (lo + hi)
            if mid in (lo, hi):
                break
            gm = self.g(mid, phi_deg)
            if (gm <= 0) == (glo <= 0):
                lo, glo = mid, gm
            else:
                hi = mid
        return lo if glo <= 0 else hi

    def energy_at(self, phi_deg, guess):
        xs = self.xs_on_limit(phi_deg, guess)
        cin, cout = arm.clearance(xs, math.radians(phi_deg), self.L)
        if min(cin, cout) < self.margin:
            return math.inf, 0.0, xs
        e, err = quad.energy(self.line(xs, phi_deg))
        return e, err, xs

    def search(self, xs0, phi0):
        """golden section over phi on the limit's boundary around (xs0, phi0)."""
        guess = [xs0]

        def h(phi):
            e, err, xs = self.energy_at(phi, guess[0])
            if math.isfinite(e):
                guess[0] = xs
            return e, err, xs

        a, b = phi0 - 0.3, phi0 + 0.3
        c, d = b - GOLDEN * (b - a), a + GOLDEN * (b - a)
        hc, hd = h(c), h(d)
        while b - a > 1e-9:
            if hc[0] <= hd[0]:
                b, d, hd = d, c, hc
                c = b - GOLDEN * (b - a)
                hc = h(c)
            else:
                a, c, hc = c, d, hd
                d = a + GOLDEN * (b - a)
                hd = h(d)
        best, phi = (hc, c) if hc[0] <= hd[0] else (hd, d)
        # the energy's change over the last bracket (its feasible points: at a corner with a
        # clearance the bracket's far side leaves the admissible set)
        near = [v[0] for v in (hc, hd, h(a), h(b)) if math.isfinite(v[0])]
        return best[0], best[1] + max(near) - min(near), best[2], phi


def limits_of(pl):
    out = []
    for kind, key in (("torque", "torque_limits_Nm"), ("power", "power_limits_W")):
        lims = pl.get(key)
        if lims:
            out += [(kind, j, lims[j]) for j in (0, 1)]
    return out


def check(path):
    with open(path) as fh:
        pl = json.load(fh)["placement"]
    bad = 0
    print(os.path.basename(os.path.dirname(path)))
    for o in pl["optima"]:
        if o.get("x_s_m") is None or o.get("energy_J") is None:
            continue
        line = quad.Line(o["x_s_m"], o["phi_deg"], pl["length_m"], pl["duration_s"], o["program"],
                         o["configuration"])
        name = f"  {o['program']} conf. {o['configuration']}"
        for kind, j, lim in limits_of(pl):
            p = peak(line, kind, j)
            ok = p <= lim * (1 + 1e-12)
            bad += not ok
            if p > 0.99 * lim:
                print(f"{name}: continuous peak {kind} of joint {j + 1} {p:.10f} against "
                      f"{lim:g}: {'ok' if ok else 'ABOVE THE LIMIT'}")
        active = [a for a in o["decided_by"]["active"]
                  if a["constraint"] in ("torque_limit", "power_limit")]
        if not active:
            print(f"{name}: decided by {o['decided_by']['binding']}; no limit active")
            continue
        kind = active[0]["constraint"].split("_")[0]
        joint = active[0]["joint"] - 1
        lim = pl["torque_limits_Nm" if kind == "torque" else "power_limits_W"][joint]
        pr = Problem(pl, o, kind, joint, lim)
        e, err, xs, phi = pr.search(o["x_s_m"], o["phi_deg"])
        a, aerr = o["energy_J"], o["refinement"]["energy_error_J"] or 0.0
        diff = a - e
        ok = abs(diff) <= err + aerr + 1e-12 * abs(e)
        bad += not ok
        print(f"{name}: on the continuous {kind} limit of joint {joint + 1}: least energy "
              f"{e:.10f} +- {err:.1e} J at x_s {xs:.10f} m, phi {phi:.8f} deg; armstudy "
              f"{a:.10f} +- {aerr:.1e} J at {o['x_s_m']:.10f} m, {o['phi_deg']:.8f} deg; "
              f"difference {diff:.1e} J {'ok' if ok else 'BEYOND THE ERRORS'}")
    return bad


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    if len(sys.argv) > 1:
        paths = sys.argv[1:]
        bad = sum(check(p) for p in paths)
    else:
        cases = sorted(glob.glob(os.path.join(root, "tests", "studies", "cases",
                                              "placement-limit-*.yaml")))
        if not cases:
            print("no limit cases found", file=sys.stderr)
            return 2
        exe = os.environ.get("ARMSTUDY", os.path.join(root, "build", "armstudy"))
        with tempfile.TemporaryDirectory(prefix="check_placement_limits_") as out:
            r = subprocess.run([exe, "run", *cases, "--no-render", "--out", out],
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            if r.returncode != 0:
                print("armstudy run failed", file=sys.stderr)
                return 2
            names = [os.path.splitext(os.path.basename(c))[0] for c in cases]
            bad = sum(check(os.path.join(out, n, "results.json")) for n in names)
    print("all within the limits and the stated errors" if not bad else
          f"{bad} value(s) above a limit or beyond the stated errors")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
