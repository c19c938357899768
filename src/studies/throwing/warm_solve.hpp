// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The throwing study re-solved from a known throw (a sensitivity step, app/sensitivity.hpp):
/// SLSQP from `start` alone (no IDP, no further starts, no replay), the answer re-checked
/// with finer steps as in solve_throwing; when that throw is infeasible (the start breaks a
/// tightened limit), SLSQP again from the repair of `start` (the nearest profile inside
/// every limit, as solve_throwing repairs eq. 8). Only what the answer needs is
/// filled: the eq. 8 start (for the saving), nlopt, nlopt_run, nlopt_check, the SLSQP starts
/// ("warm start", "warm start, repaired"), the flight, status and message.

#include "studies/common.hpp"
#include "studies/throwing/result.hpp"
#include "studies/throwing/spec.hpp"

namespace armstudy::studies {

/// Solves `spec` by SLSQP from `start` (a profile meeting the displacement, e.g. the
/// nominal case's answer) on the start's control grid (its stages; the RK4 step at most
/// the case's: steps per stage = ceil(steps_per_stage x stages / the start's stages)). Solved when
/// SLSQP's throw is feasible, also in the re-check; its message starts "NOT converged" when it is
/// feasible but not first-order converged.
ThrowingResult solve_throwing_warm(const ThrowingSpec& spec, const VelocityProfile& start);

/// A throw judged against the case `spec`'s own limits and physics: `energy` on the throw's
/// control grid with the case's RK4 step (grid_setup, as the answer's energy is), `feasible` in the
/// re-check with spec.check_refinement x the steps (no back-off), `keeps_backoff` as the
/// optimisers' answers do (keeps_backoff, spec.backoff), `finite` false when the set-up or the
/// simulation failed.
struct JudgedThrow {
  double energy = 0;  ///< J
  bool feasible = false;
  bool keeps_backoff = false;
  bool finite = false;
};
JudgedThrow judge_throw(const ThrowingSpec& spec, const VelocityProfile& p);

}  // namespace armstudy::studies
