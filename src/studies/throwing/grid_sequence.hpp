// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The answer of the continuous problem, not of one control grid (docs/throwing.md, "The
/// control grid"): the first grid's SLSQP optima (IDP's stages) are prolonged to twice the
/// stages (prolong_profile: the same rate function, the same RK4 step, so the same energy
/// and the same margins) and SLSQP starts from each; the best few local optima of the first
/// grid are refined on the second, then only the best on each finer grid. A grid's answer is
/// the lowest throw feasible also in the re-check, and never worse than the prolonged start
/// (which is feasible and costs the same), so the energies never rise with the stages.
/// The sequence stops when a doubling changes the energy by at most grid.tolerance
/// (relative): converged. Otherwise, after grid.refinements doublings, it is not converged
/// and says by how much the energy still falls per doubling. The error estimate: the last
/// change times rho / (1 - rho) when the changes fall geometrically (rho = last / previous
/// change in (0, 1)), else the last change itself.
/// Offered starts (spec.offered_starts: throws the run met elsewhere, e.g. a sensitivity step's,
/// that meet these limits for less): on the answer's grid SLSQP starts from each, and the
/// answer is the lowest of it and them (its grid's entry then names the offered start).

#include "studies/throwing/result.hpp"
#include "studies/throwing/spec.hpp"

namespace armstudy::studies {

/// Refines r's SLSQP answer (r.nlopt, r.nlopt_run, r.nlopt_check on the first grid, from
/// run_slsqp_starts) over finer grids: fills r.grids, r.grid_*, r.first_grid(_check),
/// r.answer_steps_per_stage, and replaces r.nlopt, r.nlopt_run, r.nlopt_check by the finest
/// grid's answer. `setup` and `settings` are the first grid's; the finer grids' SLSQP uses
/// exact derivatives when spec.grid.exact_gradient is set (or settings.exact_gradient). Nothing is
/// refined (one grid listed) when spec.grid.refinements is 0 or the first grid has no feasible
/// throw.
void refine_grids(const ThrowSetup& setup, const ThrowingSpec& spec, const Eigen::Vector2d& delta,
                  const NloptSettings& settings, ThrowingResult& r);

/// RK4 steps per stage on `stages` stages with the step at most that of `steps_per_stage`
/// steps on `first_stages` stages: ceil(steps_per_stage x first_stages / stages), at least 1.
int steps_on_grid(int steps_per_stage, int first_stages, int stages);

/// The setup of `stages` stages whose RK4 step is at most the first grid's (steps_on_grid).
ThrowSetup grid_setup(const ThrowSetup& setup, int first_stages, int stages);

}  // namespace armstudy::studies
