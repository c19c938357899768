// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/pendulum/solve.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <locale>
#include <sstream>
#include <stdexcept>

#include "core/dynamics.hpp"
#include "core/integrators.hpp"
#include "core/kinematics.hpp"

namespace armstudy::studies {
// the integrators of core/integrators.hpp
using core::Dopri5Options;
using core::Dopri5Stats;
using core::integrate_dopri5;
using core::OdeState;

PendulumSpec default_pendulum_spec() {
  PendulumSpec s;
  TrayArmParams& a = s.arm;
  // sec. 3 of 003
  a.m3 = 0.109;
  a.m4 = 0.122;
  a.r4 = 0.075;
  a.rb = 0.015;
  // open choices (docs/assumptions.md), documented in the header
  a.circle_offset = 0.015;
  a.r3 = a.circle_offset + a.r4 + a.rb;
  a.I3 = a.m3 * (a.r4 + a.rb) * (a.r4 + a.rb) / 3.0;
  a.Ib = solid_sphere_inertia(a.m4, a.rb);
  return s;
}

namespace {
// output times: the sample grid merged with the snapshot times (in `snapshot_t`)
std::vector<double> output_times(const PendulumSpec& spec, std::vector<double>* snapshot_t) {
  std::vector<double> times;
  const int ns = static_cast<int>(std::floor(spec.duration / spec.sample_step + 1e-9));
  for (int k = 0; k <= ns; ++k) times.push_back(k * spec.sample_step);
  if (times.back() < spec.duration - 1e-12) times.push_back(spec.duration);
  const int nsnap = static_cast<int>(std::floor(spec.duration / spec.snapshot_step + 1e-9));
  for (int k = 0; k <= nsnap; ++k) snapshot_t->push_back(k * spec.snapshot_step);
  times.insert(times.end(), snapshot_t->begin(), snapshot_t->end());
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end(),
                          [](double a, double b) { return std::abs(a - b) < 1e-12; }),
              times.end());
  return times;
}

// energy and geometry along the motion (states xs at `times`), the snapshots' indices and
// the energy drift
void record_pendulum_motion(const PendulumSpec& spec, const core::PlanarChain& chain,
                            const std::vector<double>& times, const std::vector<OdeState>& xs,
                            PendulumResult& r) {
  core::JointVector q(4), qd(4);
  for (size_t k = 0; k < times.size(); ++k) {
    q << spec.theta1, spec.theta2, xs[k][0], xs[k][1];
    qd << 0.0, 0.0, xs[k][2], xs[k][3];
    r.t.push_back(times[k]);
    r.q.push_back(q);
    r.qd.push_back(qd);
    const double K = core::kinetic_energy(chain, q, qd);
    const double U = core::potential_energy(chain, q);
    r.kinetic.push_back(K);
    r.potential.push_back(U);
    r.total.push_back(K + U);
    const core::ChainPose pose = core::forward_kinematics(chain, q);
    r.ball.push_back(pose.p_WJ.col(4));
    r.circle_centre.push_back(pose.p_WJ.col(3));
  }
  for (double ts : r.snapshot_t) {
    const auto it = std::lower_bound(r.t.begin(), r.t.end(), ts - 1e-12);
    r.snapshot_index.push_back(static_cast<int>(it - r.t.begin()));
  }
  r.energy_initial = r.total.front();
  for (size_t k = 0; k < r.t.size(); ++k) {
    r.energy_scale = std::max(r.energy_scale, r.kinetic[k]);
    r.energy_drift = std::max(r.energy_drift, std::abs(r.total[k] - r.energy_initial));
  }
  // at rest everywhere (an equilibrium start) the drift is measured against the weight
  if (r.energy_scale <= 0)
    r.energy_scale = std::abs(r.energy_initial) > 0 ? std::abs(r.energy_initial) : 1.0;
  r.energy_drift_rel = r.energy_drift / r.energy_scale;
}

// the summary sentence: the simulated time, the steps and the energy drift
std::string pendulum_message(const PendulumSpec& spec, const PendulumResult& r) {
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os << "pendulum simulated for " << spec.duration << " s (" << r.steps_accepted
     << " steps); energy drift " << std::setprecision(3) << r.energy_drift_rel << " of the "
     << std::setprecision(4) << r.energy_scale << " J exchanged";
  return os.str();
}
}  // namespace

PendulumResult solve_pendulum(const PendulumSpec& spec, const ProgressFn& progress) {
  const auto t_start = std::chrono::steady_clock::now();
  PendulumResult r;
  r.integrator =
      "DOPRI5 (Dormand-Prince 5(4), adaptive step, error per step <= atol + rtol |x|; "
      "steps end at every output sample)";
  r.rtol = spec.rtol;
  r.atol = spec.atol;
  core::PlanarChain chain;
  try {
    chain = make_tray_arm(spec.arm);
  } catch (const std::invalid_argument& e) {
    r.message = std::string("invalid tray arm: ") + e.what();
    return r;
  }
  if (!(spec.duration > 0) || !(spec.sample_step > 0) || !(spec.snapshot_step > 0)) {
    r.message = "duration, sample step and snapshot step should be > 0 s";
    return r;
  }

  const std::vector<double> times = output_times(spec, &r.snapshot_t);

  // state (q3, q4, qd3, qd4); joints 1, 2 locked (zero rate and acceleration)
  const core::JointVector zero = core::JointVector::Zero(4);
  auto rhs = [&](double, const OdeState& x) {
    core::JointVector qq(4), qqd(4);
    qq << spec.theta1, spec.theta2, x[0], x[1];
    qqd << 0.0, 0.0, x[2], x[3];
    const core::MixedDynamics d = core::passive_forward_dynamics(chain, qq, qqd, zero, zero);
    OdeState dx(4);
    dx << x[2], x[3], d.qdd[2], d.qdd[3];
    return dx;
  };
  OdeState x0(4);
  x0 << spec.theta3, spec.theta4, spec.theta3_rate, spec.theta4_rate;
  Dopri5Options opt;
  opt.rtol = spec.rtol;
  opt.atol = spec.atol;
  opt.max_steps = spec.max_steps;
  Dopri5Stats stats;
  std::vector<OdeState> xs;
  try {
    xs = integrate_dopri5(rhs, 0.0, x0, times, opt, &stats);
  } catch (const std::runtime_error& e) {
    r.message = std::string("the pendulum integration failed: ") + e.what();
    return r;
  }
  if (progress) progress(0.9, "pendulum energy");
  r.steps_accepted = stats.accepted;
  r.steps_rejected = stats.rejected;
  r.evaluations = stats.evaluations;

  record_pendulum_motion(spec, chain, times, xs, r);
  r.status = Status::kSolved;
  r.message = pendulum_message(spec, r);
  r.run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  return r;
}

}  // namespace armstudy::studies
