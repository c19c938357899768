// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Exact derivatives of the throw's energy and constraint values with respect to the
/// interior node rates (SLSQP's variables, nlopt_solve.hpp), by forward sensitivities of the
/// discrete RK4 simulation.
///
/// The passive state x = (theta3, theta4, theta3', theta4', energy) is small and the
/// parameters are many, and the active joints' angles, rates and accelerations are linear
/// in the node rates (profile.hpp). So the simulation carries S = dx/dp (5 x n) along: at
/// every right-hand-side evaluation of an RK4 step the local Jacobian of the right-hand side
/// with respect to its 10 inputs (the four joint angles and rates, the two active
/// accelerations) comes from the same physics instantiated with Eigen's AutoDiffScalar
/// (tray_dynamics_impl.hpp, core::motor_electrics), and the step's own map is
/// differentiated exactly: dk_i = J_i (dz_i/dp), where z_i's passive part is
/// S + c_i dt dk_(i-1) and its active part the profile's (known) derivative, and
/// S' = S + dt/6 (dk_1 + 2 dk_2 + 2 dk_3 + dk_4). The values are those of simulate_profile
/// (the same operations on the value parts; the test holds them equal bit for bit), and the
/// derivatives are those of that discrete map, not of the continuous ODE.
///
/// A stage's constraint is the worst of its samples; its derivative is that of the sample
/// that is the worst (the first one, on a tie, as the simulation's running maximum keeps it),
/// which is what central differences of the simulation approximate. It is not differentiable
/// where two samples tie; there it is one of the one-sided derivatives.

#include <vector>

#include <Eigen/Dense>

#include "studies/throwing/profile.hpp"
#include "studies/throwing/simulate.hpp"

namespace armstudy::studies {

/// The values and exact derivatives of one profile.
struct ThrowDerivatives {
  ProfileEvaluation evaluation;     ///< simulate_profile(setup, profile, nullptr, backoff)'s
  std::vector<double> constraints;  ///< constraint_values(setup, evaluation, backoff), 6P + 1
  /// d energy / d p, p the interior node rates: node k's rate of joint j at 2 (k - 1) + j
  Eigen::VectorXd energy_gradient;
  Eigen::MatrixXd constraint_jacobian;  ///< (6P + 1) x n, rows as `constraints`
  /// (per_sample only) the stage constraints sample by sample, smooth where the stage maxima
  /// are kinked: kSampleRows rows per RK4 sample (the samples the stage maxima run over, in
  /// time order), normalised and backed off as constraint_values; the release row is not here
  std::vector<double> sample_constraints;
  Eigen::MatrixXd sample_jacobian;  ///< rows as sample_constraints
  std::vector<int> sample_stage;    ///< the stage of each sample (one entry per sample)
};

/// Rows per sample of ThrowDerivatives::sample_constraints: contact, friction, tray angle,
/// then voltage, current and power of motor 1 and of motor 2 (each its |value|).
inline constexpr int kSampleRows = 9;

/// Can throw_derivatives differentiate `setup`'s simulations: the tray arm's 4-joint chain
/// with joints 1, 2 active and 3, 4 passive (kernel_applies's chain)?
bool derivatives_apply(const ThrowSetup& setup);

/// Simulates `profile` (as simulate_profile(setup, profile, nullptr, backoff)) with its
/// forward sensitivities. A simulation that is not finite gives zero derivatives.
/// @throws std::invalid_argument unless derivatives_apply(setup) and P >= 2.
/// per_sample: also the constraints sample by sample (ThrowDerivatives::sample_constraints).
ThrowDerivatives throw_derivatives(const ThrowSetup& setup, const VelocityProfile& profile,
                                   double backoff = 0.0, bool per_sample = false);

}  // namespace armstudy::studies
