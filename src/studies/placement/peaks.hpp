// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The peaks of one motion's joint torques and powers over the continuous motion, not only
/// at its samples: a torque or power limit is a limit on the motion, and a peak that sits on
/// its limit between two samples breaks it there (by ~h^2 of the peak's curvature: 2e-5
/// relative at 401 samples on a limit-bound optimum).
///
/// Method: the motion sampled at `samples` uniform instants (LinePower, the quadrature's
/// evaluator, so that a line near a boundary keeps its digits); around every sample that is
/// a local maximum of |tau_j| or |tau_j qd_j| within 1 % of that quantity's sampled maximum,
/// golden-section search for the maximum on the two sample spacings around it, to 1e-10 of
/// the duration. The peak's resolution is the spread of the last bracket's values plus 8 ulp
/// of the peak (the golden section on a smooth maximum leaves an error ~ f'' dt^2 / 2, far
/// below roundoff at that bracket).

#include "core/motion_program.hpp"
#include "studies/placement/arm2.hpp"

namespace armstudy::studies::placement {

/// The continuous peaks of one motion.
struct MotionPeaks {
  double torque[2] = {0, 0};  ///< N m, max |tau_j| over [0, T]
  double power[2] = {0, 0};   ///< W, max |tau_j qd_j| over [0, T]
  /// relative, the largest resolution of the four peaks (see above)
  double resolution = 0;
  bool finite = true;  ///< false: a sample at a singular pose (no peak)
};

/// The continuous peaks of the motion `program` (rest to rest over `length` m in `duration`
/// s) along `line` in configuration 1 or 2, refined from `samples` >= 3 uniform samples.
MotionPeaks continuous_peaks(const Arm2& arm, core::MotionProgram program, double duration,
                             double length, const Line& line, int configuration, int samples = 401);

}  // namespace armstudy::studies::placement
