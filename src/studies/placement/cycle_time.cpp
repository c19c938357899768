// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/placement/cycle_time.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/check.hpp"
#include "studies/time_optimal/solve.hpp"
#include "studies/time_optimal/solvers.hpp"

namespace armstudy::studies::placement {

time_optimal::Spec cycle_time_problem(const Spec& spec, int configuration, double x_s, double phi,
                                      int grid_points) {
  ARM_THROW_UNLESS(spec.cycle_time.has_value(), "the placement spec has no cycle_time limits");
  const CycleTimeSpec& ct = *spec.cycle_time;
  time_optimal::Spec t;
  t.chain = spec.chain;
  t.chain.base = Eigen::Vector2d::Zero();
  t.chain.base_angle = 0;
  t.space = time_optimal::PathSpace::kTip;
  t.path.kind = time_optimal::PathKind::kLine;
  const Eigen::Vector2d start(x_s, 0.0);
  t.path.points = {start, start + spec.length * Eigen::Vector2d(std::cos(phi), std::sin(phi))};
  t.configuration = configuration;
  t.velocity_limit = ct.velocity_limit;
  t.torque_limit = ct.torque_limit;
  t.acceleration_limit = ct.acceleration_limit;
  t.dp.states.clear();
  t.dp.convergence_segments.clear();
  t.complex.enabled = false;
  t.exact.grid_points = grid_points;
  t.exact.checks_per_interval = ct.checks_per_interval;
  t.exact.tolerance_rel = ct.tolerance_rel;
  t.arm_origin = spec.arm_origin;
  return t;
}

double cycle_time_on_grid(const Spec& spec, int configuration, double x_s, double phi,
                          int grid_points) {
  constexpr double kNoMotion = std::numeric_limits<double>::quiet_NaN();
  const time_optimal::Spec t = cycle_time_problem(spec, configuration, x_s, phi, grid_points);
  const time_optimal::Limits limits{t.velocity_limit, t.torque_limit, t.acceleration_limit};
  try {
    const time_optimal::Problem pb = time_optimal::make_problem(t, limits);
    const time_optimal::SolverOutput o = time_optimal::solve_exact(
        pb, time_optimal::make_nodes(pb.path, grid_points - 1), t.exact.checks_per_interval);
    return o.solved ? o.duration : kNoMotion;
  } catch (const std::exception&) {  // (a point off the workspace or singular: no motion)
    return kNoMotion;
  }
}

namespace {

// every limit of the problem with its largest use by the exact solution
std::vector<LimitUse> limit_uses(const time_optimal::Result& r) {
  std::vector<LimitUse> out;
  const time_optimal::SolverResult& exact = r.solvers.front();
  const int kinds = r.limits.acceleration ? 3 : 2;
  for (int j = 0; j < r.limits.joints(); ++j)
    for (int k = 0; k < kinds; ++k) {
      LimitUse u;
      u.kind = time_optimal::limit_name(static_cast<time_optimal::LimitKind>(k));
      u.joint = j + 1;
      u.ratio = exact.violation.ratio[k][j];
      u.binding = u.ratio >= 1 - kBindingSlack;
      out.push_back(u);
    }
  return out;
}

}  // namespace

ConvergedCycleTime converged_cycle_time(const Spec& spec, int configuration, double x_s,
                                        double phi) {
  ConvergedCycleTime out;
  const time_optimal::Spec t =
      cycle_time_problem(spec, configuration, x_s, phi, spec.cycle_time->grid_points);
  const time_optimal::Result r = time_optimal::solve(t);
  out.message = r.message;
  if (r.status != Status::kSolved || r.solvers.empty() || !r.solvers.front().solved) return out;
  out.solved = true;
  out.grid_duration = r.solvers.front().duration;
  out.grid_points = r.grid.grid_points;
  const bool extrapolated = r.grid.extrapolation_computed && std::isfinite(r.grid.extrapolated);
  out.duration = r.grid.reference_duration(out.grid_duration);
  // without an extrapolation the grid's halving change is what is known of its error
  out.error = extrapolated ? r.grid.extrapolation_error : r.grid.change * out.grid_duration;
  out.limits = limit_uses(r);
  return out;
}

}  // namespace armstudy::studies::placement
