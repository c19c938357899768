// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "app/placement_cycle_time_section.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/motion_program.hpp"
#include "core/types.hpp"

namespace armstudy::app {
namespace {
namespace pl = studies::placement;
using Results = pl::StudyResults;

Results::Pair xy(const Eigen::Vector2d& v) { return {v.x(), v.y()}; }
Results::Pair joints(const core::JointVector& v) { return {v[0], v[1]}; }

Results::CycleTimeAt at_section(const pl::ConvergedCycleTime& c) {
  Results::CycleTimeAt a;
  a.solved = c.solved;
  a.message = c.message;
  if (c.solved) {
    a.duration_s = c.duration;
    a.error_s = c.error;
    a.grid_duration_s = c.grid_duration;
  }
  a.grid_points = c.grid_points;
  for (const pl::LimitUse& u : c.limits) a.limits.push_back({u.kind, u.joint, u.ratio, u.binding});
  return a;
}

std::optional<pl::FastEnergy> fast_section(const pl::FastMotionEnergy& f) {
  if (!f.computed) return std::nullopt;
  return pl::FastEnergy{f.energy, f.error, f.duration, f.grid_points};
}

Results::CycleTimeMap map_section(const pl::CycleTimeMap& m, int grid_points) {
  Results::CycleTimeMap mj;
  mj.x_m = m.x;
  mj.y_m = m.y;
  const size_t nx = m.x.size();
  for (size_t row = 0; row < m.y.size(); ++row) {
    std::string t, st;
    for (size_t i = 0; i < nx; ++i) {
      const double v = m.time[row * nx + i];
      if (i) t += ' ';
      if (std::isfinite(v)) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.6g", v);
        t += buf;
      } else {
        t += '-';
      }
      st += pl::status_char(m.status[row * nx + i]);
    }
    mj.time_s_rows.push_back(std::move(t));
    mj.status_rows.push_back(std::move(st));
  }
  mj.encoding =
      "row j is y_m[j]; time_s_rows: space-separated least traversal times in s at 6 "
      "significant digits on the exact solver's coarse grid, '-' where not admissible or "
      "unsolved; status_rows: '.' unreachable, 's' inside the singularity margin, 'o' "
      "admissible; Y < 0 is the mirror image with the configurations swapped";
  mj.nodes_solved = m.solved;
  mj.grid_points = grid_points;
  mj.threads = m.threads;
  mj.seconds = m.seconds;
  return mj;
}

Results::CycleTimeOptimum optimum_section(const pl::CycleTimeOptimum& o) {
  Results::CycleTimeOptimum oj;
  oj.found = o.found;
  oj.reason = o.reason;
  oj.refinement_solves = o.evaluations;
  if (!o.found) return oj;
  oj.root_xy_m = xy(o.root);
  oj.x_s_m = o.x_s;
  oj.phi_deg = o.phi / core::kDeg;
  oj.root_error_m = o.root_error;
  oj.duration_s = o.converged.duration;
  oj.duration_error_s = o.duration_error;
  oj.grid_root_xy_m = xy(o.grid_root);
  oj.grid_time_s = o.grid_time;
  oj.fine_time_s = o.fine_time;
  oj.inner_slack_m = o.inner_slack;
  oj.outer_slack_m = o.outer_slack;
  oj.set_by_margin = o.set_by_margin;
  oj.converged = at_section(o.converged);
  oj.fast_motion_energy = fast_section(o.fast_energy);
  return oj;
}

Results::EnergyOptimumTime energy_optimum_section(const pl::EnergyOptimumCycleTime& e,
                                                  bool time_optimum) {
  Results::EnergyOptimumTime ej;
  ej.program = std::string(core::program_name(e.program));
  ej.x_s_m = e.x_s;
  ej.phi_deg = e.phi / core::kDeg;
  ej.energy_J = e.energy;
  ej.root_xy_m = xy(e.root);
  ej.cycle_time = at_section(e.time);
  ej.fast_motion_energy = fast_section(e.fast_energy);
  if (e.has_energy_at_time_optimum) {
    ej.energy_at_time_optimum_J = e.energy_at_time_optimum;
    ej.energy_at_time_optimum_error_J = e.energy_at_time_optimum_error;
  }
  if (time_optimum) ej.status_at_time_optimum = pl::status_name(e.status_at_time_optimum);
  for (const pl::CycleEnergyPoint& p : e.front)
    ej.front.push_back(
        {p.kind, xy(p.root), p.x_s, p.phi / core::kDeg, p.time, p.energy, p.fast_energy});
  return ej;
}

}  // namespace

std::optional<Results::CycleTimeSection> cycle_time_section(const pl::Spec& spec,
                                                            const pl::Result& r) {
  if (!spec.cycle_time) return std::nullopt;
  const pl::CycleTimeSpec& ct = *spec.cycle_time;
  Results::CycleTimeSection s;
  s.velocity_limit_rad_s = joints(ct.velocity_limit);
  s.torque_limit_Nm = joints(ct.torque_limit);
  if (ct.acceleration_limit) s.acceleration_limit_rad_s2 = joints(*ct.acceleration_limit);
  for (const pl::CycleTime& c : r.cycle_time) {
    Results::CycleTime cj;
    cj.configuration = c.configuration;
    cj.map = map_section(c.map, ct.map_grid_points);
    cj.optimum = optimum_section(c.optimum);
    for (const pl::EnergyOptimumCycleTime& e : c.at_energy_optima)
      cj.at_energy_optima.push_back(energy_optimum_section(e, c.optimum.found));
    s.configurations.push_back(std::move(cj));
  }
  return s;
}

}  // namespace armstudy::app
