// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// SLSQP from several deterministic starts (the multi-start of docs/throwing.md): the
/// feasible reference, IDP's optimum, the raw eq. 8 profile and `perturbed_starts` seeded
/// perturbations of the reference. Each start's local optimum is re-simulated with finer
/// steps; the answer is the lowest-energy one that is converged (first order) and feasible
/// in the re-check, ties to the earlier start. The problem has nearby local optima (a
/// single start moved 2-70 % under a last-digit change of an input); the best of several
/// is the same one under such changes.

#include "studies/throwing/result.hpp"
#include "studies/throwing/spec.hpp"

namespace armstudy::studies {

/// Fills r.slsqp_starts, r.slsqp_best_start (-1: no start gave a profile) and, for the
/// best start, r.nlopt_run, r.nlopt, r.nlopt_check. `reference` is the feasible reference
/// (or eq. 8 when there is none), `eq8` the raw eq. 8 profile; r.idp_run must be set.
/// The starts run side by side on settings.threads threads (one simulation thread each):
/// the results do not depend on the thread count.
void run_slsqp_starts(const ThrowSetup& setup, const ThrowingSpec& spec,
                      const VelocityProfile& reference, const VelocityProfile& eq8,
                      const Eigen::Vector2d& delta, const NloptSettings& settings,
                      ThrowingResult& r);

/// SLSQP from each named start on `setup` (any grid), each local optimum re-checked with
/// spec.check_refinement x the steps, appended to `out` in the order of `starts`. Several
/// starts run side by side on settings.threads threads (one simulation thread each), one
/// start uses them for its gradients: the results do not depend on the thread count.
void run_slsqp_wave(const ThrowSetup& setup, const ThrowingSpec& spec,
                    const std::vector<std::pair<std::string, VelocityProfile>>& starts,
                    const Eigen::Vector2d& delta, const NloptSettings& settings,
                    std::vector<ThrowingResult::SlsqpStart>& out);

}  // namespace armstudy::studies
