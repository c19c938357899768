// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The planning model's RK4 simulation without recorded samples (IDP's candidates, SLSQP's
/// points and neighbours), one profile at a time or up to five at once in the lanes of
/// lanes.hpp.
///
/// It computes what simulate_profile's one-evaluation-at-a-time path computes (the Planner
/// of simulate.cpp with TrayDynamics::mixed and core::motor_sample): each value the same
/// scalar expression in the same order, so each profile's ProfileEvaluation is that path's
/// bit for bit (tests/studies/throwing_kernel_test.cpp). What it saves:
/// - the active joints' part of an evaluation (their angles, rates, link frames, the cosine
///   and sine of links 1 and 2, their bodies' sums in the mass matrix and bias forces, and
///   their terms of the ball's acceleration) depends only on the stage and the time: RK4's
///   second and third evaluations share it, and so do a step's last and the next step's
///   first when their times are the same double; it is computed once and reused;
/// - no Eigen temporaries of run-time size and only eq. 5-6's voltage, current and power;
/// - profiles of the same stages and final time run side by side, the same operations on
///   the lanes of SSE2 registers (lanes.hpp: two in a D2 for about the time of one alone;
///   four as two D2). A lane ends when its profile does (stopped at a certain violation or
///   not finite, as simulate_profile); the others then go on from the last point all
///   passed, in as many lanes as are left; re-evaluating that point only repeats its
///   maxima, which leaves them unchanged.

#include <vector>

#include "studies/throwing/simulate.hpp"

namespace armstudy::studies {

/// Can `setup`'s simulations run in the kernel: not generic_dynamics, a 4-joint chain whose
/// joints 1, 2 are active and 3, 4 passive (the tray arm)?
bool kernel_applies(const ThrowSetup& setup);

/// simulate_profile(setup, profile, nullptr, backoff, stop_when_infeasible) (from == nullptr),
/// its checkpointed form (save) or simulate_profile_from's resumed simulation (from, first).
/// Requires kernel_applies(setup).
ProfileEvaluation simulate_kernel(const ThrowSetup& setup, const VelocityProfile& profile,
                                  double backoff, bool stop_when_infeasible,
                                  const SimulationCheckpoints* from = nullptr, int first = 0,
                                  SimulationCheckpoints* save = nullptr);

/// simulate_kernel for each of `profiles` (out[i] of profiles[i]), `width` (1 to 5; others
/// are clamped) of them at once (consecutive profiles of the same stages and final time);
/// all resume at stage `first` of `from` if it is given. stop_each (if given): profile i's
/// stop_when_infeasible.
void simulate_kernel_lanes(const ThrowSetup& setup,
                           const std::vector<const VelocityProfile*>& profiles, int width,
                           double backoff, bool stop_when_infeasible, ProfileEvaluation* out,
                           const SimulationCheckpoints* from = nullptr, int first = 0,
                           const bool* stop_each = nullptr);

}  // namespace armstudy::studies
