// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// One property harness for the fast paths: random chains, states and motions (std::mt19937,
// fixed seeds), and each specialised implementation against the one reference, the generic
// chain's dynamics of core/dynamics.hpp, itself held to MuJoCo's mj_inverse on the same
// random chains (as Pinocchio checks CRBA against RNEA on random configurations):
// - the placement study's closed-form sample (arm2_sample) and its blocked, vectorised form
//   (sample_block);
// - the time-optimal study's path dynamics (a s'' + b s'^2 + c) and its inverse dynamics;
// - the throwing study's one-pass tray dynamics (TrayDynamics::mixed, with the ball's
//   contact forces);
// - the throwing kernel's simulation (its own RK4 loop, DC motor and energy), against the
//   planning model written out here on the references: core::rk4_step, core dynamics and
//   core::motor_sample.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/dc_motor.hpp"
#include "core/dynamics.hpp"
#include "core/integrators.hpp"
#include "core/kinematics.hpp"
#include "scene/mujoco_check.hpp"
#include "studies/placement/arm2.hpp"
#include "studies/placement/arm2_block.hpp"
#include "studies/throwing/profile.hpp"
#include "studies/throwing/simulate.hpp"
#include "studies/throwing/solve.hpp"
#include "studies/throwing/tray_dynamics.hpp"
#include "studies/time_optimal/two_link_dynamics.hpp"
#include "studies/tray_arm.hpp"

namespace armstudy {
namespace {

double harness_uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

core::JointVector harness_vector(std::mt19937& rng, int n, double scale) {
  core::JointVector v(n);
  for (int i = 0; i < n; ++i) v[i] = harness_uniform(rng, -scale, scale);
  return v;
}

// |a - b| within rel of the larger magnitude (and of `floor`)
::testing::AssertionResult harness_close(const core::JointVector& a, const core::JointVector& b,
                                         double rel, double floor = 1e-12) {
  const double scale = std::max({a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff(), floor});
  const double err = (a - b).cwiseAbs().maxCoeff();
  if (err <= rel * scale) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "[" << a.transpose() << "] vs [" << b.transpose()
                                       << "]: error " << err << " > " << rel << " x " << scale;
}

// a random chain of n links: lengths, masses, centres of mass on and off the axis,
// inertias, point masses and a spinner (a rotor), gravity and base angle as given
core::PlanarChain harness_chain(std::mt19937& rng, int n, double gravity, double base_angle) {
  core::PlanarChain c;
  for (int i = 0; i < n; ++i) {
    core::Link l;
    l.length = harness_uniform(rng, 0.1, 0.6);
    l.mass = harness_uniform(rng, 0.1, 3.0);
    l.com = harness_uniform(rng, 0.0, l.length);
    l.com_lateral = harness_uniform(rng, -0.05, 0.05);
    l.inertia = harness_uniform(rng, 1e-4, 0.05);
    c.links.push_back(l);
    if (harness_uniform(rng, 0, 1) < 0.7)
      c.point_masses.push_back({i, harness_uniform(rng, 0.0, l.length),
                                harness_uniform(rng, -0.03, 0.03),
                                harness_uniform(rng, 0.05, 1.5)});
  }
  core::SpinningInertia rotor;
  rotor.inertia = harness_uniform(rng, 1e-5, 1e-3);
  rotor.coeffs = core::JointVector::Zero(n);
  rotor.coeffs[n - 1] = harness_uniform(rng, 1.0, 10.0);  // a geared motor of the last joint
  c.spinners.push_back(rotor);
  c.gravity = gravity;
  c.base_angle = base_angle;
  return core::make_chain(c);
}

constexpr int kHarnessChains = 25;

TEST(FastPathHarness, TheReferenceAgreesWithMujocosInverseDynamicsOnRandomChains) {
  std::mt19937 rng(5301);
  for (int k = 0; k < kHarnessChains; ++k) {
    const int n = 2 + k % 3;
    const core::PlanarChain chain =
        harness_chain(rng, n, k % 2 ? 9.81 : 0.0, harness_uniform(rng, -core::kPi, core::kPi));
    std::vector<core::JointVector> q, qd, qdd, tau;
    for (int s = 0; s < 4; ++s) {
      q.push_back(harness_vector(rng, n, core::kPi));
      qd.push_back(harness_vector(rng, n, 3.0));
      qdd.push_back(harness_vector(rng, n, 10.0));
      tau.push_back(core::inverse_dynamics(chain, q.back(), qd.back(), qdd.back()));
    }
    const scene::MujocoAgreement a = scene::mujoco_agreement(chain, q, qd, qdd, tau);
    EXPECT_LT(a.torque_rel, 1e-9) << "chain " << k << " (" << n << " links)";
  }
}

TEST(FastPathHarness, PlacementSampleAndItsBlockedFormAgainstTheReference) {
  std::mt19937 rng(5302);
  namespace pl = studies::placement;
  for (int k = 0; k < kHarnessChains; ++k) {
    const core::PlanarChain chain = harness_chain(rng, 2, 0.0, 0.0);
    const pl::Arm2 arm = pl::make_arm2(chain);
    const double L1 = chain.links[0].length, L2 = chain.links[1].length;
    const double inner = std::abs(L1 - L2), outer = L1 + L2, span = outer - inner;
    // a line through the annulus, clear of its boundaries, and a sampled motion along it
    const double r0 = harness_uniform(rng, inner + 0.2 * span, outer - 0.2 * span);
    const double a0 = harness_uniform(rng, -core::kPi, core::kPi),
                 dir = harness_uniform(rng, -core::kPi, core::kPi);
    const double sx = r0 * std::cos(a0), sy = r0 * std::sin(a0);
    const double ux = std::cos(dir), uy = std::sin(dir);
    constexpr int m = 13;
    double s[m], sd[m], sdd[m], p1[m], p2[m], t1[m], t2[m], s2abs[m];
    for (int i = 0; i < m; ++i) {
      s[i] = harness_uniform(rng, -0.05, 0.05) * span;
      sd[i] = harness_uniform(rng, -2.0, 2.0);
      sdd[i] = harness_uniform(rng, -20.0, 20.0);
    }
    for (const double sign : {1.0, -1.0}) {
      pl::sample_block(arm, s, sd, sdd, m, sx, sy, ux, uy, sign, p1, p2, t1, t2, s2abs);
      for (int i = 0; i < m; ++i) {
        const double px = sx + s[i] * ux, py = sy + s[i] * uy;
        const pl::Arm2Sample a =
            pl::arm2_sample(arm, px, py, sd[i] * ux, sd[i] * uy, sdd[i] * ux, sdd[i] * uy, sign);
        core::JointVector q(2), qd(2), qdd(2), tau(2);
        q << std::atan2(a.s1, a.c1), std::atan2(a.s2, a.c2);
        qd << a.qd1, a.qd2;
        qdd << a.qdd1, a.qdd2;
        tau << a.tau1, a.tau2;
        // the pose reaches the tip, and the torques are the reference's
        EXPECT_TRUE(harness_close(core::end_effector(chain, q), Eigen::Vector2d(px, py), 1e-12));
        EXPECT_TRUE(harness_close(tau, core::inverse_dynamics(chain, q, qd, qdd), 1e-10))
            << "chain " << k << ", sample " << i << ", sign " << sign;
        // the blocked form computes the sample's figures
        EXPECT_NEAR(p1[i], a.tau1 * a.qd1, 1e-12 * std::abs(a.tau1 * a.qd1) + 1e-15);
        EXPECT_NEAR(p2[i], a.tau2 * a.qd2, 1e-12 * std::abs(a.tau2 * a.qd2) + 1e-15);
        EXPECT_NEAR(t1[i], std::abs(a.tau1), 1e-12 * std::abs(a.tau1) + 1e-15);
        EXPECT_NEAR(t2[i], std::abs(a.tau2), 1e-12 * std::abs(a.tau2) + 1e-15);
        EXPECT_NEAR(s2abs[i], std::abs(a.s2), 1e-15);
      }
    }
  }
}

TEST(FastPathHarness, TimeOptimalPathDynamicsAgainstTheReference) {
  std::mt19937 rng(5303);
  namespace to = studies::time_optimal;
  for (int k = 0; k < kHarnessChains; ++k) {
    const core::PlanarChain chain =
        harness_chain(rng, 2, k % 2 ? 9.81 : 0.0, harness_uniform(rng, -core::kPi, core::kPi));
    const to::TwoLinkDynamics d = to::make_two_link_dynamics(chain);
    for (int s = 0; s < 5; ++s) {
      // a path q(s) at one point: q, q' = dq/ds, q'' = d2q/ds2; the motion's s', s''
      const core::JointVector q = harness_vector(rng, 2, core::kPi);
      const core::JointVector dq = harness_vector(rng, 2, 2.0), ddq = harness_vector(rng, 2, 5.0);
      const double sd = harness_uniform(rng, 0.0, 3.0), sdd = harness_uniform(rng, -10.0, 10.0);
      core::JointVector a(2), b(2), c(2), tau(2);
      to::path_dynamics(d, q, dq, ddq, &a, &b, &c);
      const core::JointVector qd = dq * sd, qdd = dq * sdd + ddq * sd * sd;
      const core::JointVector reference = core::inverse_dynamics(chain, q, qd, qdd);
      EXPECT_TRUE(harness_close(core::JointVector(a * sdd + b * sd * sd + c), reference, 1e-12))
          << "chain " << k;
      to::inverse_dynamics(d, q, qd, qdd, &tau);
      EXPECT_TRUE(harness_close(tau, reference, 1e-12)) << "chain " << k;
    }
  }
}

// the tray arm with each parameter moved by up to +-30 % (and a rotor, motor 2 either way)
studies::TrayArmParams harness_tray_arm(std::mt19937& rng) {
  studies::TrayArmParams p;
  auto scale = [&](double& v) { v *= harness_uniform(rng, 0.7, 1.3); };
  for (double* v : {&p.l1, &p.m1, &p.r1, &p.I1, &p.l2, &p.m2, &p.r2, &p.I2, &p.circle_offset, &p.m3,
                    &p.r3, &p.I3, &p.m4, &p.r4, &p.rb, &p.Ib})
    scale(*v);
  p.r3_lateral = harness_uniform(rng, -0.005, 0.005);
  p.rotor_inertia = harness_uniform(rng, 0.0, 2e-6);
  p.motor2 = harness_uniform(rng, 0, 1) < 0.5 ? studies::Motor2Mount::kOnLink1
                                              : studies::Motor2Mount::kOnBase;
  return p;
}

TEST(FastPathHarness, TrayDynamicsAndContactForcesAgainstTheReference) {
  std::mt19937 rng(5304);
  for (int k = 0; k < kHarnessChains; ++k) {
    const studies::TrayArmParams p = harness_tray_arm(rng);
    const core::PlanarChain chain = studies::make_tray_arm(p);
    const studies::TrayDynamics fast(chain);
    for (int s = 0; s < 5; ++s) {
      const core::JointVector q = harness_vector(rng, 4, core::kPi);
      const core::JointVector qd = harness_vector(rng, 4, 8.0);
      core::JointVector qdd_active = harness_vector(rng, 4, 60.0);
      qdd_active[2] = qdd_active[3] = 0;
      Eigen::Vector2d force;
      const core::MixedDynamics f = fast.mixed(q, qd, qdd_active, p.m4, force);
      const core::MixedDynamics r =
          core::passive_forward_dynamics(chain, q, qd, qdd_active, core::JointVector::Zero(4));
      EXPECT_TRUE(harness_close(f.qdd, r.qdd, 1e-12)) << "arm " << k;
      EXPECT_TRUE(harness_close(f.tau, r.tau, 1e-12)) << "arm " << k;
      EXPECT_TRUE(
          harness_close(force, studies::ball_contact_forces(chain, p.m4, q, qd, r.qdd), 1e-12))
          << "arm " << k;
    }
  }
}

// The planning model of the throw on the references alone: the active joints follow the
// piecewise-linear rate profile, the passive ones core's mixed dynamics, each motor eq. 5-6
// (core::motor_sample), the energy eq. 7, integrated with core::rk4_step, steps_per_stage
// steps a stage. Returns theta3, theta4, their rates and the energy at tf, and the largest
// |voltage|, |current|, |e i| and the smallest normal force over the steps' starts and ends.
struct HarnessReferenceThrow {
  Eigen::Matrix<double, 5, 1> final_state;
  double max_voltage = 0, max_current = 0, max_power = 0, min_normal = INFINITY;
};

HarnessReferenceThrow harness_reference_throw(const studies::ThrowSetup& s,
                                              const studies::VelocityProfile& p) {
  HarnessReferenceThrow out;
  const Eigen::Matrix<double, 2, 4> B = studies::motor_matrix(s.mount);
  const int P = p.stages(), n = s.steps_per_stage;
  const double h = p.stage_length(), dt = h / n;
  core::OdeState x(5);
  x << s.theta3_0, s.theta4_0, 0, 0, 0;
  for (int k = 0; k < P; ++k) {
    // the state's derivative in stage k (its constant accelerations), tracking the limits
    const auto f = [&](double t, const core::OdeState& y, bool track) {
      const studies::ActiveState a = studies::evaluate_profile(p, k, t);
      core::JointVector q(4), qd(4), qdd_active(4);
      q << a.q, y[0], y[1];
      qd << a.qd, y[2], y[3];
      qdd_active << a.qdd, 0, 0;
      const core::MixedDynamics d =
          core::passive_forward_dynamics(s.chain, q, qd, qdd_active, core::JointVector::Zero(4));
      const Eigen::Vector2d tau_m = studies::motor_torques(s.mount, d.tau);
      const Eigen::Vector2d rate = B * Eigen::Matrix<double, 4, 1>(qd);
      const Eigen::Vector2d acc = B * Eigen::Matrix<double, 4, 1>(d.qdd);
      double power = 0;
      for (int m = 0; m < 2; ++m) {
        const core::MotorSample ms = core::motor_sample(s.motor[m], rate[m], acc[m], tau_m[m]);
        power += s.count_regeneration ? ms.power : std::max(0.0, ms.power);
        if (track) {
          out.max_voltage = std::max(out.max_voltage, std::abs(ms.voltage));
          out.max_current = std::max(out.max_current, std::abs(ms.current));
          out.max_power = std::max(out.max_power, std::abs(ms.power));
        }
      }
      if (track)
        out.min_normal = std::min(
            out.min_normal, studies::ball_contact_forces(s.chain, s.ball_mass, q, qd, d.qdd)[0]);
      core::OdeState dx(5);
      dx << y[2], y[3], d.qdd[2], d.qdd[3], power;
      return dx;
    };
    for (int j = 0; j < n; ++j) {
      const double t = k * h + j * dt;
      f(t, x, true);
      x = core::rk4_step([&](double tt, const core::OdeState& y) { return f(tt, y, false); }, t, x,
                         dt);
    }
    f((k + 1) * h, x, true);
  }
  out.final_state = x;
  return out;
}

TEST(FastPathHarness, ThrowKernelRk4AndMotorsAgainstTheReferenceModel) {
  std::mt19937 rng(5305);
  for (int k = 0; k < 8; ++k) {
    studies::ThrowingSpec spec;
    spec.arm = harness_tray_arm(rng);
    spec.stages = 6 + k % 3;
    spec.steps_per_stage = 6;
    spec.tf = harness_uniform(rng, 0.5, 0.9);
    studies::ThrowSetup setup = studies::make_throw_setup(spec);
    studies::VelocityProfile p = studies::eq8_profile(
        spec.start, Eigen::Vector2d::Zero(), spec.release, spec.release_rate, spec.tf, spec.stages);
    for (int c = 1; c < p.stages(); ++c)
      p.v.col(c) += Eigen::Vector2d(harness_uniform(rng, -2, 2), 0.0);
    const HarnessReferenceThrow r = harness_reference_throw(setup, p);
    // the kernel (one lane and four), the Planner's fast dynamics and its generic ones
    for (const int variant : {0, 1, 2, 3}) {
      studies::ThrowSetup s = setup;
      s.kernel_lanes = variant == 0 ? 1 : variant == 1 ? 4 : 0;
      s.generic_dynamics = variant == 3;
      const studies::ProfileEvaluation e = studies::simulate_profile(s, p);
      SCOPED_TRACE("arm " + std::to_string(k) + ", variant " + std::to_string(variant));
      ASSERT_TRUE(e.finite);
      const auto near = [](double a, double b) {
        EXPECT_NEAR(a, b, 1e-9 * std::max(1.0, std::abs(b)));
      };
      near(e.theta3_final, r.final_state[0]);
      near(e.theta4_final, r.final_state[1]);
      near(e.theta3_rate_final, r.final_state[2]);
      near(e.theta4_rate_final, r.final_state[3]);
      near(e.energy, r.final_state[4]);
      near(e.max_voltage, r.max_voltage);
      near(e.max_current, r.max_current);
      near(e.max_power, r.max_power);
      near(e.min_normal_force, r.min_normal);
    }
  }
}

}  // namespace
}  // namespace armstudy
