// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/throwing/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "core/check.hpp"
#include "core/dynamics.hpp"
#include "core/integrators.hpp"
#include "studies/throwing/simulate_kernel.hpp"
#include "studies/throwing/tray_dynamics.hpp"

namespace armstudy::studies {
// the integrators of core/integrators.hpp
using core::Dopri5Options;
using core::Dopri5Stats;
using core::integrate_dopri5;
using core::OdeState;
namespace {

double sign(double x) { return x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0); }

// one evaluation of the planning model at (t, x) inside a stage
struct PointEval {
  OdeState dx;
  core::JointVector q, qd, qdd, tau;
  Eigen::Vector2d tau_m, rate;
  core::MotorSample ms[2];
  Eigen::Vector2d force;  // normal, tangential force of the tray on the ball
};

class Planner {
 public:
  Planner(const ThrowSetup& s, const VelocityProfile& p) : s_(s), p_(p) {
    B_ = motor_matrix(s.mount);
    if (!s.generic_dynamics && s.chain.num_links() == 4) fast_.emplace(s.chain);
    h_ = p.stage_length();
    // angles at each stage start (trapezoids)
    q_start_.resize(p.stages() + 1);
    q_start_[0] = p.q0;
    for (int k = 0; k < p.stages(); ++k)
      q_start_[k + 1] = q_start_[k] + 0.5 * h_ * (p.v.col(k) + p.v.col(k + 1));
  }

  void eval(int stage, double t, const OdeState& x, PointEval& out) const {
    const double tau = t - stage * h_;
    const Eigen::Vector2d v0 = p_.v.col(stage);
    const Eigen::Vector2d acc = (p_.v.col(stage + 1) - v0) / h_;
    const Eigen::Vector2d qa = q_start_[stage] + v0 * tau + 0.5 * acc * tau * tau;
    const Eigen::Vector2d qda = v0 + acc * tau;
    out.q.resize(4);
    out.qd.resize(4);
    out.q << qa, x[0], x[1];
    out.qd << qda, x[2], x[3];
    core::JointVector qdd_active(4);
    qdd_active << acc, 0.0, 0.0;
    // passive joints from the dynamics, active torques that realise the motion (and the
    // ball's contact forces): the one-pass fast path, or the generic chain (the reference)
    const core::MixedDynamics d =
        fast_ ? fast_->mixed(out.q, out.qd, qdd_active, s_.ball_mass, out.force)
              : core::passive_forward_dynamics(s_.chain, out.q, out.qd, qdd_active,
                                               core::JointVector::Zero(4));
    out.qdd = d.qdd;
    out.tau = d.tau;
    out.tau_m = motor_torques(s_.mount, d.tau);
    const Eigen::Matrix<double, 4, 1> qd4 = out.qd;
    const Eigen::Matrix<double, 4, 1> qdd4 = out.qdd;
    out.rate = B_ * qd4;
    const Eigen::Vector2d acc_m = B_ * qdd4;
    double power = 0.0;
    // eq. 5-6 per motor; rotor inertia is in the chain, so the motors' Im is 0 here
    for (int m = 0; m < 2; ++m) {
      out.ms[m] = core::motor_sample(s_.motor[m], out.rate[m], acc_m[m], out.tau_m[m]);
      power += s_.count_regeneration ? out.ms[m].power : std::max(0.0, out.ms[m].power);
    }
    if (!fast_) out.force = ball_contact_forces(s_.chain, s_.ball_mass, out.q, out.qd, out.qdd);
    out.dx.resize(5);
    out.dx << x[2], x[3], d.qdd[2], d.qdd[3], power;  // eq. 7 integrand as the fifth state
  }

 private:
  const ThrowSetup& s_;
  const VelocityProfile& p_;
  Eigen::Matrix<double, 2, 4> B_;
  double h_ = 0;
  std::vector<Eigen::Vector2d> q_start_;
  std::optional<TrayDynamics> fast_;
};

void record(const PointEval& pe, int stage, double t, double energy,
            std::vector<ThrowSample>* out) {
  ThrowSample s;
  s.t = t;
  s.stage = stage;
  s.q = pe.q;
  s.qd = pe.qd;
  s.qdd = pe.qdd;
  s.tau = pe.tau;
  s.tau_m = pe.tau_m;
  s.motor_rate = pe.rate;
  s.motor[0] = pe.ms[0];
  s.motor[1] = pe.ms[1];
  s.energy = energy;
  s.normal_force = pe.force[0];
  s.tangential_force = pe.force[1];
  out->push_back(s);
}

}  // namespace

Eigen::Vector2d ball_contact_forces(const core::PlanarChain& chain, double ball_mass,
                                    const core::JointVector& q, const core::JointVector& qd,
                                    const core::JointVector& qdd) {
  // ball centre p = sum_i L_i e(phi_i), phi_i = base + q_1 + .. + q_i; its acceleration
  // a = sum_i L_i (phi_i'' e(phi_i)^perp - phi_i'^2 e(phi_i))
  double phi = chain.base_angle, w = 0.0, al = 0.0;
  Eigen::Vector2d a = Eigen::Vector2d::Zero();
  const int n = static_cast<int>(chain.links.size());
  for (int i = 0; i < n; ++i) {
    phi += q[i];
    w += qd[i];
    al += qdd[i];
    const Eigen::Vector2d e(std::cos(phi), std::sin(phi)), ep(-std::sin(phi), std::cos(phi));
    a += chain.links[i].length * (al * ep - w * w * e);
  }
  // n: from the centre of the ball's circle to the ball's centre (the last link's axis)
  const Eigen::Vector2d nn(std::cos(phi), std::sin(phi)), tt(-std::sin(phi), std::cos(phi));
  const Eigen::Vector2d g(0.0, -chain.gravity);
  // m a = -N n + F_t t + m g
  return {ball_mass * (g - a).dot(nn), ball_mass * (a - g).dot(tt)};
}

const char* constraint_name(ConstraintKind k) {
  switch (k) {
    case ConstraintKind::kContact: return "contact force";
    case ConstraintKind::kFriction: return "friction needed";
    case ConstraintKind::kTray: return "tray angle";
    case ConstraintKind::kVoltage: return "voltage";
    case ConstraintKind::kCurrent: return "current";
    case ConstraintKind::kPower: return "power";
    case ConstraintKind::kRelease: return "release angle";
  }
  return "?";
}

namespace {

// the 6 constraint values of stage k, in the order of ConstraintKind (constraint_values)
void stage_constraint_values(const ThrowSetup& s, const ProfileEvaluation& e, int k, double backoff,
                             double g[6]) {
  const double weight = s.ball_mass * s.chain.gravity;
  g[0] = (s.contact_margin - e.stage_normal[k]) / weight + backoff;
  g[1] = e.stage_friction[k] / weight + backoff;
  g[2] = (e.stage_theta4[k] - s.half_width) / s.half_width + backoff;
  g[3] = (e.stage_voltage[k] - s.voltage_max) / s.voltage_max + backoff;
  g[4] = (e.stage_current[k] - s.current_max) / s.current_max + backoff;
  g[5] = (e.stage_power[k] - s.power_max) / s.power_max + backoff;
}

}  // namespace

std::vector<double> constraint_values(const ThrowSetup& s, const ProfileEvaluation& e,
                                      double backoff) {
  const int P = static_cast<int>(e.stage_theta4.size());
  std::vector<double> g(6 * P + 1, 1e3);
  if (!e.finite) return g;
  for (int k = 0; k < P; ++k) {
    double gk[6];
    stage_constraint_values(s, e, k, backoff, gk);
    for (int c = 0; c < 6; ++c) g[c * P + k] = gk[c];
  }
  g[6 * size_t(P)] =
      (std::abs(e.theta3_final - s.theta3_release) - s.release_tolerance) / s.release_tolerance +
      backoff;
  return g;
}

std::array<double, kConstraintKinds> worst_constraints(const ThrowSetup& s,
                                                       const ProfileEvaluation& e) {
  const std::vector<double> g = constraint_values(s, e, 0.0);
  const int P = static_cast<int>(e.stage_theta4.size());
  std::array<double, kConstraintKinds> w;
  w.fill(-INFINITY);
  for (int c = 0; c < 6; ++c)
    for (int k = 0; k < P; ++k) w[c] = std::max(w[c], g[c * P + k]);
  w[6] = g[6 * size_t(P)];
  return w;
}

void reset_stage_extremes(int P, ProfileEvaluation& e) {
  e.stage_theta4.assign(P, 0.0);
  e.stage_voltage.assign(P, 0.0);
  e.stage_current.assign(P, 0.0);
  e.stage_power.assign(P, 0.0);
  e.stage_normal.assign(P, INFINITY);
  e.stage_friction.assign(P, -INFINITY);
}

void classify(const ThrowSetup& s, ProfileEvaluation& e, double backoff) {
  e.violation = 0.0;
  for (double g : constraint_values(s, e, backoff)) e.violation += std::max(0.0, g);
  e.feasible = e.finite && e.violation == 0.0;
}

void finish_finite(const ThrowSetup& setup, const double* x, double backoff,
                   ProfileEvaluation& ev) {
  ev.max_abs_theta4 = *std::max_element(ev.stage_theta4.begin(), ev.stage_theta4.end());
  ev.max_voltage = *std::max_element(ev.stage_voltage.begin(), ev.stage_voltage.end());
  ev.max_current = *std::max_element(ev.stage_current.begin(), ev.stage_current.end());
  ev.max_power = *std::max_element(ev.stage_power.begin(), ev.stage_power.end());
  ev.min_normal_force = *std::min_element(ev.stage_normal.begin(), ev.stage_normal.end());
  ev.max_friction_excess = *std::max_element(ev.stage_friction.begin(), ev.stage_friction.end());
  ev.energy = x[4];
  ev.theta3_final = x[0];
  ev.theta4_final = x[1];
  ev.theta3_rate_final = x[2];
  ev.theta4_rate_final = x[3];
  classify(setup, ev, backoff);
}

namespace {

// the per-stage extremes of P stages at their neutral values; with `from`, stage `first`'s
// state and the stages before it copied from its evaluation. Returns the first stage to run.
int start_stages(int P, const SimulationCheckpoints* from, int first, ProfileEvaluation& ev,
                 OdeState& x) {
  reset_stage_extremes(P, ev);
  ev.max_friction_ratio = 0.0;
  if (!from) return 0;
  const int k0 = first;
  x = from->x[k0];
  ev.max_friction_ratio = from->friction_ratio[k0];
  const ProfileEvaluation& b = from->evaluation;
  for (int k = 0; k < k0; ++k) {
    ev.stage_theta4[k] = b.stage_theta4[k];
    ev.stage_voltage[k] = b.stage_voltage[k];
    ev.stage_current[k] = b.stage_current[k];
    ev.stage_power[k] = b.stage_power[k];
    ev.stage_normal[k] = b.stage_normal[k];
    ev.stage_friction[k] = b.stage_friction[k];
  }
  return k0;
}

// the evaluation of a simulation that stopped (a constraint certainly violated), diverged
// or ran to the end at state x
void finish_simulation(const ThrowSetup& setup, OdeState& x, double backoff,
                       ProfileEvaluation& ev) {
  if (ev.stopped) {
    ev.energy = std::numeric_limits<double>::max() / 4;
    ev.violation = INFINITY;
    ev.feasible = false;
    return;
  }
  if (!ev.finite) {
    ev.energy = std::numeric_limits<double>::max() / 4;
    ev.max_friction_ratio = INFINITY;
    classify(setup, ev, backoff);
    return;
  }
  finish_finite(setup, &x[0], backoff, ev);
}

// simulate_profile; with `from`, resumes at stage `first` from its state (the stages before
// copied from its evaluation); with `save`, stores the state at every stage start
// (over 60 lines, kept whole: the loop of core::rk4_step steps over the stages with its
// tracking of the limits, read as one integration)
ProfileEvaluation simulate(const ThrowSetup& setup, const VelocityProfile& profile,
                           std::vector<ThrowSample>* samples, double backoff,
                           bool stop_when_infeasible, const SimulationCheckpoints* from, int first,
                           SimulationCheckpoints* save) {
  if (!samples && setup.kernel_lanes > 0 && kernel_applies(setup))
    return simulate_kernel(setup, profile, backoff, stop_when_infeasible, from, first, save);
  const Planner planner(setup, profile);
  const int P = profile.stages();
  const double h = profile.stage_length();
  const int n = std::max(1, setup.steps_per_stage);
  const double dt = h / n;
  ProfileEvaluation ev;
  OdeState x(5);
  x << setup.theta3_0, setup.theta4_0, 0.0, 0.0, 0.0;
  PointEval k1, kj;  // an RK4 step's first stage (tracked), its later ones
  const int k0 = start_stages(P, from, first, ev, x);
  if (save) {
    save->profile = profile;
    save->x.clear();
    save->friction_ratio.clear();
  }
  int stage = 0;
  auto track = [&](const PointEval& pe) {
    ev.stage_theta4[stage] = std::max(ev.stage_theta4[stage], std::abs(pe.q[3]));
    for (int m = 0; m < 2; ++m) {
      ev.stage_voltage[stage] = std::max(ev.stage_voltage[stage], std::abs(pe.ms[m].voltage));
      ev.stage_current[stage] = std::max(ev.stage_current[stage], std::abs(pe.ms[m].current));
      ev.stage_power[stage] = std::max(ev.stage_power[stage], std::abs(pe.ms[m].power));
    }
    const double N = pe.force[0], Ft = std::abs(pe.force[1]);
    ev.stage_normal[stage] = std::min(ev.stage_normal[stage], N);
    ev.stage_friction[stage] =
        std::max(ev.stage_friction[stage], Ft - setup.friction_coefficient * N);
    ev.max_friction_ratio = std::max(ev.max_friction_ratio, N > 0 ? Ft / N : INFINITY);
  };
  // is a constraint of the current stage already certainly violated?
  auto violated = [&] {
    double g[6];
    stage_constraint_values(setup, ev, stage, backoff, g);
    for (double v : g)
      if (v > 0) return true;
    return false;
  };
  // the right-hand side inside the current stage
  auto stage_rhs = [&](double t, const OdeState& y) {
    planner.eval(stage, t, y, kj);
    return kj.dx;
  };
  if (samples) samples->clear();
  for (int k = k0; k < P && ev.finite && !ev.stopped; ++k) {
    stage = k;
    if (save) {
      save->x.push_back(x);
      save->friction_ratio.push_back(ev.max_friction_ratio);
    }
    for (int j = 0; j < n; ++j) {
      const double t = k * h + j * dt;
      // core::rk4_step inside stage k (the accelerations are constant there) from its
      // first stage, where the limits are tracked
      planner.eval(k, t, x, k1);
      track(k1);
      if (samples) record(k1, k, t, x[4], samples);
      if (stop_when_infeasible && violated()) {
        ev.stopped = true;
        break;
      }
      x = core::rk4_step(stage_rhs, t, x, k1.dx, dt);
      if (!x.allFinite() || std::abs(x[2]) > 1e4 || std::abs(x[3]) > 1e4) {
        ev.finite = false;
        break;
      }
    }
    if (!ev.finite || ev.stopped) break;
    // the end of the stage with this stage's accelerations (left limit at the node)
    planner.eval(k, (k + 1) * h, x, k1);
    track(k1);
    if (samples) record(k1, k, (k + 1) * h, x[4], samples);
    if (stop_when_infeasible && violated()) {
      ev.stopped = true;
      break;
    }
  }
  finish_simulation(setup, x, backoff, ev);
  return ev;
}

}  // namespace

ProfileEvaluation simulate_profile(const ThrowSetup& setup, const VelocityProfile& profile,
                                   std::vector<ThrowSample>* samples, double backoff,
                                   bool stop_when_infeasible) {
  return simulate(setup, profile, samples, backoff, stop_when_infeasible, nullptr, 0, nullptr);
}

ProfileEvaluation simulate_profile(const ThrowSetup& setup, const VelocityProfile& profile,
                                   SimulationCheckpoints& save, double backoff) {
  save.evaluation = simulate(setup, profile, nullptr, backoff, false, nullptr, 0, &save);
  return save.evaluation;
}

namespace {

// simulate_profile_from's condition on the profile and the point it resumes at
void check_resume(const VelocityProfile& profile, const SimulationCheckpoints& base,
                  int first_stage) {
  const VelocityProfile& b = base.profile;
  ARM_THROW_UNLESS(first_stage >= 0 && first_stage < profile.stages() &&
                       profile.stages() == b.stages() && profile.tf == b.tf && profile.q0 == b.q0 &&
                       profile.v.leftCols(first_stage + 1) == b.v.leftCols(first_stage + 1),
                   "a simulation resumes at stage " << first_stage
                                                    << " only if the nodes up to it are the same");
}

}  // namespace

ProfileEvaluation simulate_profile_from(const ThrowSetup& setup, const VelocityProfile& profile,
                                        const SimulationCheckpoints& base, int first_stage,
                                        double backoff) {
  check_resume(profile, base, first_stage);
  if (first_stage == 0 || first_stage >= static_cast<int>(base.x.size()))
    return simulate(setup, profile, nullptr, backoff, false, nullptr, 0, nullptr);
  return simulate(setup, profile, nullptr, backoff, false, &base, first_stage, nullptr);
}

void simulate_group_from(const ThrowSetup& setup,
                         const std::vector<const VelocityProfile*>& profiles,
                         const SimulationCheckpoints& base, int first_stage, double backoff,
                         ProfileEvaluation* out) {
  for (const VelocityProfile* p : profiles) check_resume(*p, base, first_stage);
  if (setup.kernel_lanes < 2 || !kernel_applies(setup)) {
    for (size_t i = 0; i < profiles.size(); ++i)
      out[i] = simulate_profile_from(setup, *profiles[i], base, first_stage, backoff);
    return;
  }
  const bool resume = first_stage > 0 && first_stage < static_cast<int>(base.x.size());
  simulate_kernel_lanes(setup, profiles, setup.kernel_lanes, backoff, false, out,
                        resume ? &base : nullptr, resume ? first_stage : 0);
}

Eigen::Vector2d VoltageHistory::at(int st, double time) const {
  // samples of this stage: contiguous
  const auto lo = std::lower_bound(stage.begin(), stage.end(), st) - stage.begin();
  const auto hi = std::upper_bound(stage.begin(), stage.end(), st) - stage.begin();
  if (lo >= hi) throw std::invalid_argument("voltage history has no sample in a stage");
  if (time <= t[lo]) return e[lo];
  if (time >= t[hi - 1]) return e[hi - 1];
  const auto it = std::upper_bound(t.begin() + lo, t.begin() + hi, time) - t.begin();
  const size_t b = static_cast<size_t>(it), a = b - 1;
  const double w = (time - t[a]) / (t[b] - t[a]);
  return (1.0 - w) * e[a] + w * e[b];
}

VoltageHistory voltage_history(const std::vector<ThrowSample>& samples) {
  VoltageHistory v;
  for (const ThrowSample& s : samples) {
    v.t.push_back(s.t);
    v.stage.push_back(s.stage);
    v.e.emplace_back(s.motor[0].voltage, s.motor[1].voltage);
  }
  if (!samples.empty()) {
    v.tf = samples.back().t;
    v.stages = samples.back().stage + 1;
  }
  return v;
}

ReplayResult replay_voltages(const ThrowSetup& setup, const VoltageHistory& voltages,
                             const core::JointVector& q0, const core::JointVector& qd0,
                             const std::vector<double>& times, double rtol, double atol,
                             double sign_band) {
  const Eigen::Matrix<double, 2, 4> B = motor_matrix(setup.mount);
  ReplayResult out;
  OdeState x(8);
  x << q0, qd0;
  Dopri5Options opt;
  opt.rtol = rtol;
  opt.atol = atol;
  const double h = voltages.tf / voltages.stages;
  size_t next = 0;
  // requested times at t = 0
  while (next < times.size() && times[next] <= 0.0) {
    out.t.push_back(times[next++]);
    out.q.push_back(x.head(4));
    out.qd.push_back(x.tail(4));
  }
  for (int k = 0; k < voltages.stages; ++k) {
    const double t_end = (k + 1) * h;
    auto rhs = [&](double t, const OdeState& s) {
      const core::JointVector q = s.head(4), qd = s.tail(4);
      const Eigen::Matrix<double, 4, 1> qd4 = s.tail(4);
      const Eigen::Vector2d rate = B * qd4;
      const Eigen::Vector2d e = voltages.at(k, t);
      Eigen::Vector2d tau_m;
      // eq. 5 solved for the load torque (Im = 0: rotors are in the chain)
      for (int m = 0; m < 2; ++m) {
        const core::DcMotor& mo = setup.motor[m];
        // coulomb friction smoothed over |qd_m| < sign_band: an exact sign makes the replay
        // chatter wherever a joint comes to rest (sticking), which no ODE solver resolves
        const double sg = sign_band > 0 ? std::tanh(rate[m] / sign_band) : sign(rate[m]);
        tau_m[m] = (mo.kt / mo.Ra) * (e[m] - mo.kv * rate[m]) - mo.Dm * rate[m] - mo.tau_f * sg;
      }
      const core::JointVector qdd =
          core::forward_dynamics(setup.chain, q, qd, joint_torques(setup.mount, tau_m));
      OdeState dx(8);
      dx << qd, qdd;
      return dx;
    };
    std::vector<double> ts;
    const size_t first = next;
    while (next < times.size() &&
           (times[next] < t_end || (k + 1 == voltages.stages && times[next] <= t_end + 1e-12)))
      ts.push_back(times[next++]);
    ts.push_back(t_end);
    Dopri5Stats st;
    const std::vector<OdeState> xs = integrate_dopri5(rhs, k * h, x, ts, opt, &st);
    out.steps += st.accepted;
    for (size_t i = 0; i + 1 < xs.size(); ++i) {
      out.t.push_back(times[first + i]);
      out.q.push_back(xs[i].head(4));
      out.qd.push_back(xs[i].tail(4));
    }
    x = xs.back();
  }
  return out;
}

}  // namespace armstudy::studies
