// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/dynamic_replay.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/dynamics.hpp"
#include "scene/chain_map.hpp"
#include "scene/mjcf_writer.hpp"
#include "scene/mujoco_model.hpp"
#include "scene/phase_times.hpp"
#include "scene/scene_error.hpp"

namespace armstudy::scene {
namespace {
// 3-point Gauss-Legendre on [-1, 1]
constexpr double kGx[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
constexpr double kGw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

struct StepTorque {
  core::JointVector mean;   // N m, mean of the plan's torque over the step
  core::JointVector accel;  // rad/s^2, M(q_mid)^-1 mean
};

// mean torque of every step of `h` over [0, steps h], split at the breaks
std::vector<StepTorque> step_torques(const core::PlanarChain& chain, const PlanFunction& plan,
                                     double h, int steps, std::vector<double> breaks) {
  std::sort(breaks.begin(), breaks.end());
  std::vector<StepTorque> out(steps);
  size_t b = 0;
  for (int k = 0; k < steps; ++k) {
    const double t0 = k * h, t1 = (k + 1) * h;
    std::vector<double> cuts{t0};
    while (b < breaks.size() && breaks[b] <= t0) ++b;
    for (size_t i = b; i < breaks.size() && breaks[i] < t1; ++i)
      if (breaks[i] - cuts.back() > 1e-12 * h) cuts.push_back(breaks[i]);
    cuts.push_back(t1);
    core::JointVector sum = core::JointVector::Zero(chain.num_links());
    for (size_t p = 0; p + 1 < cuts.size(); ++p) {
      const double mid = 0.5 * (cuts[p] + cuts[p + 1]), half = 0.5 * (cuts[p + 1] - cuts[p]);
      for (int g = 0; g < 3; ++g) {
        const PlannedState s = plan(mid + half * kGx[g]);
        sum += kGw[g] * half * s.tau;
      }
    }
    const core::JointVector q_mid = plan(0.5 * (t0 + t1)).q;
    out[k].mean = sum / h;
    out[k].accel = core::mass_matrix(chain, q_mid).ldlt().solve(out[k].mean);
  }
  return out;
}

// one open-loop run with `means` held over steps of h; fills the deviation (and records)
struct Run {
  double max_dev = 0, max_dev_t = 0;
  int max_dev_joint = 0;
  std::vector<double> t;
  std::vector<core::JointVector> q_plan, q_sim;
};

Run run(MujocoModel& mm, const ChainMap& map, const core::PlanarChain& chain,
        const PlanFunction& plan, const std::vector<core::JointVector>& means, double h,
        double scale, const std::vector<core::JointVector>& q_plan_at_steps, int every) {
  mjModel* m = mm.model();
  mjData* d = mm.data();
  m->opt.timestep = h;
  mj_resetData(m, d);
  const PlannedState s0 = plan(0.0);
  map.set_state(m, d, s0.q, s0.qd);
  mj_forward(m, d);
  const int n = chain.num_links();
  std::vector<int> actuator(n, -1);
  for (int i = 0; i < n; ++i)
    if (chain.links[i].active) {
      actuator[i] = mj_name2id(m, mjOBJ_ACTUATOR, ("motor" + std::to_string(i + 1)).c_str());
      if (actuator[i] < 0)
        throw SceneError("dynamic replay: the model has no actuator motor" + std::to_string(i + 1));
    }
  Run r;
  const int steps = static_cast<int>(means.size());
  for (int k = 0; k <= steps; ++k) {
    const core::JointVector q = map.chain_q(d);
    const core::JointVector& qp =
        q_plan_at_steps[static_cast<size_t>(k) * (q_plan_at_steps.size() - 1) / steps];
    for (int j = 0; j < n; ++j) {
      const double dev = std::abs(q[j] - qp[j]);
      if (dev > r.max_dev) {
        r.max_dev = dev;
        r.max_dev_t = k * h;
        r.max_dev_joint = j;
      }
    }
    if (every > 0 && (k % every == 0 || k == steps)) {
      r.t.push_back(k * h);
      r.q_plan.push_back(qp);
      r.q_sim.push_back(q);
    }
    if (k == steps) break;
    mju_zero(d->ctrl, m->nu);
    for (int i = 0; i < n; ++i)
      if (actuator[i] >= 0) d->ctrl[actuator[i]] = scale * means[k][i];
    mj_step(m, d);
  }
  return r;
}
}  // namespace

DynamicReplay replay_torques(const core::PlanarChain& chain, double duration,
                             const PlanFunction& plan, const DynamicReplayOptions& o) {
  PhaseScope phase("mujoco_replay");
  if (!(duration > 0)) throw std::invalid_argument("dynamic replay: duration should be > 0");
  if (o.steps < 2) throw std::invalid_argument("dynamic replay: steps should be >= 2");
  const int steps = o.steps + (o.steps % 2);  // even, for the replay at 2 h
  DynamicReplay out;
  out.duration = duration;
  out.steps = steps;
  out.timestep = duration / steps;
  out.coarse_timestep = 2 * out.timestep;
  out.torque_scale = o.torque_scale;
  const double h = out.timestep;

  MjcfOptions mo;
  mo.integrator = "RK4";
  mo.timestep = h;
  MujocoModel mm(write_mjcf(chain, mo), "the generated model of the case's arm (dynamic replay)");
  const ChainMap map(chain, mm.model());

  const std::vector<StepTorque> st = step_torques(chain, plan, h, steps, o.breaks);
  std::vector<core::JointVector> fine(steps), coarse(steps / 2);
  for (int k = 0; k < steps; ++k) fine[k] = st[k].mean;
  for (int k = 0; k < steps / 2; ++k) coarse[k] = 0.5 * (st[2 * k].mean + st[2 * k + 1].mean);
  for (int k = 1; k < steps; ++k)
    out.variation += (st[k].accel - st[k - 1].accel).cwiseAbs().maxCoeff();
  out.tolerance = h * h * out.variation;

  // the plan's angles at every step boundary
  std::vector<core::JointVector> q_plan(steps + 1);
  core::JointVector lo, hi;
  for (int k = 0; k <= steps; ++k) {
    q_plan[k] = plan(k * h).q;
    lo = k == 0 ? q_plan[k] : lo.cwiseMin(q_plan[k]);
    hi = k == 0 ? q_plan[k] : hi.cwiseMax(q_plan[k]);
  }
  out.excursion = (hi - lo).maxCoeff();

  const int every = std::max(1, steps / std::max(1, o.records - 1));
  Run f = run(mm, map, chain, plan, fine, h, o.torque_scale, q_plan, every);
  out.t = std::move(f.t);
  out.q_plan = std::move(f.q_plan);
  out.q_sim = std::move(f.q_sim);
  out.max_deviation = f.max_dev;
  out.max_deviation_t = f.max_dev_t;
  out.max_deviation_joint = f.max_dev_joint;
  const Run c = run(mm, map, chain, plan, coarse, 2 * h, o.torque_scale, q_plan, 0);
  out.coarse_max_deviation = c.max_dev;
  out.observed_order = f.max_dev > 0 && c.max_dev > 0 ? std::log2(c.max_dev / f.max_dev) : 0.0;
  // the step's own error, measured: a deviation of order 2 in h is (coarse - fine) / 3 at h;
  // twice that is what the hold and the integrator may leave (a wrong model's deviation does
  // not shrink with h, so the difference stays small beside it)
  out.step_error = std::max(0.0, 2.0 * (c.max_dev - f.max_dev) / 3.0);
  out.tolerance = std::max(out.tolerance, out.step_error);
  return out;
}

studies::Check replay_check(const DynamicReplay& r, const std::string& name,
                            const std::string& what) {
  std::ostringstream os;
  os.precision(3);
  os << "the plan's joint torques of " << what
     << " applied open loop through mj_step (RK4, h = " << r.timestep << " s, " << r.steps
     << " steps, each holding the plan's mean torque over it)"
     << " in the generated MJCF, from the plan's initial state: largest joint deviation from the "
        "plan (rad), at t = "
     << r.max_deviation_t << " s, joint " << r.max_deviation_joint + 1
     << "; tolerance the larger of h^2 V with V = " << r.variation
     << " rad/s^2 the total variation of M(q)^-1 tau and the step's error measured, 2 "
        "(coarse - fine) / 3 = "
     << r.step_error << " rad: at 2 h the deviation is " << r.coarse_max_deviation
     << " rad (observed order " << r.observed_order << ")";
  if (r.torque_scale != 1.0) os << "; torques scaled by " << r.torque_scale;
  return studies::make_check(name, os.str(), r.max_deviation, r.tolerance);
}

std::string replay_tolerance_rule() {
  return "tolerance = the larger of h^2 V, V the total variation of M(q)^-1 tau over the "
         "steps (rad/s^2), and the step's error measured from a second replay at 2 h: each "
         "step holds the plan's mean torque (its impulse exact), which displaces the joints by "
         "at most h^2/8 of the variation within the step, so by at most h^2 V / 8 over the "
         "motion, the factor 8 leaving room for RK4's O(h^4); where the open-loop growth of "
         "that error is larger, a deviation of order 2 in h is (coarse - fine) / 3 at h, and "
         "twice that is tolerated (a wrong torque's deviation does not shrink with h)";
}

std::string replay_simulates() {
  return "MuJoCo integrates the rigid-body dynamics of the MJCF generated from the case's arm "
         "(its own mass matrix, Coriolis and centrifugal forces and gravity, with the case's "
         "masses, centres of mass and inertias) with RK4, driven only by the plan's joint "
         "torques, open loop, from the plan's initial state";
}

std::string replay_does_not_simulate() {
  return "it does not simulate motors or their electrics (the torques are ideal sources, gear "
         "1), friction or damping (zero), joint limits or contacts (the geoms are visual only), "
         "and nothing holds the tip on the path but the torques themselves; a point mass or "
         "payload is part of its link's inertial, not a separate body";
}

}  // namespace armstudy::scene
