// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/throwing/warm_solve.hpp"

#include <chrono>
#include <cmath>
#include <locale>
#include <sstream>
#include <stdexcept>

#include "studies/throwing/grid_sequence.hpp"
#include "studies/throwing/solve.hpp"

namespace armstudy::studies {

JudgedThrow judge_throw(const ThrowingSpec& spec, const VelocityProfile& p) {
  JudgedThrow j;
  if (p.stages() < 2) return j;
  ThrowSetup setup;
  try {
    setup = grid_setup(make_throw_setup(spec), spec.stages, p.stages());
  } catch (const std::invalid_argument&) {
    return j;
  }
  const ProfileEvaluation e = simulate_profile(setup, p);
  if (!e.finite) return j;
  j.finite = true;
  j.energy = e.energy;
  j.keeps_backoff = keeps_backoff(setup, e, spec.backoff);
  j.feasible = verify_profile(setup, p, spec.check_refinement).feasible;
  return j;
}

// (over 60 lines, kept whole: the warm re-solve's steps in order (set-up, repair, SLSQP, re-check),
// as solve_throwing's)
ThrowingResult solve_throwing_warm(const ThrowingSpec& case_spec, const VelocityProfile& start) {
  const auto t0 = std::chrono::steady_clock::now();
  ThrowingResult r;
  ThrowSetup setup;
  VelocityProfile initial;
  // the start's control grid (the nominal answer's finest), with the RK4 step kept at most
  // the case's (steps_on_grid, grid_setup's rule)
  ThrowingSpec spec = case_spec;
  if (start.stages() >= 2 && start.stages() != spec.stages) {
    spec.steps_per_stage = steps_on_grid(spec.steps_per_stage, spec.stages, start.stages());
    spec.stages = start.stages();
  }
  const Eigen::Vector2d delta = spec.release - spec.start;
  if (!prepare_throw(spec, setup, initial, r)) return r;
  r.answer_steps_per_stage = spec.steps_per_stage;
  r.initial = record_motion(setup, spec, initial);
  r.initial_feasible = r.initial.evaluation.feasible;
  NloptSettings ns = spec.nlopt;
  ns.threads = spec.threads;
  ns.backoff = spec.backoff;
  VelocityProfile from = start;
  project_displacement(from, delta);
  ThrowingResult::SlsqpStart s;
  s.name = "warm start";
  s.run = run_nlopt(setup, from, delta, ns);
  s.check = verify_profile(setup, s.run.best, spec.check_refinement);
  r.slsqp_starts.push_back(s);
  r.slsqp_best_start = 0;
  if (!(s.run.feasible && s.check.feasible)) {
    // the nominal answer breaks a tighter limit and SLSQP did not leave it: first the
    // nearest profile twice the back-off inside every limit (as solve_throwing repairs
    // eq. 8), then SLSQP from there
    r.repair_run = run_nlopt(setup, from, delta, ns, Objective::kViolation);
    if (r.repair_run.feasible) {
      ThrowingResult::SlsqpStart t;
      t.name = "warm start, repaired";
      t.run = run_nlopt(setup, r.repair_run.best, delta, ns);
      t.check = verify_profile(setup, t.run.best, spec.check_refinement);
      r.slsqp_starts.push_back(t);
      if (t.run.feasible && t.check.feasible) r.slsqp_best_start = 1;
    }
  }
  s = r.slsqp_starts[r.slsqp_best_start];
  r.nlopt_ran = true;
  r.answer = "slsqp";
  r.nlopt_run = s.run;
  r.nlopt_check = s.check;
  r.nlopt = record_motion(setup, spec, r.nlopt_run.best);
  r.idp = r.nlopt;  // no IDP ran: the comparison is the answer itself
  r.idp_check = r.nlopt_check;
  const bool feasible = r.nlopt_run.feasible && r.nlopt_check.feasible;
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.setf(std::ios::fixed);
  os.precision(4);
  os << r.nlopt.evaluation.energy << " J by SLSQP from the nominal answer"
     << (r.slsqp_best_start == 1 ? " (repaired)" : "") << ", first-order residual ";
  os.precision(6);
  os << r.nlopt_run.kkt_residual;
  const std::string b = os.str();
  if (!feasible) {
    r.status = Status::kUnsolvable;
    r.message = "no feasible throw found from the nominal answer: " + b +
                (r.nlopt_run.feasible ? " breaks a limit in the re-check" : " breaks a limit");
  } else {
    r.status = Status::kSolved;
    r.saving_percent = 100.0 * (r.initial.evaluation.energy - r.nlopt.evaluation.energy) /
                       std::abs(r.initial.evaluation.energy);
    r.message = (r.nlopt_run.converged ? "" : "NOT converged: ") + b;
  }
  r.run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace armstudy::studies
