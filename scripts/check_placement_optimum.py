#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
"""Independent check of a placement optimum: pure Python, no code shared with
armstudy. Model: the 2-link arm in absolute angles (th1, th2) from its Lagrangian, torques
M2 = Q2 (elbow), M1 = Q1 + Q2 (root), energy = int |M1 th1'| + |M2 (th2' - th1')| dt by the
trapezoid on the same uniform time grid. The optimum is searched by brute force: a coarse
global grid over (x_s, phi) among admissible lines, then every family of lines on the
boundary of the admissible set (tangent to the circle |L1 - L2| + margin, an end on it, an
end on the circle L1 + L2 - margin) scanned finely and polished by golden section.

usage: check_placement_optimum.py [fraction] [program] [configuration] [margin] [samples]
defaults: 0.5 cycloidal 1 0.01 401 (the thesis's arm, T = 1 s)."""
import math
import sys

L1, L2 = 0.4, 0.2
m1, m2, mp = 4.0, 2.0, 1.0
r1, r2 = 0.2, 0.1
I1, I2 = m1 * L1 ** 2 / 12, m2 * L2 ** 2 / 12
J1 = I1 + m1 * r1 ** 2 + (m2 + mp) * L1 ** 2   # link 1 about the root, with what it carries
J2 = I2 + m2 * r2 ** 2 + mp * L2 ** 2          # link 2 and payload about the elbow
H = (m2 * r2 + mp * L2) * L1
INNER, OUTER = abs(L1 - L2), L1 + L2
LMAX = 4 * math.sqrt(L1 * L2)


def program(name, T, L, n):
    out = []
    for k in range(n):
        t = k * T / (n - 1)
        tau = t / T
        if name == "cycloidal":
            w = 2 * math.pi / T
            s = L * (tau - math.sin(w * t) / (2 * math.pi))
            sd = L / T * (1 - math.cos(w * t))
            sdd = L * w / T * math.sin(w * t)
        else:  # poly345
            s = L * (10 * tau ** 3 - 15 * tau ** 4 + 6 * tau ** 5)
            sd = L / T * (30 * tau ** 2 - 60 * tau ** 3 + 30 * tau ** 4)
            sdd = L / T ** 2 * (60 * tau - 180 * tau ** 2 + 120 * tau ** 3)
        out.append((s, sd, sdd))
    return out


def energy(prog, T, xs, phi, config):
    ux, uy = math.cos(phi), math.sin(phi)
    n = len(prog)
    dt = T / (n - 1)
    total = 0.0
    for k, (s, sd, sdd) in enumerate(prog):
        px, py = xs + s * ux, s * uy
        c = (px * px + py * py - L1 * L1 - L2 * L2) / (2 * L1 * L2)
        c = max(-1.0, min(1.0, c))
        q2 = math.acos(c) * (1 if config == 1 else -1)
        th1 = math.atan2(py, px) - math.atan2(L2 * math.sin(q2), L1 + L2 * math.cos(q2))
        th2 = th1 + q2
        s1, c1, s2, c2 = math.sin(th1), math.cos(th1), math.sin(th2), math.cos(th2)
        det = L1 * L2 * (c1 * s2 - s1 * c2)
        vx, vy, ax, ay = sd * ux, sd * uy, sdd * ux, sdd * uy
        # J = [[-L1 s1, -L2 s2], [L1 c1, L2 c2]]
        w1 = (L2 * c2 * vx + L2 * s2 * vy) / det
        w2 = (-L1 * c1 * vx - L1 * s1 * vy) / det
        bx = ax + L1 * c1 * w1 ** 2 + L2 * c2 * w2 ** 2
        by = ay + L1 * s1 * w1 ** 2 + L2 * s2 * w2 ** 2
        a1 = (L2 * c2 * bx + L2 * s2 * by) / det
        a2 = (-L1 * c1 * bx - L1 * s1 * by) / det
        cd, sdl = math.cos(th2 - th1), math.sin(th2 - th1)
        Q1 = J1 * a1 + H * cd * a2 - H * sdl * w2 ** 2
        Q2 = H * cd * a1 + J2 * a2 + H * sdl * w1 ** 2
        M2, M1 = Q2, Q1 + Q2
        p = abs(M1 * w1) + abs(M2 * (w2 - w1))
        total += p * (0.5 if k in (0, n - 1) else 1.0)
    return total * dt


def clearance(xs, phi, L):
    ux, uy = math.cos(phi), math.sin(phi)
    sstar = min(max(-xs * ux, 0.0), L)
    rmin = math.hypot(xs + sstar * ux, sstar * uy)
    rmax = max(xs, math.hypot(xs + L * ux, L * uy))
    return rmin - INNER, OUTER - rmax


def main():
    frac = float(sys.argv[1]) if len(sys.argv) > 1 else 0.5
    prog_name = sys.argv[2] if len(sys.argv) > 2 else "cycloidal"
    config = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    margin = float(sys.argv[4]) if len(sys.argv) > 4 else 0.01
    n = int(sys.argv[5]) if len(sys.argv) > 5 else 401
    T, L = 1.0, frac * LMAX
    prog = program(prog_name, T, L, n)
    coarse = program(prog_name, T, L, 101)

    def admissible(xs, phi):
        if xs <= 0:
            return False
        a, b = clearance(xs, phi, L)
        return min(a, b) >= margin - 1e-12

    # coarse global scan among admissible lines
    best = (math.inf, None, None)
    for i in range(61):
        xs = INNER + (OUTER - INNER) * i / 60
        for j in range(181):
            phi = math.pi * j / 180
            if admissible(xs, phi):
                e = energy(coarse, T, xs, phi, config)
                if e < best[0]:
                    best = (e, xs, phi)
    print(f"coarse global scan (101 samples): {best[0]:.6f} J at x_s = {best[1]:.4f} m, phi = {math.degrees(best[2]):.2f} deg")

    # families of boundary lines, each x_s(phi); None where the family does not exist
    ri, ro = INNER + margin, OUTER - margin

    def tangent_inner(phi):
        sp = math.sin(phi)
        if sp <= 1e-12:
            return None
        xs = ri / sp
        return xs if 0 <= -xs * math.cos(phi) <= L else None

    def end_on(radius, sign):
        def f(phi):
            d = radius ** 2 - (L * math.sin(phi)) ** 2
            if d < 0:
                return None
            xs = -L * math.cos(phi) + sign * math.sqrt(d)
            return xs if xs > 0 else None
        return f

    families = {"tangent to the inner circle + margin": tangent_inner,
                "start on the inner circle + margin": lambda phi: ri,
                "end on the inner circle + margin (+)": end_on(ri, 1),
                "end on the inner circle + margin (-)": end_on(ri, -1),
                "start on the outer circle - margin": lambda phi: ro,
                "end on the outer circle - margin (+)": end_on(ro, 1),
                "end on the outer circle - margin (-)": end_on(ro, -1)}

    def on_family(f, phi):
        xs = f(phi)
        if xs is None or not admissible(xs, phi):
            return math.inf, xs
        return energy(prog, T, xs, phi, config), xs

    results = []
    for name, f in families.items():
        m = 1500
        scan = [(on_family(f, math.pi * j / m), math.pi * j / m) for j in range(m + 1)]
        (e0, xs0), phi0 = min(scan, key=lambda t: t[0][0])
        if not math.isfinite(e0):
            continue
        a, b = phi0 - math.pi / m, phi0 + math.pi / m
        g = (math.sqrt(5) - 1) / 2
        c, d = b - g * (b - a), a + g * (b - a)
        fc, fd = on_family(f, c)[0], on_family(f, d)[0]
        while b - a > 1e-11:
            if fc <= fd:
                b, d, fd = d, c, fc
                c = b - g * (b - a)
                fc = on_family(f, c)[0]
            else:
                a, c, fc = c, d, fd
                d = a + g * (b - a)
                fd = on_family(f, d)[0]
        phi = 0.5 * (a + b)
        e, xs = on_family(f, phi)
        results.append((e, xs, phi, name))
        print(f"  {name}: {e:.9f} J at x_s = {xs:.7f} m, phi = {math.degrees(phi):.6f} deg")
    e, xs, phi, name = min(results)
    print(f"least energy on the boundary of the admissible set ({n} samples): {e:.9f} J, {name}, "
          f"x_s = {xs:.7f} m, phi = {math.degrees(phi):.6f} deg")
    # is the optimum on the boundary? moving inward from it must cost energy
    step = 1e-4
    inward = []
    for dx in (-step, step):
        for dp in (-step, step):
            if admissible(xs + dx, phi + dp):
                inward.append(energy(prog, T, xs + dx, phi + dp, config))
    print(f"admissible neighbours at 1e-4: min {min(inward):.9f} J (>= the boundary optimum: "
          f"{min(inward) >= e})" if inward else "no admissible neighbour")
    fine = program(prog_name, T, L, 2 * (n - 1) + 1)
    e2 = energy(fine, T, xs, phi, config)
    print(f"same line at {2 * (n - 1) + 1} samples: {e2:.9f} J (relative change {abs(e2 - e) / e2:.2e})")


if __name__ == "__main__":
    main()
