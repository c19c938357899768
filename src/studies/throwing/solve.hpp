// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Solves the throwing study (spec.hpp -> result.hpp; the method: docs/throwing.md).

#include <Eigen/Dense>

#include "studies/common.hpp"
#include "studies/throwing/result.hpp"
#include "studies/throwing/spec.hpp"

namespace armstudy::studies {

/// Builds the simulation setup of a spec. @throws std::invalid_argument on bad parameters.
ThrowSetup make_throw_setup(const ThrowingSpec& spec);

/// The throw's set-up and its eq. 8 start profile; false, with r.message saying why, when the
/// spec cannot be set up. (The first step of solve_throwing and of solve_throwing_warm.)
bool prepare_throw(const ThrowingSpec& spec, ThrowSetup& setup, VelocityProfile& initial,
                   ThrowingResult& r);

/// Simulates one profile and records its series, split and release errors.
ThrowMotion record_motion(const ThrowSetup& setup, const ThrowingSpec& spec,
                          const VelocityProfile& profile);

/// Re-simulates `profile` with `refinement` x the setup's steps and checks every constraint
/// (no backoff).
Verification verify_profile(const ThrowSetup& setup, const VelocityProfile& profile,
                            int refinement);

/// Whether `e` stays at least 3/4 of `backoff` inside every limit. The optimisers aim at all of
/// it, and SLSQP's answers end within its tolerance of that (about 1.98 % inside at a 2 %
/// back-off); a throw met elsewhere (an offered start) is compared with them only when it keeps
/// the back-off too: one that spends it on a limit is cheaper for that reason alone.
bool keeps_backoff(const ThrowSetup& setup, const ProfileEvaluation& e, double backoff);

/// Ballistic flight from (p, v) under gravity g (m/s^2, > 0) down or up to height h.
Flight ballistic_flight(const Eigen::Vector2d& p, const Eigen::Vector2d& v, double g, double h);

/// Solves the study: eq. 8 start, IDP, SLSQP (if enabled), replay, flight.
ThrowingResult solve_throwing(const ThrowingSpec& spec, const ProgressFn& progress = {});

}  // namespace armstudy::studies
