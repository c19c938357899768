// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The placement study's checks on its own answer, each a function of the measured figures
/// and the case's limits (solve() runs them; tests hold each verdict on both sides of its
/// limit). printed_limits.hpp has the check of the actuator limits at the printed samples.

#include <utility>
#include <vector>

#include "studies/common.hpp"
#include "studies/placement/arm2.hpp"
#include "studies/placement/result.hpp"
#include "studies/placement/spec.hpp"

namespace armstudy::studies::placement {

/// "signed_work_rest_to_rest": the largest |signed work| / energy over the candidate lines
/// (boundary distance, sampled metrics) clear of the singularity margin with a finite,
/// positive energy; tolerance 1e-6 (rest to rest without gravity the work is 0).
Check signed_work_check(const Spec& spec,
                        const std::vector<std::pair<double, const LineMetrics*>>& lines);

/// Appends the checks of the found optima of `res.cases`: "optima_clear_of_singularities"
/// (margin - boundary distance <= kMarginTol), "refinement_converged" (the final COBYLA
/// restart's relative gain <= 1e-7; infinite when not converged), "optima_energy_converged"
/// (relative quadrature error <= 1e-4; infinite when withheld) and "refinement_not_worse"
/// (refined energy - grid energy <= 0 J).
void check_optima(const Spec& spec, Result& res);

/// Appends "energy_converged": the first found optimum's energy at spec.samples against the
/// last row of res.convergence, relative, at most 1e-4 (none with fewer than two rows).
void check_sample_convergence(const Spec& spec, Result& res);

}  // namespace armstudy::studies::placement
