// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Solves the pendulum study (spec.hpp -> result.hpp).

#include "studies/common.hpp"
#include "studies/pendulum/result.hpp"
#include "studies/pendulum/spec.hpp"

namespace armstudy::studies {

/// Simulates the locked-arm pendulum with DOPRI5 at (rtol, atol); joints 1 and 2 get zero
/// acceleration and the passive joints follow core::passive_forward_dynamics.
/// Invalid arm parameters give status kUnsolvable with the reason.
PendulumResult solve_pendulum(const PendulumSpec& spec, const ProgressFn& progress = {});

}  // namespace armstudy::studies
