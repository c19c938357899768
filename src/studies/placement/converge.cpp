// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/placement/converge.hpp"

#include "studies/placement/quadrature.hpp"

#include <algorithm>
#include <cmath>

namespace armstudy::studies::placement {

EnergyConvergence converge_energy(const Arm2& arm, core::MotionProgram program, double duration,
                                  double length, const Line& line, int configuration, int samples,
                                  bool touches, double tol, double peak_tol, int max_samples) {
  EnergyConvergence c;
  c.checked = true;
  c.touches_boundary = touches;
  c.tolerance = tol;
  int n = std::max(samples, 3);
  LineMetrics prev =
      evaluate_line(arm, make_program_table(program, duration, length, n), line, configuration);
  c.rows.push_back({n, prev.energy, std::max(prev.peak_torque[0], prev.peak_torque[1])});
  c.samples = n;
  c.metrics = prev;
  while (2 * (n - 1) + 1 <= max_samples) {
    const int m = 2 * (n - 1) + 1;
    const LineMetrics next =
        evaluate_line(arm, make_program_table(program, duration, length, m), line, configuration);
    c.rows.push_back({m, next.energy, std::max(next.peak_torque[0], next.peak_torque[1])});
    if (!prev.finite() || !next.finite()) {
      // a sample on the singular pose itself: nothing converges
      c.rel_change = std::numeric_limits<double>::infinity();
      c.peak_converged = false;
      prev = next;
      n = m;
      if (!next.finite()) break;
      continue;
    }
    c.rel_change = std::abs(next.energy - prev.energy) / std::abs(next.energy);
    const double pk_prev = std::max(prev.peak_torque[0], prev.peak_torque[1]);
    const double pk_next = std::max(next.peak_torque[0], next.peak_torque[1]);
    const double peak_change_before = c.peak_rel_change;
    c.peak_rel_change = std::abs(pk_next - pk_prev) / pk_next;
    // a sampled peak has settled when its change is small and it shrank by half or more
    // since the doubling before (the samples resolve the peak's width); a change that is
    // small by chance, a sample landing near a peak narrower than the spacing, is not enough
    c.peak_converged =
        c.peak_rel_change < peak_tol &&
        (c.peak_rel_change <= 1e-14 || c.peak_rel_change <= 0.5 * peak_change_before);
    if (c.rel_change < tol && c.peak_converged) {
      // the finer of the pair is kept (the coarser one's error is the change itself)
      c.converged = true;
      c.samples = m;
      c.metrics = next;
      return c;
    }
    prev = next;
    n = m;
  }
  c.samples = n;
  c.metrics = prev;
  return c;
}

EnergyConvergence check_energy(const Arm2& arm, core::MotionProgram program, double duration,
                               double length, const Line& line, int configuration, int samples,
                               bool touches, bool touches_inner, double tol, double quad_tol,
                               double peak_tol, int max_samples) {
  EnergyConvergence c = converge_energy(arm, program, duration, length, line, configuration,
                                        samples, touches, tol, peak_tol, max_samples);
  c.touches_inner = touches_inner;
  const EnergyQuadrature q =
      energy_quadrature(arm, program, duration, length, line, configuration, quad_tol);
  c.quadrature = true;
  c.energy = q.energy;
  c.energy_error = q.error;
  c.quadrature_tolerance = q.tolerance_rel;
  c.energy_jump = q.jump;
  c.quadrature_intervals = q.intervals;
  c.quadrature_evaluations = q.evaluations;
  if (c.energy_converged()) c.metrics.energy = q.energy;
  return c;
}

}  // namespace armstudy::studies::placement
