// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/throwing/grid_sequence.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "studies/throwing/slsqp_starts.hpp"
#include "studies/throwing/solve.hpp"

namespace armstudy::studies {
namespace {

bool usable(const ThrowingResult::SlsqpStart& s) {
  return s.run.best.v.size() != 0 && s.run.feasible && s.check.feasible;
}

// the prolonged start itself as a throw of the finer grid (the fallback when SLSQP from it
// ends nowhere better): the same energy and margins, its own first-order measure there
ThrowingResult::SlsqpStart unchanged(const ThrowSetup& fine, const ThrowingSpec& spec,
                                     const VelocityProfile& p, const Eigen::Vector2d& delta,
                                     const NloptSettings& ns, const std::string& name) {
  ThrowingResult::SlsqpStart s;
  s.name = name + ", unchanged";
  s.run.best = p;
  s.run.evaluation = simulate_profile(fine, p, nullptr, ns.backoff);
  double worst = -INFINITY;
  for (double g : constraint_values(fine, s.run.evaluation, 0.0)) worst = std::max(worst, g);
  s.run.feasible = s.run.evaluation.finite && worst <= 0.0;
  const Optimality o = first_order_optimality(fine, p, delta, ns);
  s.run.kkt_residual = o.kkt_residual;
  s.run.active_constraints = o.active_constraints;
  s.run.binding = o.binding;
  s.run.converged = s.run.feasible && o.kkt_residual <= ns.kkt_tolerance;
  s.run.return_code = "NONE (the prolonged start)";
  s.check = verify_profile(fine, p, spec.check_refinement);
  return s;
}

// the lowest usable throw of `runs` (-1: none); ties to the earlier
int lowest(const std::vector<ThrowingResult::SlsqpStart>& runs) {
  int best = -1;
  for (int i = 0; i < static_cast<int>(runs.size()); ++i)
    if (usable(runs[i]) &&
        (best < 0 || runs[i].run.evaluation.energy < runs[best].run.evaluation.energy))
      best = i;
  return best;
}

// the first grid's distinct local optima to refine: the answer first, then the other usable
// starts by energy (one of those within 1e-6 of a taken energy is the same optimum)
std::vector<std::pair<std::string, VelocityProfile>> first_candidates(const ThrowingResult& r,
                                                                      int count) {
  std::vector<std::pair<std::string, VelocityProfile>> out;
  std::vector<double> taken;
  auto take = [&](const ThrowingResult::SlsqpStart& s) {
    const double e = s.run.evaluation.energy;
    for (double t : taken)
      if (std::abs(e - t) <= 1e-6 * std::abs(t)) return;
    taken.push_back(e);
    out.emplace_back(s.name, s.run.best);
  };
  take(r.slsqp_starts[r.slsqp_best_start]);
  std::vector<int> order;
  for (int i = 0; i < static_cast<int>(r.slsqp_starts.size()); ++i)
    if (usable(r.slsqp_starts[i])) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return r.slsqp_starts[a].run.evaluation.energy < r.slsqp_starts[b].run.evaluation.energy;
  });
  for (int i : order)
    if (static_cast<int>(out.size()) < count) take(r.slsqp_starts[i]);
  return out;
}

// the error of the finest energy against the limit, from the last two changes; only for a
// converged sequence: one ratio of changes does not show a settled rate, and while the energy
// still falls by more than the tolerance a geometric fit is a guess (the bundled throw's
// 16-32-64-stage fit said about 3.75 J; its 256-stage answer is 3.274 J, docs/throwing.md),
// so a sequence that has not converged states no error and no limit (NaN: null)
void estimate_error(const ThrowingSpec& spec, ThrowingResult& r) {
  const auto& g = r.grids;
  const size_t n = g.size();
  if (n < 2) return;
  const double last = g[n - 1].energy - g[n - 2].energy;
  r.grid_change = last;
  r.grid_converged = std::abs(last) <= spec.grid.tolerance * std::abs(g[n - 1].energy);
  if (!r.grid_converged) {
    r.grid_error = NAN;
    r.grid_extrapolated = NAN;
    return;
  }
  double remaining = std::abs(last);
  if (n >= 3) {
    const double before = g[n - 2].energy - g[n - 3].energy;
    const double rho = before != 0 ? last / before : NAN;
    if (rho > 0 && rho < 1) remaining = std::abs(last) * rho / (1 - rho);
  }
  r.grid_error = remaining;
  r.grid_extrapolated = g[n - 1].energy - (last <= 0 ? remaining : -remaining);
}

// `best`, a throw of the grid `g` (set up as `fine`), as that grid's entry and the answer
void take_answer(const ThrowSetup& fine, const ThrowingSpec& spec,
                 const ThrowingResult::SlsqpStart& best, ThrowingResult::GridLevel& g,
                 ThrowingResult& r) {
  g.energy = best.run.evaluation.energy;
  g.feasible = true;
  g.converged = best.run.converged;
  g.kkt_residual = best.run.kkt_residual;
  g.from = best.name;
  r.nlopt_run = best.run;
  r.nlopt_check = best.check;
  r.answer_steps_per_stage = fine.steps_per_stage;
  r.nlopt = record_motion(fine, spec, best.run.best);
}

// spec.offered_starts on the answer's grid: SLSQP from each and each unchanged (it meets the
// limits: never worse than it); when the lowest of them is below the answer (or the grid had
// no feasible throw), it becomes the answer and its grid's entry (the runs are listed in that
// entry either way)
void adopt_offered(const ThrowSetup& setup, const ThrowingSpec& spec, const Eigen::Vector2d& delta,
                   const NloptSettings& settings, ThrowingResult& r) {
  if (spec.offered_starts.empty() || r.grids.empty() || r.slsqp_best_start < 0) return;
  const int stages = r.nlopt.profile.stages();
  std::vector<std::pair<std::string, VelocityProfile>> starts;
  for (const OfferedStart& o : spec.offered_starts)
    if (o.profile.stages() == stages) starts.emplace_back("offered: " + o.name, o.profile);
  if (starts.empty()) return;
  const auto t0 = std::chrono::steady_clock::now();
  const ThrowSetup fine = grid_setup(setup, r.grids.front().stages, stages);
  std::vector<ThrowingResult::SlsqpStart> runs;
  run_slsqp_wave(fine, spec, starts, delta, settings, runs);
  // each unchanged too, where it keeps the optimisers' back-off (keeps_backoff): an answer
  // that spends it would be cheaper for that alone
  for (const auto& [name, p] : starts) {
    ThrowingResult::SlsqpStart u = unchanged(fine, spec, p, delta, settings, name);
    u.run.feasible = u.run.feasible && keeps_backoff(fine, u.run.evaluation, settings.backoff);
    u.run.converged = u.run.converged && u.run.feasible;
    runs.push_back(std::move(u));
  }
  ThrowingResult::GridLevel& g = r.grids.back();
  const int b = lowest(runs);
  // (lower than the answer, or the answer's grid had no feasible throw)
  const bool lower =
      b >= 0 && (!g.feasible || runs[b].run.evaluation.energy < r.nlopt.evaluation.energy);
  if (lower) {
    take_answer(fine, spec, runs[b], g, r);
    if (r.grids.size() == 1) {
      r.first_grid = r.nlopt;
      r.first_grid_check = r.nlopt_check;
    }
  }
  for (auto& s : runs) {
    g.simulations += s.run.simulations;
    g.runs.push_back(std::move(s));
  }
  g.run_time += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (lower) estimate_error(spec, r);
}

}  // namespace

int steps_on_grid(int steps_per_stage, int first_stages, int stages) {
  const long steps = static_cast<long>(steps_per_stage) * first_stages;
  return static_cast<int>(std::max(1L, (steps + stages - 1) / stages));
}

ThrowSetup grid_setup(const ThrowSetup& setup, int first_stages, int stages) {
  ThrowSetup s = setup;
  s.steps_per_stage = steps_on_grid(setup.steps_per_stage, first_stages, stages);
  return s;
}

// (over 60 lines, kept whole: the grids in order, each from the coarser one's answers)
void refine_grids(const ThrowSetup& setup, const ThrowingSpec& spec, const Eigen::Vector2d& delta,
                  const NloptSettings& first_settings, ThrowingResult& r) {
  NloptSettings settings = first_settings;
  settings.exact_gradient = first_settings.exact_gradient || spec.grid.exact_gradient;
  r.grids.clear();
  r.answer_steps_per_stage = setup.steps_per_stage;
  if (r.slsqp_best_start < 0) return;
  r.first_grid = r.nlopt;
  r.first_grid_check = r.nlopt_check;
  ThrowingResult::GridLevel first;
  first.stages = r.nlopt.profile.stages();
  first.steps_per_stage = setup.steps_per_stage;
  first.energy = r.nlopt.evaluation.energy;
  first.feasible = r.nlopt_run.feasible && r.nlopt_check.feasible;
  first.converged = r.nlopt_run.converged;
  first.kkt_residual = r.nlopt_run.kkt_residual;
  first.from = r.slsqp_starts[r.slsqp_best_start].name;
  for (const auto& s : r.slsqp_starts) first.simulations += s.run.simulations;
  r.grids.push_back(first);
  if (!first.feasible || spec.grid.refinements <= 0)
    return adopt_offered(setup, spec, delta, settings, r);

  auto candidates = first_candidates(r, std::max(1, spec.grid.refine_best));
  ThrowSetup fine = setup;
  for (int level = 1; level <= spec.grid.refinements; ++level) {
    const auto t0 = std::chrono::steady_clock::now();
    ThrowingResult::GridLevel g;
    g.stages = first.stages << level;
    fine = grid_setup(setup, first.stages, g.stages);
    g.steps_per_stage = fine.steps_per_stage;
    std::vector<std::pair<std::string, VelocityProfile>> starts;
    for (const auto& [name, p] : candidates)
      starts.emplace_back("prolonged, from " + name, prolong_profile(p, 2));
    run_slsqp_wave(fine, spec, starts, delta, settings, g.runs);
    // the prolonged coarser answer (the first candidate) unchanged: never worse than it
    g.runs.push_back(unchanged(fine, spec, starts[0].second, delta, settings, starts[0].first));
    const int b = lowest(g.runs);
    if (b < 0) break;  // no throw of this grid is feasible in the re-check: stop refining
    take_answer(fine, spec, g.runs[b], g, r);
    for (const auto& s : g.runs) g.simulations += s.run.simulations;
    g.run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    // the first grid's start this throw descends from
    const std::string origin =
        b < static_cast<int>(candidates.size()) ? candidates[b].first : candidates[0].first;
    candidates = {{origin, g.runs[b].run.best}};
    r.grids.push_back(std::move(g));
    estimate_error(spec, r);
    if (r.grid_converged) break;
  }
  adopt_offered(setup, spec, delta, settings, r);
}

}  // namespace armstudy::studies
