// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The per-sample part of evaluate_line (arm2.hpp) over a block of samples, structure of
/// arrays: arm2_sample's arithmetic, unchanged, in a loop without calls or branches that the
/// compiler vectorises. Internal to the placement study.

#include "studies/placement/arm2.hpp"

namespace armstudy::studies::placement {

/// For samples k in [0, m) of the tip motion start + s[k] dir (velocity sd[k] dir,
/// acceleration sdd[k] dir; dir = (ux, uy)) in configuration `sign` (+1 / -1): the joint
/// powers p1 = tau1 qd1, p2 = tau2 qd2 (W), |tau1|, |tau2| (N m) and |sin q2|, exactly as
/// arm2_sample computes them.
void sample_block(const Arm2& arm, const double* __restrict s, const double* __restrict sd,
                  const double* __restrict sdd, int m, double sx, double sy, double ux, double uy,
                  double sign, double* __restrict p1, double* __restrict p2, double* __restrict t1,
                  double* __restrict t2, double* __restrict s2abs);

}  // namespace armstudy::studies::placement
