// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Actuator power and energy along sampled motions.

#include <span>

#include "core/types.hpp"

namespace armstudy::core {

/// Absolute actuator power sum_i |tau_i qd_i| on relative joint angles, W: the integrand
/// of the no-regeneration energy of Kopmaz (2016) Ch. 8.
inline double absolute_power(const JointVector& tau, const JointVector& qd) {
  return (tau.array() * qd.array()).abs().sum();
}

/// Signed actuator power sum_i tau_i qd_i, W: its integral is the change of kinetic plus
/// potential energy (work-energy theorem).
inline double signed_power(const JointVector& tau, const JointVector& qd) { return tau.dot(qd); }

/// Trapezoidal integral of samples y over times t (same size, t increasing).
double integrate_trapezoid(std::span<const double> t, std::span<const double> y);

/// Simpson's integral of samples y on a uniform grid of step h (odd sample count;
/// falls back to the trapezoid rule for an even count).
double integrate_simpson(std::span<const double> y, double h);

}  // namespace armstudy::core
