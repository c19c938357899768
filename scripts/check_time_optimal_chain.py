#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
"""Independent check of the time-optimal duration of reports/cases/time-optimal-3link.yaml:
pure Python, no code shared with armstudy. The path is the case's natural cubic spline in
joint space (chord-length knots; the duration does not depend on how the curve is
parameterised); the dynamics are written out for a planar chain of uniform rods with a tip
payload (every body's centre-of-mass acceleration summed through its Jacobian, no mass
matrix code from armstudy); the fastest motion comes from the classic numerical
integration of the phase-plane bounds (Bobrow, Dubowsky and Gibson 1985): at every point
of a fine grid the largest and smallest path acceleration s'' the torque limits allow at
s'^2 = x, the maximum velocity curve (largest x with some s'' allowed, bisection, and the
velocity limits), then a forward pass at the largest s'' and a backward pass at the
smallest, clipped by that curve; the profile is the smaller of the two. Duration:
sum 2 ds / (s'_k + s'_k+1).

usage: check_time_optimal_chain.py [grid points] [results.json to compare with]
defaults: 20001 points; without a results.json it prints the duration only."""
import json
import math
import sys

# the case (reports/cases/time-optimal-3link.yaml)
LENGTHS = [0.40, 0.35, 0.25]
MASSES = [3.0, 2.0, 1.0]
PAYLOAD = 0.5
G = 9.81
WAYPOINTS = [[-2.30, 0.50, 0.40], [-1.90, 0.20, 0.30], [-1.20, -0.20, -0.10], [-0.80, -0.50, -0.40]]
VMAX = [2.5, 3.0, 4.0]
TMAX = [30.0, 12.0, 3.0]
N = len(LENGTHS)


def spline(points):
    """Natural cubic spline through points (chord-length knots): returns (knots, f) with
    f(t) = (q, dq/dt, d2q/dt2)."""
    n = len(points)
    t = [0.0]
    for i in range(1, n):
        t.append(t[-1] + math.sqrt(sum((a - b) ** 2 for a, b in zip(points[i], points[i - 1]))))
    dim = len(points[0])
    # second derivatives m_i per joint: dense linear system, m_0 = m_{n-1} = 0
    m = [[0.0] * dim for _ in range(n)]
    k = n - 2
    for d in range(dim):
        A = [[0.0] * k for _ in range(k)]
        r = [0.0] * k
        for j in range(k):
            i = j + 1
            h0, h1 = t[i] - t[i - 1], t[i + 1] - t[i]
            if j > 0:
                A[j][j - 1] = h0
            A[j][j] = 2 * (h0 + h1)
            if j + 1 < k:
                A[j][j + 1] = h1
            r[j] = 6 * ((points[i + 1][d] - points[i][d]) / h1 - (points[i][d] - points[i - 1][d]) / h0)
        # Gaussian elimination with partial pivoting
        for c in range(k):
            p = max(range(c, k), key=lambda row: abs(A[row][c]))
            A[c], A[p] = A[p], A[c]
            r[c], r[p] = r[p], r[c]
            for row in range(c + 1, k):
                f = A[row][c] / A[c][c]
                for cc in range(c, k):
                    A[row][cc] -= f * A[c][cc]
                r[row] -= f * r[c]
        x = [0.0] * k
        for c in reversed(range(k)):
            x[c] = (r[c] - sum(A[c][cc] * x[cc] for cc in range(c + 1, k))) / A[c][c]
        for j in range(k):
            m[j + 1][d] = x[j]

    def f(s):
        s = min(max(s, 0.0), t[-1])
        i = 0
        while i + 2 < n and s > t[i + 1]:
            i += 1
        h = t[i + 1] - t[i]
        a, b = (t[i + 1] - s) / h, (s - t[i]) / h
        q, dq, ddq = [], [], []
        for d in range(dim):
            p0, p1, m0, m1 = points[i][d], points[i + 1][d], m[i][d], m[i + 1][d]
            q.append(a * p0 + b * p1 + ((a ** 3 - a) * m0 + (b ** 3 - b) * m1) * h * h / 6)
            dq.append((p1 - p0) / h - (3 * a * a - 1) / 6 * h * m0 + (3 * b * b - 1) / 6 * h * m1)
            ddq.append(a * m0 + b * m1)
        return q, dq, ddq

    return t, f


def bodies():
    """(link, distance along it, mass, own inertia): the rods and the payload."""
    out = [(i, LENGTHS[i] / 2, MASSES[i], MASSES[i] * LENGTHS[i] ** 2 / 12) for i in range(N)]
    out.append((N - 1, LENGTHS[-1], PAYLOAD, 0.0))
    return out


def torques(q, qd, qdd):
    """Inverse dynamics of the chain (relative angles, gravity along -y)."""
    th, w, al = [], [], []
    a = v = z = 0.0
    for i in range(N):
        a += q[i]
        v += qd[i]
        z += qdd[i]
        th.append(a)
        w.append(v)
        al.append(z)
    tau = [0.0] * N
    for link, r, mass, inertia in bodies():
        # position Jacobian of the body point and its acceleration
        jac = [[0.0, 0.0] for _ in range(N)]
        acc = [0.0, 0.0]
        for i in range(link + 1):
            length = LENGTHS[i] if i < link else r
            c, s = math.cos(th[i]), math.sin(th[i])
            # d/d q_l of length * (c, s) for l <= i: length * (-s, c)
            for l in range(i + 1):
                jac[l][0] += -length * s
                jac[l][1] += length * c
            acc[0] += length * (-s * al[i] - c * w[i] ** 2)
            acc[1] += length * (c * al[i] - s * w[i] ** 2)
        force = (mass * acc[0], mass * (acc[1] + G))
        for l in range(N):
            tau[l] += jac[l][0] * force[0] + jac[l][1] * force[1]
            if l <= link:
                tau[l] += inertia * al[link]
    return tau


def point(f, s):
    q, dq, ddq = f(s)
    zero = [0.0] * N
    c = torques(q, zero, zero)
    a = [x - y for x, y in zip(torques(q, zero, dq), c)]      # M q'
    b = [x - y for x, y in zip(torques(q, dq, ddq), c)]       # M q'' + C(q, q') q'
    return a, b, c, dq


def u_bounds(p, x):
    a, b, c, _ = p
    lo, hi = -math.inf, math.inf
    for j in range(N):
        if abs(a[j]) < 1e-15:
            if abs(b[j] * x + c[j]) > TMAX[j]:
                return math.inf, -math.inf
            continue
        u1 = (TMAX[j] - c[j] - b[j] * x) / a[j]
        u2 = (-TMAX[j] - c[j] - b[j] * x) / a[j]
        lo, hi = max(lo, min(u1, u2)), min(hi, max(u1, u2))
    return lo, hi


def mvc(p):
    _, _, _, dq = p
    xv = min(VMAX[j] ** 2 / dq[j] ** 2 for j in range(N) if abs(dq[j]) > 1e-15)
    lo_ok = u_bounds(p, 0.0)
    if lo_ok[0] > lo_ok[1]:
        return 0.0
    if u_bounds(p, xv)[0] <= u_bounds(p, xv)[1]:
        return xv
    lo, hi = 0.0, xv
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        u = u_bounds(p, mid)
        lo, hi = (mid, hi) if u[0] <= u[1] else (lo, mid)
    return lo


def duration(points_n):
    knots, f = spline(WAYPOINTS)
    length = knots[-1]
    ds = length / (points_n - 1)
    pts = [point(f, k * ds) for k in range(points_n)]
    cap = [mvc(p) for p in pts]
    fwd = [0.0] * points_n
    for k in range(points_n - 1):
        u = u_bounds(pts[k], fwd[k])[1]
        fwd[k + 1] = max(0.0, min(fwd[k] + 2 * ds * u, cap[k + 1]))
    bwd = [0.0] * points_n
    for k in range(points_n - 1, 0, -1):
        u = u_bounds(pts[k], bwd[k])[0]
        bwd[k - 1] = max(0.0, min(bwd[k] - 2 * ds * u, cap[k - 1]))
    x = [min(a, b) for a, b in zip(fwd, bwd)]
    total = 0.0
    for k in range(points_n - 1):
        total += 2 * ds / (math.sqrt(x[k]) + math.sqrt(x[k + 1]))
    return total, length


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 20001
    total, length = duration(n)
    print(f"path length {length:.6f} rad, {n} grid points: duration {total:.7f} s")
    if len(sys.argv) > 2:
        with open(sys.argv[2]) as fh:
            r = json.load(fh)
        exact = next(s for s in r["time_optimal"]["solvers"] if s["name"] == "exact")["duration_s"]
        rel = exact / total - 1
        print(f"armstudy exact {exact:.7f} s: relative difference {rel:.3e}")
        return 0 if abs(rel) < 2e-3 else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
