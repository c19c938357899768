// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/placement/cycle_time.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "core/check.hpp"
#include "studies/placement/arm2.hpp"
#include "studies/time_optimal/profile.hpp"
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

namespace {

// the exact solver's motion along the line (x_s, phi) on grid_points uniform nodes; nullopt
// where there is none (unsolved, or a point off the workspace or singular)
std::optional<time_optimal::SolverOutput> exact_on_grid(const Spec& spec, int configuration,
                                                        double x_s, double phi, int grid_points) {
  const time_optimal::Spec t = cycle_time_problem(spec, configuration, x_s, phi, grid_points);
  const time_optimal::Limits limits{t.velocity_limit, t.torque_limit, t.acceleration_limit};
  try {
    const time_optimal::Problem pb = time_optimal::make_problem(t, limits);
    time_optimal::SolverOutput o = time_optimal::solve_exact(
        pb, time_optimal::make_nodes(pb.path, grid_points - 1), t.exact.checks_per_interval);
    if (!o.solved) return std::nullopt;
    return o;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

constexpr double kNoMotion = std::numeric_limits<double>::quiet_NaN();

}  // namespace

double cycle_time_on_grid(const Spec& spec, int configuration, double x_s, double phi,
                          int grid_points) {
  const auto o = exact_on_grid(spec, configuration, x_s, phi, grid_points);
  return o ? o->duration : kNoMotion;
}

namespace {

// E = integral of |tau1 qd1| + |tau2 qd2| dt over the exact solver's motion (constant s''
// per interval) along the line (x_s, phi): 4 Gauss-Legendre points per interval in time, the
// placement's closed-form inverse dynamics at each (arm2_sample)
double profile_energy(const Spec& spec, int configuration, double x_s, double phi,
                      const time_optimal::Profile& profile) {
  const Arm2 arm = make_arm2(spec.chain);
  const Eigen::Vector2d start(x_s, 0.0), u(std::cos(phi), std::sin(phi));
  const double sign = configuration == 1 ? 1.0 : -1.0;
  static constexpr double kNode[2] = {0.3399810435848563, 0.8611363115940526};
  static constexpr double kWeight[2] = {0.6521451548625461, 0.3478548451374538};
  double energy = 0;
  for (size_t k = 0; k + 1 < profile.s.size(); ++k) {
    const double ds = profile.s[k + 1] - profile.s[k];
    const double a = profile.sd[k], b = profile.sd[k + 1];
    if (!(ds > 0) || !(a + b > 0)) continue;
    const double sdd = (b * b - a * a) / (2 * ds), dt = 2 * ds / (a + b);
    for (int side = -1; side <= 1; side += 2)
      for (int g = 0; g < 2; ++g) {
        const double tau = 0.5 * dt * (1 + side * kNode[g]);
        const double s = profile.s[k] + a * tau + 0.5 * sdd * tau * tau, sd = a + sdd * tau;
        const Eigen::Vector2d p = start + s * u, v = sd * u, acc = sdd * u;
        const Arm2Sample o = arm2_sample(arm, p.x(), p.y(), v.x(), v.y(), acc.x(), acc.y(), sign);
        energy += 0.5 * dt * kWeight[g] * (std::abs(o.tau1 * o.qd1) + std::abs(o.tau2 * o.qd2));
      }
  }
  return energy;
}

}  // namespace

FastMotionOnGrid fastest_motion_on_grid(const Spec& spec, int configuration, double x_s, double phi,
                                        int grid_points) {
  const auto o = exact_on_grid(spec, configuration, x_s, phi, grid_points);
  if (!o) return {kNoMotion, kNoMotion};
  return {o->duration, profile_energy(spec, configuration, x_s, phi, o->profile)};
}

FastMotionEnergy fastest_motion_energy(const Spec& spec, int configuration, double x_s,
                                       double phi) {
  FastMotionEnergy out;
  const int n = spec.cycle_time->grid_points;
  const FastMotionOnGrid coarse = fastest_motion_on_grid(spec, configuration, x_s, phi, n);
  const FastMotionOnGrid fine = fastest_motion_on_grid(spec, configuration, x_s, phi, 2 * n - 1);
  if (!std::isfinite(coarse.energy) || !std::isfinite(fine.energy)) return out;
  out.computed = true;
  out.energy = fine.energy;
  out.error = std::abs(fine.energy - coarse.energy);
  out.grid_points = 2 * n - 1;
  out.duration = fine.duration;
  return out;
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
