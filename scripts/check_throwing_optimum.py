#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
"""Independent re-simulation of a throwing answer: pure Python 3 standard library, no code
shared with armstudy.

Model (docs/derivations/throwing.md, written out again here): the planar tray arm with
RELATIVE joint angles theta1..theta4 (link 1, link 2, the passive tray, the ball on its
circle). The script writes only the POSITIONS of the bodies' centres of mass and their
ABSOLUTE angles as functions of q:

    link 1  r1 e1                               angle theta1
    link 2  l1 e1 + r2 e12                      angle theta1 + theta2
    tray    l1 e1 + l2 e12 + r3 e123 + r3' e123^perp     angle theta1 + theta2 + theta3
    ball    l1 e1 + l2 e12 + d e123 + r4 e1234  spin angle theta1 + theta2 + theta3
                                                - (r4 / r_b) theta4 (rolling without slip)
    rotors  angle B q (B = [1 0 0 0; 0 1 0 0], or [1 0 0 0; 1 1 0 0] with motor 2 on the base)

Everything else is derived numerically from those functions (a Lagrangian formulation, not
armstudy's Jacobian-derivative one):
- Jacobians by the complex step (exact to rounding): J[:, j] = Im p(q + i h e_j) / h;
- the mass matrix M(q) = sum m J^T J + I w^T w (+ the rotors);
- the velocity-product terms from the Christoffel symbols of M: c_i = sum_jk (dM_ij/dq_k
  - 1/2 dM_jk/dq_i) q'_j q'_k, with dM/dq by a fourth-order central difference (h = 1e-3);
- gravity G = dU/dq, U = g sum m y, by the complex step.
Joints 1 and 2 follow the node profile (rate linear in each stage); joints 3 and 4 are
passive (no torque, no joint friction): M_PP q_P'' = -(c + G)_P - M_PA q_A''; the driving
torques Q_A = M_AA q_A'' + M_AP q_P'' + (c + G)_A. Motor torques tau = B^-T Q_A; each motor
i = (tau + Dm w + tau_f sgn w) / kt (the rotor inertia is already in M), e = Ra i + kv w,
power e i; the energy integral of e i (signed unless count_regeneration is false) is a fifth
state. The ball's centre acceleration a = J4 q'' + d/ds[J4(q + s q') q'] (directional complex
step, then a central difference in s) gives N = m4 (g - a).n and F_t = m4 (a - g).t
(docs/throwing.md); the ball's spin equation I_Gb omega_b' = r_b F_t is checked beside it.

Integration: Dormand-Prince 5(4) with its own step control (rtol 1e-10, atol 1e-12), stepping
exactly to every stage boundary, to every zero of a motor rate (where sgn w jumps) and to a
0.25 ms sampling grid; every quantity is sampled at each step end, and at every breakpoint on
both sides. A second integration at rtol 1e-12 estimates the integration error.

It prints armstudy's values (results.json, the answer's motion) beside the independent ones
and each limit's margin by the independent model; exit 0 when the energies agree within
1e-3 (relative) and every limit is met (the optimisers' 2 % back-off is their target, not a
limit), else 1.

usage: check_throwing_optimum.py OUTPUT_DIR [rtol]
  OUTPUT_DIR: a case's folder from `armstudy run` (the one holding results.json) or the run's
  --out folder holding one case folder.
"""
import cmath
import json
import math
import os
import sys
import time

CSTEP = 1e-30   # complex step
DSTEP = 1e-3    # fourth-order central difference step for dM/dq


class Model:
    def __init__(self, par):
        l1, l2 = par["link1"], par["link2"]
        tr, ball, mo = par["tray"], par["ball"], par["motors"]
        self.g = par["gravity_m_s2"]
        self.l1, self.m1, self.r1, self.I1 = l1["length_m"], l1["mass_kg"], l1["com_m"], l1["inertia_kg_m2"]
        self.l2, self.m2, self.r2, self.I2 = l2["length_m"], l2["mass_kg"], l2["com_m"], l2["inertia_kg_m2"]
        self.d, self.m3, self.r3 = tr["circle_offset_m"], tr["mass_kg"], tr["com_m"]
        self.r3l, self.I3 = tr.get("com_lateral_m", 0.0), tr["inertia_kg_m2"]
        self.m4, self.r4, self.rb = ball["mass_kg"], ball["circle_radius_m"], ball["radius_m"]
        self.Ib = ball.get("inertia_kg_m2")
        if self.Ib is None:
            self.Ib = 0.4 * self.m4 * self.rb ** 2
        self.kt, self.kv, self.Ra = mo["kt_Nm_per_A"], mo["kv_V_s_per_rad"], mo["resistance_ohm"]
        self.Dm, self.tf_c, self.Im = mo["viscous_Nm_s_per_rad"], mo["coulomb_Nm"], mo.get("rotor_inertia_kg_m2", 0.0)
        self.on_base = mo.get("motor2", "on_link1") == "on_base"
        self.regen = mo.get("count_regeneration", True)
        # rows of B: motor rates w = B q'
        self.B = [[1.0, 0.0, 0.0, 0.0], [1.0, 1.0, 0.0, 0.0] if self.on_base else [0.0, 1.0, 0.0, 0.0]]

    # -- the only geometry: centres of mass and absolute angles (works on complex q) --
    def bodies(self, q):
        """[(mass, inertia, x, y, angle)] of link 1, link 2, tray, ball (point mass + spin)."""
        a1 = q[0]
        a2 = a1 + q[1]
        a3 = a2 + q[2]
        a4 = a3 + q[3]
        c1, s1 = cmath.cos(a1), cmath.sin(a1)
        c2, s2 = cmath.cos(a2), cmath.sin(a2)
        c3, s3 = cmath.cos(a3), cmath.sin(a3)
        c4, s4 = cmath.cos(a4), cmath.sin(a4)
        x1, y1 = self.r1 * c1, self.r1 * s1
        e2x, e2y = self.l1 * c1, self.l1 * s1            # elbow
        x2, y2 = e2x + self.r2 * c2, e2y + self.r2 * s2
        hx, hy = e2x + self.l2 * c2, e2y + self.l2 * s2  # tray hinge
        x3 = hx + self.r3 * c3 - self.r3l * s3
        y3 = hy + self.r3 * s3 + self.r3l * c3
        x4 = hx + self.d * c3 + self.r4 * c4
        y4 = hy + self.d * s3 + self.r4 * s4
        spin = a3 - (self.r4 / self.rb) * q[3]
        return [(self.m1, self.I1, x1, y1, a1), (self.m2, self.I2, x2, y2, a2),
                (self.m3, self.I3, x3, y3, a3), (self.m4, self.Ib, x4, y4, spin)]

    def rotor_angles(self, q):
        return [sum(b * qi for b, qi in zip(row, q)) for row in self.B]

    def jacobians(self, q):
        """per body: (m, I, Jx[4], Jy[4], Jw[4]); rotors: Jw rows. Complex step."""
        cols = []
        for j in range(4):
            qc = [complex(v) for v in q]
            qc[j] += 1j * CSTEP
            cols.append(([(b[2].imag / CSTEP, b[3].imag / CSTEP, b[4].imag / CSTEP) for b in self.bodies(qc)],
                         [r.imag / CSTEP for r in self.rotor_angles(qc)]))
        bods = self.bodies(q)
        out = []
        for bi, b in enumerate(bods):
            out.append((b[0].real if isinstance(b[0], complex) else b[0], b[1],
                        [cols[j][0][bi][0] for j in range(4)],
                        [cols[j][0][bi][1] for j in range(4)],
                        [cols[j][0][bi][2] for j in range(4)]))
        rot = [[cols[j][1][m] for j in range(4)] for m in range(2)]
        return out, rot

    def mass_matrix(self, q):
        bods, rot = self.jacobians(q)
        M = [[0.0] * 4 for _ in range(4)]
        for m, I, Jx, Jy, Jw in bods:
            for i in range(4):
                Mi = M[i]
                for j in range(4):
                    Mi[j] += m * (Jx[i] * Jx[j] + Jy[i] * Jy[j]) + I * Jw[i] * Jw[j]
        if self.Im:
            for w in rot:
                for i in range(4):
                    for j in range(4):
                        M[i][j] += self.Im * w[i] * w[j]
        return M

    def potential(self, q):
        return self.g * sum(b[0] * b[3] for b in self.bodies(q))

    def gravity(self, q):
        G = []
        for j in range(4):
            qc = [complex(v) for v in q]
            qc[j] += 1j * CSTEP
            G.append(self.potential(qc).imag / CSTEP)
        return G

    def dM(self, q):
        """dM/dq_k, k = 0..3, by the fourth-order central difference."""
        out = []
        for k in range(4):
            Ms = []
            for s in (2, 1, -1, -2):
                qs = list(q)
                qs[k] += s * DSTEP
                Ms.append(self.mass_matrix(qs))
            out.append([[(-Ms[0][i][j] + 8 * Ms[1][i][j] - 8 * Ms[2][i][j] + Ms[3][i][j]) / (12 * DSTEP)
                         for j in range(4)] for i in range(4)])
        return out

    def bias(self, q, qd):
        """c(q, q') + G(q) and M(q)."""
        M = self.mass_matrix(q)
        D = self.dM(q)
        G = self.gravity(q)
        h = []
        for i in range(4):
            s = 0.0
            for j in range(4):
                for k in range(4):
                    s += (D[k][i][j] - 0.5 * D[i][j][k]) * qd[j] * qd[k]
            h.append(s + G[i])
        return M, h

    def ball_point(self, q):
        b = self.bodies(q)[3]
        return b[2], b[3]

    def ball_accel(self, q, qd, qdd):
        # J4 q'' and J4 q' by complex steps along a direction
        def dirderiv(q0, v):
            qc = [complex(a) + 1j * CSTEP * b for a, b in zip(q0, v)]
            x, y = self.ball_point(qc)
            return x.imag / CSTEP, y.imag / CSTEP
        ax, ay = dirderiv(q, qdd)
        vn = max(abs(v) for v in qd)
        if vn > 0:
            s = DSTEP / vn
            vals = []
            for k in (2, 1, -1, -2):
                vals.append(dirderiv([a + k * s * b for a, b in zip(q, qd)], qd))
            ax += (-vals[0][0] + 8 * vals[1][0] - 8 * vals[2][0] + vals[3][0]) / (12 * s)
            ay += (-vals[0][1] + 8 * vals[1][1] - 8 * vals[2][1] + vals[3][1]) / (12 * s)
        return ax, ay


class Profile:
    """Joints 1, 2: rates linear between the nodes (t_k, v_k); angles from the start angles."""

    def __init__(self, t, v, q0):
        self.t, self.v = t, v
        self.P = len(t) - 1
        self.acc = [[(v[k + 1][j] - v[k][j]) / (t[k + 1] - t[k]) for j in range(2)] for k in range(self.P)]
        self.q = [list(q0)]
        for k in range(self.P):
            h = t[k + 1] - t[k]
            self.q.append([self.q[k][j] + h * v[k][j] + 0.5 * self.acc[k][j] * h * h for j in range(2)])

    def at(self, t, k):
        tau = t - self.t[k]
        a = self.acc[k]
        return ([self.q[k][j] + self.v[k][j] * tau + 0.5 * a[j] * tau * tau for j in range(2)],
                [self.v[k][j] + a[j] * tau for j in range(2)], list(a))


def sgn(x):
    return (x > 0) - (x < 0)


class Sim:
    def __init__(self, model, prof, q30, q40):
        self.m, self.p = model, prof
        self.y0 = [q30, q40, 0.0, 0.0, 0.0]

    def point(self, t, y, k, signs):
        """all quantities at (t, y) in stage k with the motor friction signs of the interval."""
        m = self.m
        qa, qda, qdda = self.p.at(t, k)
        q = [qa[0], qa[1], y[0], y[1]]
        qd = [qda[0], qda[1], y[2], y[3]]
        M, h = m.bias(q, qd)
        # passive accelerations: M_PP x = -h_P - M_PA qdd_A
        r0 = -h[2] - M[2][0] * qdda[0] - M[2][1] * qdda[1]
        r1 = -h[3] - M[3][0] * qdda[0] - M[3][1] * qdda[1]
        a, b, c, d = M[2][2], M[2][3], M[3][2], M[3][3]
        det = a * d - b * c
        x3 = (d * r0 - b * r1) / det
        x4 = (a * r1 - c * r0) / det
        qdd = [qdda[0], qdda[1], x3, x4]
        Q = [sum(M[i][j] * qdd[j] for j in range(4)) + h[i] for i in range(2)]
        tau = [Q[0] - Q[1], Q[1]] if m.on_base else [Q[0], Q[1]]
        w = [sum(m.B[r][j] * qd[j] for j in range(4)) for r in range(2)]
        cur, volt, powr = [], [], []
        for j in range(2):
            i = (tau[j] + m.Dm * w[j] + m.tf_c * signs[j]) / m.kt
            e = m.Ra * i + m.kv * w[j]
            cur.append(i)
            volt.append(e)
            powr.append(e * i)
        dE = sum(powr) if m.regen else sum(max(0.0, pw) for pw in powr)
        return {"q": q, "qd": qd, "qdd": qdd, "Q": Q, "tau": tau, "i": cur, "e": volt, "p": powr,
                "dy": [y[2], y[3], x3, x4, dE]}

    def forces(self, pt):
        m = self.m
        q, qd, qdd = pt["q"], pt["qd"], pt["qdd"]
        ax, ay = m.ball_accel(q, qd, qdd)
        phi = q[0] + q[1] + q[2] + q[3]
        nx, ny = math.cos(phi), math.sin(phi)
        tx, ty = -ny, nx
        gx, gy = 0.0, -m.g
        N = m.m4 * ((gx - ax) * nx + (gy - ay) * ny)
        Ft = m.m4 * ((ax - gx) * tx + (ay - gy) * ty)
        # second route: the ball's spin, I_Gb omega_b' = r_b F_t
        wbd = qdd[0] + qdd[1] + qdd[2] - (m.r4 / m.rb) * qdd[3]
        Ft_spin = m.Ib * wbd / m.rb
        return N, Ft, Ft_spin


# Dormand-Prince 5(4)
C = [0.0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1.0, 1.0]
A = [[], [1 / 5], [3 / 40, 9 / 40], [44 / 45, -56 / 15, 32 / 9],
     [19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729],
     [9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656],
     [35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84]]
BH = A[6]
BS = [5179 / 57600, 0.0, 7571 / 16695, 393 / 640, -92097 / 339200, 187 / 2100, 1 / 40]
ERR = [b - s for b, s in zip(BH + [0.0], BS)]


def integrate(sim, rtol, atol, sample_dt, on_sample):
    """DOPRI5 over the whole motion; on_sample(t, point, k, signs) at every step end and at both
    sides of every breakpoint. Returns the final state and statistics."""
    prof = sim.p
    y = list(sim.y0)
    nsteps = nrej = nfev = 0
    stage_states = [list(y)]
    hstep = 1e-5
    for k in range(prof.P):
        t0, t1 = prof.t[k], prof.t[k + 1]
        # breakpoints inside the stage: zeros of the motor rates (rates linear in t)
        bps = {t0, t1}
        n = max(1, int(round((t1 - t0) / sample_dt)))
        for s in range(1, n):
            bps.add(t0 + (t1 - t0) * s / n)
        for r in range(2):
            row = sim.m.B[r]
            w0 = row[0] * prof.v[k][0] + row[1] * prof.v[k][1]
            w1 = row[0] * prof.v[k + 1][0] + row[1] * prof.v[k + 1][1]
            if w0 * w1 < 0:
                bps.add(t0 + (t1 - t0) * w0 / (w0 - w1))
        grid = sorted(bps)
        for ta, tb in zip(grid[:-1], grid[1:]):
            if tb - ta < 1e-15:
                continue
            tm = 0.5 * (ta + tb)
            _, wa, _ = prof.at(tm, k)
            signs = [sgn(sim.m.B[r][0] * wa[0] + sim.m.B[r][1] * wa[1]) for r in range(2)]
            t = ta
            pt = sim.point(t, y, k, signs)
            nfev += 1
            on_sample(t, pt, k, signs)
            f0 = pt["dy"]
            while t < tb:
                hh = min(hstep, tb - t)
                last = tb - t <= hh * (1 + 1e-12)
                if last:
                    hh = tb - t
                ks = [f0]
                for s in range(1, 7):
                    ys = [y[i] + hh * sum(A[s][j] * ks[j][i] for j in range(s)) for i in range(5)]
                    ts = tb if (s >= 5 and last) else t + C[s] * hh
                    ptx = sim.point(ts, ys, k, signs)
                    nfev += 1
                    ks.append(ptx["dy"])
                ynew = ys  # stage 7 is the 5th-order solution (FSAL)
                errn = 0.0
                for i in range(5):
                    sc = atol + rtol * max(abs(y[i]), abs(ynew[i]))
                    ei = hh * sum(ERR[j] * ks[j][i] for j in range(7))
                    errn += (ei / sc) ** 2
                errn = math.sqrt(errn / 5)
                if errn <= 1.0:
                    t = tb if last else t + hh
                    y = ynew
                    f0 = ptx["dy"]
                    nsteps += 1
                    on_sample(t, ptx, k, signs)
                    fac = 5.0 if errn == 0 else min(5.0, max(0.2, 0.9 * errn ** -0.2))
                    if not last:
                        hstep = hh * fac
                    else:
                        hstep = max(hstep, hh * fac) if hh < hstep else hh * fac
                else:
                    nrej += 1
                    hstep = hh * max(0.2, 0.9 * errn ** -0.2)
        stage_states.append(list(y))
    return y, stage_states, nsteps, nrej, nfev


def run(model, prof, q30, q40, rtol, sample_dt, want_samples, mu=0.5):
    sim = Sim(model, prof, q30, q40)
    ex = {"Nmin": math.inf, "ratio": 0.0, "fric_excess": -math.inf, "th4": 0.0, "V": 0.0, "I": 0.0,
          "P": 0.0, "Ft_spin_diff": 0.0, "samples": 0, "dt_max": 0.0, "last_t": 0.0}

    def on_sample(t, pt, k, signs):
        ex["samples"] += 1
        ex["dt_max"] = max(ex["dt_max"], t - ex["last_t"])
        ex["last_t"] = t
        if not want_samples:
            return
        N, Ft, Ft2 = sim.forces(pt)
        ex["Nmin"] = min(ex["Nmin"], N)
        ex["ratio"] = max(ex["ratio"], abs(Ft) / N if N > 0 else math.inf)
        ex["fric_excess"] = max(ex["fric_excess"], abs(Ft) - mu * N)
        ex["Ft_spin_diff"] = max(ex["Ft_spin_diff"], abs(Ft - Ft2))
        ex["th4"] = max(ex["th4"], abs(pt["q"][3]))
        ex["V"] = max(ex["V"], max(abs(v) for v in pt["e"]))
        ex["I"] = max(ex["I"], max(abs(v) for v in pt["i"]))
        ex["P"] = max(ex["P"], max(abs(v) for v in pt["p"]))

    y, stages, nsteps, nrej, nfev = integrate(sim, rtol, 1e-12, sample_dt, on_sample)
    ex.update({"y": y, "stages": stages, "steps": nsteps, "rejected": nrej, "fev": nfev})
    return ex


def find_results(path):
    if os.path.isfile(path):
        return path
    if os.path.isfile(os.path.join(path, "results.json")):
        return os.path.join(path, "results.json")
    subs = [os.path.join(path, d, "results.json") for d in sorted(os.listdir(path))
            if os.path.isfile(os.path.join(path, d, "results.json"))]
    if len(subs) != 1:
        sys.exit(f"no single results.json under {path}: {subs}")
    return subs[0]


def main():
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(sys.argv) >= 2 else 2
    rtol = float(sys.argv[2]) if len(sys.argv) > 2 else 1e-10
    wall = time.time()
    fn = find_results(sys.argv[1])
    th = json.load(open(fn))["throwing"]
    par, lim = th["parameters"], th["limits"]
    answer = th.get("answer")
    mot = th["nlopt"]["motion"] if answer == "slsqp" else th["optimum"]
    prof_json = mot["profile"]
    model = Model(par)
    mu = lim["friction_coefficient"]
    task = par["task"]
    start = [math.radians(a) for a in task["start_deg"]]
    prof = Profile(prof_json["t_s"], prof_json["rate_rad_s"], start[:2])
    print(f"{fn}: answer {answer!r}, {prof.P} stages, motor 2 "
          f"{'on the base' if model.on_base else 'on link 1'}, rotor inertia {model.Im:g} kg m^2, "
          f"regeneration {'counted' if model.regen else 'not counted'}")

    sample_dt = 0.25e-3
    ex = run(model, prof, start[2], start[3], rtol, sample_dt, True, mu)
    fine = run(model, prof, start[2], start[3], rtol * 1e-2, sample_dt, False)
    E, Ef = ex["y"][4], fine["y"][4]
    th3 = ex["y"][0]
    print(f"DOPRI5 rtol {rtol:g}: {ex['steps']} steps ({ex['rejected']} rejected), "
          f"{ex['samples']} samples, largest gap {ex['dt_max'] * 1e3:.3f} ms; rtol {rtol * 1e-2:g}: "
          f"energy differs by {abs(E - Ef):.2e} J, theta3(tf) by {abs(th3 - fine['y'][0]):.2e} rad")
    print(f"ball's tangential force, Newton vs spin equation: largest difference {ex['Ft_spin_diff']:.2e} N")
    # joints 1, 2 at tf against the release pose
    qa, qda, _ = prof.at(prof.t[-1], prof.P - 1)
    rel = [math.radians(a) for a in task["release_deg"]]
    print(f"joints 1, 2 at tf: angle error {qa[0] - rel[0]:.1e}, {qa[1] - rel[1]:.1e} rad, rate error "
          f"{qda[0] - task['release_rate_rad_s'][0]:.1e}, {qda[1] - task['release_rate_rad_s'][1]:.1e} rad/s")
    # trajectory against armstudy's recorded samples at the stage ends
    ser = mot.get("series", {})
    if ser.get("t_s"):
        worst = [0.0, 0.0]
        for k in range(1, prof.P + 1):
            tk = prof.t[k]
            idx = max(i for i, t in enumerate(ser["t_s"]) if abs(t - tk) < 1e-9)
            for j in range(2):
                worst[j] = max(worst[j], abs(ser["q_rad"][idx][2 + j] - ex["stages"][k][j]))
        print(f"theta3, theta4 at the stage ends vs armstudy's series: largest difference "
              f"{worst[0]:.2e}, {worst[1]:.2e} rad")

    tol = lim["release_tolerance_rad"]
    th4lim = lim["theta4_limit_rad"][1]
    a_th3 = ser["q_rad"][-1][2] if ser.get("q_rad") else None
    m4g = model.m4 * model.g
    rows = [
        # name, armstudy, independent, limit text, margin (>= 0 is met), normalised g
        ("energy_J", mot["energy_J"], E, "", None, None),
        ("min_normal_force_N", mot["min_normal_force_N"], ex["Nmin"], f">= {lim['contact_margin_N']:g}",
         ex["Nmin"] - lim["contact_margin_N"], (lim["contact_margin_N"] - ex["Nmin"]) / m4g),
        ("max_friction_ratio", mot["max_friction_ratio"], ex["ratio"], f"<= {mu:g}", mu - ex["ratio"],
         ex["fric_excess"] / m4g),
        ("max_abs_theta4_rad", mot["max_abs_theta4_rad"], ex["th4"], f"<= {th4lim:.6g}", th4lim - ex["th4"],
         (ex["th4"] - th4lim) / th4lim),
        ("max_voltage_V", mot["max_voltage_V"], ex["V"], f"<= {lim['voltage_max_V']:g}",
         lim["voltage_max_V"] - ex["V"], (ex["V"] - lim["voltage_max_V"]) / lim["voltage_max_V"]),
        ("max_current_A", mot["max_current_A"], ex["I"], f"<= {lim['current_max_A']:g}",
         lim["current_max_A"] - ex["I"], (ex["I"] - lim["current_max_A"]) / lim["current_max_A"]),
        ("max_power_W", mot["max_power_W"], ex["P"], f"<= {lim['power_max_W']:g}",
         lim["power_max_W"] - ex["P"], (ex["P"] - lim["power_max_W"]) / lim["power_max_W"]),
        ("theta3_tf_rad", a_th3, th3, f"{rel[2]:.6g} +- {tol:.4g}", tol - abs(th3 - rel[2]),
         (abs(th3 - rel[2]) - tol) / tol),
    ]
    print()
    print(f"{'quantity':<20} {'armstudy':>13} {'independent':>13} {'rel diff':>10} {'abs diff':>10}  "
          f"{'limit':<20} {'margin':>11} {'g (<=0)':>8}  status")
    ok = True
    for name, a, b, limtxt, margin, gval in rows:
        if a is None:
            rd = ad = "-"
            atxt = "-"
        else:
            ad_v = b - a
            rd = f"{ad_v / abs(a):.2e}" if a != 0 else "-"
            ad = f"{ad_v:.2e}"
            atxt = f"{a:.8g}"
        if margin is None:
            status = "agree" if abs(b - a) <= 1e-3 * abs(a) else "DISAGREE"
            ok &= status == "agree"
            mtxt = gtxt = ""
        else:
            status = "met" if margin >= 0 else "BROKEN"
            ok &= margin >= 0
            mtxt, gtxt = f"{margin:.4g}", f"{gval:.4f}"
        print(f"{name:<20} {atxt:>13} {b:>13.8g} {rd:>10} {ad:>10}  {limtxt:<20} {mtxt:>11} {gtxt:>8}  {status}")
    print()
    print(f"energy relative difference {abs(E - mot['energy_J']) / abs(mot['energy_J']):.2e} "
          f"(tolerance 1e-3); every limit met by the independent model: "
          f"{all(r[4] is None or r[4] >= 0 for r in rows)}")
    print(f"run time {time.time() - wall:.1f} s")
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
