// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/study_replays.hpp"

#include <cmath>
#include <stdexcept>

#include "studies/placement/arm2.hpp"
#include "studies/time_optimal/profile.hpp"

namespace armstudy::scene {
namespace to = studies::time_optimal;
namespace pl = studies::placement;

DynamicReplay replay_time_optimal(const to::Spec& spec, const to::Result& result,
                                  double torque_scale) {
  if (result.status != studies::Status::kSolved || result.solvers.empty() ||
      !result.solvers.front().solved)
    throw std::invalid_argument("replay_time_optimal: the study has no exact solution");
  const to::SolverResult& exact = result.solvers.front();
  const to::Problem pb = to::make_problem(spec, result.limits);
  to::Profile pr;
  pr.law = exact.law;
  pr.s = exact.node_s;
  pr.sd = exact.node_sd;
  const PlanFunction plan = [&](double t) {
    const to::TimedState st = to::state_at_time(pb, pr, exact.node_t, t);
    return PlannedState{st.q, st.qd, st.tau};
  };
  DynamicReplayOptions o;
  o.breaks = exact.node_t;
  o.torque_scale = torque_scale;
  return replay_torques(spec.chain, exact.duration, plan, o);
}

std::vector<PlacementReplay> replay_placement(const pl::Spec& spec, const pl::Result& result,
                                              double torque_scale) {
  std::vector<PlacementReplay> out;
  // the study's frame A: root at the origin (placement arms have gravity 0)
  core::PlanarChain chain = spec.chain;
  chain.base.setZero();
  chain.base_angle = 0;
  const pl::Arm2 arm = pl::make_arm2(chain);
  const double T = spec.duration;
  for (const pl::ProgramConfig& pc : result.cases) {
    if (!pc.found || pc.series.t.size() < 2) continue;
    const Eigen::Vector2d S = pc.placement.start, F = pc.placement.end;
    const double L = (F - S).norm();
    const Eigen::Vector2d u = (F - S) / L;
    const double sign = pc.configuration == 1 ? 1.0 : -1.0;
    const pl::TimeSeries& ser = pc.series;
    const PlanFunction plan = [&](double t) {
      const core::ProgramSample ps = core::evaluate_program(pc.program, t, T, L);
      const Eigen::Vector2d p = S + ps.s * u, v = ps.sd * u, a = ps.sdd * u;
      const pl::Arm2Sample a2 =
          pl::arm2_sample(arm, p.x(), p.y(), v.x(), v.y(), a.x(), a.y(), sign);
      // q1 unwrapped like the study's series (nearest sample's branch)
      const double dt = ser.t[1] - ser.t[0];
      const size_t k =
          std::min(ser.t.size() - 1, static_cast<size_t>(std::lround(std::clamp(t, 0.0, T) / dt)));
      double q1 = std::atan2(a2.s1, a2.c1);
      q1 += 2 * core::kPi * std::round((ser.q[k][0] - q1) / (2 * core::kPi));
      PlannedState s;
      s.q = Eigen::Vector2d(q1, std::atan2(a2.s2, a2.c2));
      s.qd = Eigen::Vector2d(a2.qd1, a2.qd2);
      s.tau = Eigen::Vector2d(a2.tau1, a2.tau2);
      return s;
    };
    DynamicReplayOptions o;
    o.torque_scale = torque_scale;
    if (pc.program == core::MotionProgram::kTrapezoidal) o.breaks = {T / 3, 2 * T / 3};
    out.push_back({pc.program, pc.configuration, replay_torques(chain, T, plan, o)});
  }
  return out;
}

}  // namespace armstudy::scene
