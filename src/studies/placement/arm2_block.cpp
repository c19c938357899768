// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Compiled with -fno-math-errno -fno-trapping-math (CMakeLists.txt): neither changes a
// computed value (no reassociation, no contraction), they let the compiler vectorise the
// loop (sqrt without the errno branch, the clamp's selects without a branch).
#include "studies/placement/arm2_block.hpp"

#include <cmath>

namespace armstudy::studies::placement {

// an AVX build of the loop beside the baseline one, picked at load time where the CPU has
// AVX (4 lanes instead of 2; still no FMA, so the same roundings)
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
__attribute__((target_clones("avx", "default")))
#endif
void sample_block(const Arm2& arm, const double* __restrict s, const double* __restrict sd,
                  const double* __restrict sdd, int m, double sx, double sy, double ux, double uy,
                  double sign, double* __restrict p1, double* __restrict p2, double* __restrict t1,
                  double* __restrict t2, double* __restrict s2abs) {
  const double L1 = arm.L1, L2 = arm.L2;
  const double A = arm.A, B = arm.B, a11 = arm.a11, a12 = arm.a12, a22 = arm.a22;
  for (int k = 0; k < m; ++k) {
    const double px = sx + s[k] * ux, py = sy + s[k] * uy;
    const double vx = sd[k] * ux, vy = sd[k] * uy;
    const double ax = sdd[k] * ux, ay = sdd[k] * uy;
    const double r2 = px * px + py * py;
    double c2 = (r2 - L1 * L1 - L2 * L2) / (2.0 * L1 * L2);
    c2 = c2 > 1.0 ? 1.0 : c2;  // the clamp in two selects (no branch)
    c2 = c2 < -1.0 ? -1.0 : c2;
    const double s2 = sign * std::sqrt(1.0 - c2 * c2);
    const double k1 = L1 + L2 * c2, k2 = L2 * s2;
    const double inv_r2 = 1.0 / r2;
    const double c1 = (px * k1 + py * k2) * inv_r2;
    const double s1 = (py * k1 - px * k2) * inv_r2;
    const double ex = L1 * c1, ey = L1 * s1;
    const double fx = px - ex, fy = py - ey;
    const double inv_det = 1.0 / (L1 * L2 * s2);
    const double qd1 = (fx * vx + fy * vy) * inv_det;
    const double qd2 = -(px * vx + py * vy) * inv_det;
    const double w12 = qd1 + qd2;
    const double bx = ax + qd1 * qd1 * ex + w12 * w12 * fx;
    const double by = ay + qd1 * qd1 * ey + w12 * w12 * fy;
    const double qdd1 = (fx * bx + fy * by) * inv_det;
    const double qdd2 = -(px * bx + py * by) * inv_det;
    const double g = A * c2 - B * s2;
    const double gp = -A * s2 - B * c2;
    const double m11 = a11 + 2.0 * g, m12 = a12 + g, m22 = a22;
    const double tau1 = m11 * qdd1 + m12 * qdd2 + gp * (2.0 * qd1 * qd2 + qd2 * qd2);
    const double tau2 = m12 * qdd1 + m22 * qdd2 - gp * qd1 * qd1;
    p1[k] = tau1 * qd1;
    p2[k] = tau2 * qd2;
    t1[k] = std::abs(tau1);
    t2[k] = std::abs(tau2);
    s2abs[k] = std::abs(s2);
  }
}

}  // namespace armstudy::studies::placement
