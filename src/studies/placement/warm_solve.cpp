// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/placement/warm_solve.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <locale>
#include <sstream>

#include "studies/placement/arm2.hpp"
#include "studies/placement/converge.hpp"
#include "studies/placement/refine.hpp"
#include "studies/placement/solve.hpp"

namespace armstudy::studies::placement {

// (over 60 lines, kept whole: the warm re-solve's steps in order, as solve's)
std::optional<Result> solve_warm(const Spec& spec, const Result& nominal) {
  const auto t0 = std::chrono::steady_clock::now();
  // as solve.cpp: a line this close to a boundary touches it; printed energies to 1e-4,
  // by quadrature to 1e-9
  constexpr double kWarmTouch = 1e-9, kWarmEnergyTol = 1e-4, kWarmQuadTol = 1e-9;
  const Arm2 arm = make_arm2(spec.chain);
  Result res;
  res.lmax = nominal.lmax;
  res.length = nominal.length;
  res.inner = nominal.inner;
  res.outer = nominal.outer;
  double best = std::numeric_limits<double>::infinity();
  for (const ProgramConfig& n : nominal.cases) {
    ProgramConfig out;
    out.program = n.program;
    out.configuration = n.configuration;
    out.counts = n.counts;
    if (n.found) {
      const ProgramTable table =
          make_program_table(n.program, spec.duration, spec.length, spec.samples);
      const Candidate start =
          evaluate_candidate(spec, arm, table, n.configuration, n.refined.x_s, n.refined.phi);
      if (start.status != CandidateStatus::kFeasible) return std::nullopt;
      // a box of +-4 steps of 5 mm (and the matching angle) around the nominal optimum
      const double hx = 5e-3, hphi = std::max(spec.phi_step, hx / std::max(start.x_s, 1e-3));
      const Refinement rf = refine_constrained(spec, arm, table, n.configuration, start, hx, hphi);
      out.found = true;
      out.refined = rf.best.status == CandidateStatus::kFeasible &&
                            rf.best.metrics.energy <= start.metrics.energy
                        ? rf.best
                        : start;
      out.grid = start;
      out.refine_evaluations = rf.evaluations;
      out.refine_method = "warm: " + rf.method;
      out.refine_tolerance_rel = rf.tolerance_rel;
      out.refine_converged = rf.converged;
      out.decision = decide(spec, out.refined);
      out.refined.convergence =
          check_energy(arm, out.program, spec.duration, spec.length,
                       thesis_line(out.refined.x_s, out.refined.phi), out.configuration,
                       spec.samples, out.refined.boundary_distance < kWarmTouch,
                       out.refined.inner_clearance < kWarmTouch, kWarmEnergyTol, kWarmQuadTol);
      if (!out.refined.convergence.energy_withheld())
        best = std::min(best, out.refined.reported_metrics().energy);
    } else {
      out.reason = n.reason;
    }
    res.cases.push_back(std::move(out));
  }
  if (std::isfinite(best)) {
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os.setf(std::ios::fixed);
    os.precision(4);
    os << "least energy " << best << " J, refined from the nominal optimum";
    res.message = os.str();
    res.status = Status::kSolved;
  } else {
    res.status = Status::kUnsolvable;
    res.message = "no optimum refined from the nominal one";
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace armstudy::studies::placement
