// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/throwing/throw_gradient.hpp"

#include <unsupported/Eigen/AutoDiff>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/check.hpp"
#include "core/dc_motor.hpp"
#include "core/integrators.hpp"
#include "studies/throwing/tray_dynamics.hpp"
#include "studies/tray_arm.hpp"

namespace armstudy::studies {
namespace {

// the right-hand side's inputs z: the 4 joint angles, the 4 joint rates, the 2 active
// accelerations
constexpr int kInputs = 10;
using SensInputs = Eigen::Matrix<double, kInputs, 1>;
using SensAd = Eigen::AutoDiffScalar<SensInputs>;
using SensState = Eigen::Matrix<double, 5, Eigen::Dynamic>;        // dx/dp
using SensInput = Eigen::Matrix<double, kInputs, Eigen::Dynamic>;  // dz/dp

// the quantities a sample tracks, after the right-hand side's 5 rows
enum SensRow { kVolt0 = 5, kVolt1, kCurr0, kCurr1, kPow0, kPow1, kNormal, kTangent, kSensRows };

// one evaluation of the planning model (the Planner of simulate.cpp) with the derivatives
// of its outputs with respect to z
struct SensEval {
  double value[kSensRows];
  Eigen::Matrix<double, kSensRows, kInputs> J;
  core::OdeState dx;
};

double sens_sign(double x) { return x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0); }

// the right-hand side of the Planner (simulate.cpp) at inputs z, through tray_detail::mixed
// and core::motor_electrics instantiated with SensAd
void sens_eval(const ThrowSetup& s, const TrayDynamics& dyn, const double* z, SensEval& out) {
  constexpr int kSensJoints = tray_detail::kTrayJoints;
  SensAd q[kSensJoints], qd[kSensJoints], acc[kSensJoints], qdd[kSensJoints], tau[kSensJoints],
      force[2];
  for (int i = 0; i < kSensJoints; ++i) {
    q[i] = SensAd(z[i], kInputs, i);
    qd[i] = SensAd(z[kSensJoints + i], kInputs, kSensJoints + i);
    tau[i] = SensAd(0.0);
  }
  acc[0] = SensAd(z[8], kInputs, 8);
  acc[1] = SensAd(z[9], kInputs, 9);
  acc[2] = acc[3] = SensAd(0.0);
  tray_detail::mixed(dyn.chain(), dyn.bodies(), dyn.body_count(), q, qd, acc, s.ball_mass, qdd, tau,
                     force);
  const Eigen::Matrix<double, 2, 4> B = motor_matrix(s.mount);
  const double b = s.mount == Motor2Mount::kOnBase ? 1.0 : 0.0;
  const SensAd tau_m[2] = {tau[0] - b * tau[1], tau[1]};  // motor_torques
  SensAd power = SensAd(0.0);
  for (int m = 0; m < 2; ++m) {
    SensAd rate = B(m, 0) * qd[0], acc_m = B(m, 0) * qdd[0];
    for (int i = 1; i < kSensJoints; ++i) {
      rate += B(m, i) * qd[i];
      acc_m += B(m, i) * qdd[i];
    }
    SensAd e, i_m;
    core::motor_electrics(s.motor[m], rate, acc_m, tau_m[m], e, i_m);
    const SensAd p = e * i_m;
    power += s.count_regeneration ? p : (0.0 < p ? p : SensAd(0.0));
    const SensAd* rows[3] = {&e, &i_m, &p};
    for (int r = 0; r < 3; ++r) {
      out.value[kVolt0 + 2 * r + m] = rows[r]->value();
      out.J.row(kVolt0 + 2 * r + m) = rows[r]->derivatives().transpose();
    }
  }
  const SensAd* f[5] = {&qd[2], &qd[3], &qdd[2], &qdd[3], &power};
  out.dx.resize(5);
  for (int r = 0; r < 5; ++r) {
    out.value[r] = out.dx[r] = f[r]->value();
    out.J.row(r) = f[r]->derivatives().transpose();
  }
  for (int r = 0; r < 2; ++r) {
    out.value[kNormal + r] = force[r].value();
    out.J.row(kNormal + r) = force[r].derivatives().transpose();
  }
}

// the running worst sample of each stage constraint kind and its derivative
struct SensWorst {
  double value;
  Eigen::RowVectorXd grad;
};

class ThrowSensitivity {
 public:
  ThrowSensitivity(const ThrowSetup& s, const VelocityProfile& p, bool per_sample)
      : s_(s),
        p_(p),
        dyn_(s.chain),
        P_(p.stages()),
        n_(2 * (p.stages() - 1)),
        per_sample_(per_sample) {
    h_ = p.stage_length();
    q_start_.resize(P_ + 1);
    q_start_[0] = p.q0;
    for (int k = 0; k < P_; ++k)
      q_start_[k + 1] = q_start_[k] + 0.5 * h_ * (p.v.col(k) + p.v.col(k + 1));
  }

  ThrowDerivatives run(double backoff);

 private:
  // the inputs z at time t of `stage` and state x (the Planner's eval)
  void inputs(int stage, double t, const core::OdeState& x, double z[kInputs]) const {
    const double tau = t - stage * h_;
    for (int j = 0; j < 2; ++j) {
      const double v0 = p_.v(j, stage);
      const double acc = (p_.v(j, stage + 1) - v0) / h_;
      z[j] = q_start_[stage][j] + v0 * tau + 0.5 * acc * tau * tau;
      z[4 + j] = v0 + acc * tau;
      z[8 + j] = acc;
    }
    z[2] = x[0];
    z[3] = x[1];
    z[6] = x[2];
    z[7] = x[3];
  }
  // dz/dp at time t of `stage` for the passive state's sensitivity S (its first nc columns)
  void input_tangent(int stage, double t, const SensState& S, int nc, SensInput& Z) const;
  void track(int stage, const SensEval& e, const core::OdeState& x, const SensState& S,
             const SensInput& Z, int nc);
  void step_sensitivity(int stage, double t, double dt, const SensEval* k, const SensInput& Z1,
                        int nc, SensState& S) const;
  ThrowDerivatives finish(const core::OdeState& x, const SensState& S, double backoff);
  void sample_rows(int stage, const SensEval& e, const core::OdeState& x, const SensState& S,
                   const SensInput& Z, int nc);

  const ThrowSetup& s_;
  const VelocityProfile& p_;
  const TrayDynamics dyn_;
  const int P_, n_;
  const bool per_sample_;
  double backoff_ = 0;
  std::vector<double> sample_values_;
  std::vector<Eigen::RowVectorXd> sample_grads_;  // the first columns(stage) entries only
  std::vector<int> sample_stage_;
  double h_ = 0;
  std::vector<Eigen::Vector2d> q_start_;
  ProfileEvaluation ev_;
  std::vector<SensWorst> worst_;  // 6 per stage, in the order of ConstraintKind
};

void ThrowSensitivity::input_tangent(int stage, double t, const SensState& S, int nc,
                                     SensInput& Z) const {
  Z.setZero(kInputs, nc);
  const double tau = t - stage * h_;
  for (int j = 0; j < 2; ++j) {
    // node m's rate of joint j is column 2 (m - 1) + j; the angle at the stage start is the
    // trapezoids' sum (h for the nodes before `stage`, h / 2 for `stage` itself)
    for (int m = 1; m < stage; ++m) Z(j, 2 * (m - 1) + j) = h_;
    const double wk = tau - 0.5 * tau * tau / h_, wk1 = 0.5 * tau * tau / h_;
    if (stage >= 1) {
      const int c = 2 * (stage - 1) + j;
      Z(j, c) = 0.5 * h_ + wk;
      Z(4 + j, c) = 1.0 - tau / h_;
      Z(8 + j, c) = -1.0 / h_;
    }
    if (stage + 1 <= P_ - 1) {
      const int c = 2 * stage + j;
      Z(j, c) = wk1;
      Z(4 + j, c) = tau / h_;
      Z(8 + j, c) = 1.0 / h_;
    }
  }
  Z.row(2) = S.row(0).leftCols(nc);
  Z.row(3) = S.row(1).leftCols(nc);
  Z.row(6) = S.row(2).leftCols(nc);
  Z.row(7) = S.row(3).leftCols(nc);
}

// the Planner's track (simulate.cpp): each running worst and, where a sample becomes it,
// that sample's derivative
void ThrowSensitivity::track(int stage, const SensEval& e, const core::OdeState& x,
                             const SensState& S, const SensInput& Z, int nc) {
  SensWorst* w = &worst_[6 * size_t(stage)];
  // std::max(worst, v), the sample's derivative (grad()) only only when it becomes the worst
  auto raise = [&](SensWorst& wk, double v, auto grad) {
    if (wk.value < v) {
      wk.value = v;
      wk.grad.setZero(n_);
      wk.grad.leftCols(nc) = grad();
    }
  };
  const double t4 = x[1];
  raise(w[2], std::abs(t4),
        [&] { return Eigen::RowVectorXd(sens_sign(t4) * S.row(1).leftCols(nc)); });
  for (int m = 0; m < 2; ++m)
    for (int r = 0; r < 3; ++r) {
      const int row = kVolt0 + 2 * r + m;
      const double v = e.value[row];
      raise(w[3 + r], std::abs(v),
            [&] { return Eigen::RowVectorXd(sens_sign(v) * (e.J.row(row) * Z)); });
    }
  const double N = e.value[kNormal], Ft = e.value[kTangent];
  if (N < w[0].value) {  // std::min(worst, N): the contact constraint's worst is N's least
    w[0].value = N;
    w[0].grad.setZero(n_);
    w[0].grad.leftCols(nc) = e.J.row(kNormal) * Z;
  }
  const double mu = s_.friction_coefficient;
  raise(w[1], std::abs(Ft) - mu * N, [&] {
    return Eigen::RowVectorXd((sens_sign(Ft) * e.J.row(kTangent) - mu * e.J.row(kNormal)) * Z);
  });
  ev_.max_friction_ratio =
      std::max(ev_.max_friction_ratio, N > 0 ? std::abs(Ft) / N : double(INFINITY));
  if (per_sample_) sample_rows(stage, e, x, S, Z, nc);
}

// the sample's own constraint rows (kSampleRows), normalised as stage_constraint_values
void ThrowSensitivity::sample_rows(int stage, const SensEval& e, const core::OdeState& x,
                                   const SensState& S, const SensInput& Z, int nc) {
  const double weight = s_.ball_mass * s_.chain.gravity, b = backoff_;
  const double N = e.value[kNormal], Ft = e.value[kTangent], mu = s_.friction_coefficient;
  const double t4 = x[1];
  sample_stage_.push_back(stage);
  auto add = [&](double v, const Eigen::RowVectorXd& g) {
    sample_values_.push_back(v);
    sample_grads_.push_back(g);
  };
  add((s_.contact_margin - N) / weight + b, -(e.J.row(kNormal) * Z) / weight);
  add((std::abs(Ft) - mu * N) / weight + b,
      ((sens_sign(Ft) * e.J.row(kTangent) - mu * e.J.row(kNormal)) * Z) / weight);
  add((std::abs(t4) - s_.half_width) / s_.half_width + b,
      sens_sign(t4) * S.row(1).leftCols(nc) / s_.half_width);
  const double limit[3] = {s_.voltage_max, s_.current_max, s_.power_max};
  for (int m = 0; m < 2; ++m)
    for (int r = 0; r < 3; ++r) {
      const int row = kVolt0 + 2 * r + m;
      const double v = e.value[row];
      add((std::abs(v) - limit[r]) / limit[r] + b, sens_sign(v) * (e.J.row(row) * Z) / limit[r]);
    }
}

// S over one RK4 step from t: k[0 .. 3] the step's evaluations, Z1 the first one's dz/dp
void ThrowSensitivity::step_sensitivity(int stage, double t, double dt, const SensEval* k,
                                        const SensInput& Z1, int nc, SensState& S) const {
  const Eigen::Matrix<double, 5, Eigen::Dynamic> S0 = S.leftCols(nc);
  SensInput Z;
  Eigen::Matrix<double, 5, Eigen::Dynamic> dk[4], Si;
  dk[0] = k[0].J.topRows(5) * Z1;
  const double c[3] = {0.5 * dt, 0.5 * dt, dt}, ts[3] = {t + 0.5 * dt, t + 0.5 * dt, t + dt};
  for (int i = 1; i < 4; ++i) {
    Si = S0 + c[i - 1] * dk[i - 1];
    input_tangent(stage, ts[i - 1], Si, nc, Z);
    dk[i] = k[i].J.topRows(5) * Z;
  }
  S.leftCols(nc) = S0 + (dt / 6.0) * (dk[0] + 2.0 * dk[1] + 2.0 * dk[2] + dk[3]);
}

ThrowDerivatives ThrowSensitivity::run(double backoff) {
  backoff_ = backoff;
  const int steps = std::max(1, s_.steps_per_stage);
  const double dt = h_ / steps;
  reset_stage_extremes(P_, ev_);
  worst_.assign(6 * size_t(P_), SensWorst{0.0, Eigen::RowVectorXd::Zero(n_)});
  for (int k = 0; k < P_; ++k) {
    worst_[6 * size_t(k)].value = INFINITY;
    worst_[6 * size_t(k) + 1].value = -INFINITY;
  }
  core::OdeState x(5);
  x << s_.theta3_0, s_.theta4_0, 0.0, 0.0, 0.0;
  SensState S = SensState::Zero(5, n_);
  SensEval k[4];
  SensInput Z1;
  double z[kInputs];
  for (int st = 0; st < P_ && ev_.finite; ++st) {
    const int nc = std::min(n_, 2 * st + 2);  // the nodes up to st + 1
    for (int j = 0; j < steps; ++j) {
      const double t = st * h_ + j * dt;
      inputs(st, t, x, z);
      sens_eval(s_, dyn_, z, k[0]);
      input_tangent(st, t, S, nc, Z1);
      track(st, k[0], x, S, Z1, nc);
      int next = 1;
      auto rhs = [&](double ti, const core::OdeState& y) {
        inputs(st, ti, y, z);
        sens_eval(s_, dyn_, z, k[next]);
        return k[next++].dx;
      };
      x = core::rk4_step(rhs, t, x, k[0].dx, dt);
      step_sensitivity(st, t, dt, k, Z1, nc, S);
      if (!x.allFinite() || std::abs(x[2]) > 1e4 || std::abs(x[3]) > 1e4) {
        ev_.finite = false;
        break;
      }
    }
    if (!ev_.finite) break;
    // the end of the stage with this stage's accelerations (left limit at the node)
    inputs(st, (st + 1) * h_, x, z);
    sens_eval(s_, dyn_, z, k[0]);
    input_tangent(st, (st + 1) * h_, S, nc, Z1);
    track(st, k[0], x, S, Z1, nc);
  }
  return finish(x, S, backoff);
}

ThrowDerivatives ThrowSensitivity::finish(const core::OdeState& x, const SensState& S,
                                          double backoff) {
  ThrowDerivatives d;
  d.energy_gradient = Eigen::VectorXd::Zero(n_);
  d.constraint_jacobian = Eigen::MatrixXd::Zero(6 * P_ + 1, n_);
  for (int k = 0; k < P_; ++k) {
    const SensWorst* w = &worst_[6 * size_t(k)];
    ev_.stage_normal[k] = w[0].value;
    ev_.stage_friction[k] = w[1].value;
    ev_.stage_theta4[k] = w[2].value;
    ev_.stage_voltage[k] = w[3].value;
    ev_.stage_current[k] = w[4].value;
    ev_.stage_power[k] = w[5].value;
  }
  if (!ev_.finite) {
    ev_.energy = std::numeric_limits<double>::max() / 4;
    ev_.max_friction_ratio = INFINITY;
    classify(s_, ev_, backoff);
    d.evaluation = ev_;
    d.constraints = constraint_values(s_, ev_, backoff);
    return d;
  }
  finish_finite(s_, x.data(), backoff, ev_);
  d.evaluation = ev_;
  d.constraints = constraint_values(s_, ev_, backoff);
  d.energy_gradient = S.row(4).transpose();
  const double weight = s_.ball_mass * s_.chain.gravity;
  const double scale[6] = {-1.0 / weight,        1.0 / weight,         1.0 / s_.half_width,
                           1.0 / s_.voltage_max, 1.0 / s_.current_max, 1.0 / s_.power_max};
  for (int k = 0; k < P_; ++k)
    for (int c = 0; c < 6; ++c)
      d.constraint_jacobian.row(Eigen::Index(c) * P_ + k) =
          scale[c] * worst_[6 * size_t(k) + c].grad;
  d.constraint_jacobian.row(6 * Eigen::Index(P_)) =
      (sens_sign(x[0] - s_.theta3_release) / s_.release_tolerance) * S.row(0);
  if (per_sample_) {
    d.sample_constraints = std::move(sample_values_);
    d.sample_stage = std::move(sample_stage_);
    d.sample_jacobian = Eigen::MatrixXd::Zero(Eigen::Index(sample_grads_.size()), n_);
    for (size_t r = 0; r < sample_grads_.size(); ++r)
      d.sample_jacobian.row(Eigen::Index(r)).leftCols(sample_grads_[r].size()) = sample_grads_[r];
  }
  return d;
}

}  // namespace

bool derivatives_apply(const ThrowSetup& s) {
  const core::PlanarChain& c = s.chain;
  return c.num_links() == tray_detail::kTrayJoints && c.links[0].active && c.links[1].active &&
         !c.links[2].active && !c.links[3].active &&
         c.num_links() + static_cast<int>(c.point_masses.size()) <= core::kMaxLinks * 2;
}

ThrowDerivatives throw_derivatives(const ThrowSetup& setup, const VelocityProfile& profile,
                                   double backoff, bool per_sample) {
  ARM_THROW_UNLESS(
      derivatives_apply(setup),
      "exact derivatives need the tray arm's chain (joints 1, 2 active, 3, 4 passive)");
  ARM_THROW_UNLESS(profile.stages() >= 2,
                   "exact derivatives need >= 2 stages, the profile has " << profile.stages());
  ThrowSensitivity sens(setup, profile, per_sample);
  return sens.run(backoff);
}

}  // namespace armstudy::studies
