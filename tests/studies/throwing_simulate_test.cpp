// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The planning simulation of the tray arm (simulate.hpp): the motors' mechanical work is the
// change of the arm's kinetic plus potential energy (passive joints do no work), eq. 7's
// electrical energy splits exactly into work, copper and friction, the RK4 plan agrees with
// an independent DOPRI5 integration, and the planned voltages replayed open loop through
// the model with all joints free reproduce the planned motion.
#include "studies/throwing/simulate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/dynamics.hpp"
#include "core/integrators.hpp"
#include "studies/throwing/solve.hpp"
#include "testing/arms.hpp"

namespace armstudy::studies {
// the integrators of core/integrators.hpp
using core::Dopri5Options;
using core::Dopri5Stats;
using core::integrate_dopri5;
using core::OdeState;
using core::rk4_step;
namespace {

ThrowingSpec spec() { return ThrowingSpec{}; }

VelocityProfile eq8(const ThrowingSpec& s, int stages) {
  return eq8_profile(s.start, Eigen::Vector2d::Zero(), s.release, s.release_rate, s.tf, stages);
}

double mech_energy(const core::PlanarChain& c, const core::JointVector& q,
                   const core::JointVector& qd) {
  return core::kinetic_energy(c, q, qd) + core::potential_energy(c, q);
}

TEST(ThrowSimulation, MotorWorkEqualsTheChangeOfMechanicalEnergy) {
  for (Motor2Mount mount : {Motor2Mount::kOnLink1, Motor2Mount::kOnBase}) {
    ThrowingSpec s = spec();
    s.arm.motor2 = mount;
    s.arm.rotor_inertia = 2e-6;
    s.steps_per_stage = 200;
    const ThrowSetup setup = make_throw_setup(s);
    const ThrowMotion m = record_motion(setup, s, eq8(s, 16));
    const auto& sr = m.series;
    const double dE = mech_energy(setup.chain, sr.q.back(), sr.qd.back()) -
                      mech_energy(setup.chain, sr.q.front(), sr.qd.front());
    // trapezoid over 0.25 ms samples: second order
    EXPECT_TRUE(testing::near_rel(m.split.mechanical, dE, 1e-4))
        << "mount " << static_cast<int>(mount);
  }
}

TEST(ThrowSimulation, ElectricalEnergySplitsIntoWorkCopperAndFriction) {
  const ThrowingSpec s = spec();
  const ThrowSetup setup = make_throw_setup(s);
  const ThrowMotion m = record_motion(setup, s, eq8(s, 16));
  EXPECT_LT(std::abs(m.split.rest), 1e-10 * m.split.electrical);
  EXPECT_GT(m.split.copper, 0.0);
  EXPECT_GT(m.split.friction, 0.0);
  // the rk4 quadrature state and the trapezoid over the samples agree
  EXPECT_TRUE(testing::near_rel(m.split.electrical, m.evaluation.energy, 1e-3));
}

// eq. 6's current jumps by 2 tau_f / kt where a motor's rate changes sign; a node rate is the
// rate at an RK4 sample, so with the exact sign (coulomb_band 0) the sampled energy jumps as
// that node rate passes 0, and a gradient method stalls on the jump's edge (docs/throwing.md,
// "The Coulomb term"). With the band (the default, 1e-3 rad/s) it is continuous there.
// Measured on eq. 8's 16 stages, node rates of motor 1 at +-1e-9 rad/s: up to 0.022 J with
// the exact sign, 3.2e-7 J with the band.
TEST(ThrowSimulation, TheSampledEnergyIsContinuousWhereAMotorRateCrossesZero) {
  const double d = 1e-9;  // rad/s, either side of 0
  for (const double band : {0.0, 1e-3}) {
    ThrowingSpec s = spec();
    s.motor.coulomb_band = band;
    const ThrowSetup setup = make_throw_setup(s);
    double most = 0;
    for (int k = 1; k < 16; ++k) {
      VelocityProfile p = eq8(s, 16);
      p.v(0, k) = d;
      const double above = simulate_profile(setup, p).energy;
      p.v(0, k) = -d;
      most = std::max(most, std::abs(above - simulate_profile(setup, p).energy));
    }
    if (band > 0)
      EXPECT_LT(most, 1e-6) << "the energy jumps where motor 1's rate crosses 0";
    else
      EXPECT_GT(most, 1e-3) << "the exact sign no longer makes the jump this test guards";
    std::printf("coulomb band %g rad/s: largest energy change over +-%g rad/s: %.3g J\n", band, d,
                most);
  }
}

TEST(ThrowSimulation, Rk4PlanAgreesWithAnIndependentDopri5Integration) {
  const ThrowingSpec s = spec();
  const ThrowSetup setup = make_throw_setup(s);
  const VelocityProfile p = eq8(s, 16);
  const ProfileEvaluation ev = simulate_profile(setup, p);
  // passive joints by dopri5 stage by stage (accelerations jump at the nodes)
  OdeState x(4);
  x << s.theta3_start, s.theta4_start, 0.0, 0.0;
  const core::JointVector zero = core::JointVector::Zero(4);
  const double h = p.stage_length();
  Dopri5Options opt;
  opt.rtol = 1e-11;
  opt.atol = 1e-12;
  for (int k = 0; k < p.stages(); ++k) {
    auto f = [&](double t, const OdeState& y) {
      const ActiveState a = evaluate_profile(p, k, t);
      core::JointVector q(4), qd(4), qdd(4);
      q << a.q, y[0], y[1];
      qd << a.qd, y[2], y[3];
      qdd << a.qdd, 0.0, 0.0;
      const core::MixedDynamics d = core::passive_forward_dynamics(setup.chain, q, qd, qdd, zero);
      OdeState dy(4);
      dy << y[2], y[3], d.qdd[2], d.qdd[3];
      return dy;
    };
    x = integrate_dopri5(f, k * h, x, {(k + 1) * h}, opt).back();
  }
  EXPECT_NEAR(ev.theta3_final, x[0], 1e-5);
  EXPECT_NEAR(ev.theta4_final, x[1], 1e-5);
  EXPECT_NEAR(ev.theta3_rate_final, x[2], 1e-3);
}

TEST(ThrowSimulation, PlannedVoltagesReplayedOpenLoopReproduceTheMotion) {
  for (Motor2Mount mount : {Motor2Mount::kOnLink1, Motor2Mount::kOnBase}) {
    ThrowingSpec s = spec();
    s.arm.motor2 = mount;
    s.steps_per_stage = 80;
    const ThrowSetup setup = make_throw_setup(s);
    std::vector<ThrowSample> samples;
    simulate_profile(setup, eq8(s, 16), &samples);
    std::vector<double> times;
    for (const auto& x : samples)
      if (times.empty() || x.t > times.back()) times.push_back(x.t);
    core::JointVector q0(4);
    q0 << s.start, s.theta3_start, s.theta4_start;
    const ReplayResult rr = replay_voltages(setup, voltage_history(samples), q0,
                                            core::JointVector::Zero(4), times, 1e-10, 1e-12);
    double err = 0;
    size_t j = 0;
    for (const auto& x : samples) {
      while (rr.t[j] < x.t - 1e-12) ++j;
      err = std::max(err, (rr.q[j] - x.q).cwiseAbs().maxCoeff());
    }
    // stated tolerance of the study's check (replay_tolerance_rad default)
    EXPECT_LT(err, 2e-3) << "mount " << static_cast<int>(mount);
  }
}

TEST(ThrowContact, BallAtRestInTheCupIsPushedByItsWeightAndNeedsNoFriction) {
  // the arm held still with the tray hanging (theta1 + theta2 + theta3 = -90 deg): the ball
  // sits at the bottom of the cup, N = m4 g, F_t = 0
  ThrowingSpec s = spec();
  const ThrowSetup setup = make_throw_setup(s);
  VelocityProfile still;
  still.tf = 0.4;
  still.q0 = s.start;
  still.v = Eigen::Matrix<double, 2, Eigen::Dynamic>::Zero(2, 5);
  std::vector<ThrowSample> samples;
  const ProfileEvaluation ev = simulate_profile(setup, still, &samples);
  ASSERT_TRUE(ev.finite);
  for (const ThrowSample& x : samples) {
    EXPECT_NEAR(x.normal_force, s.arm.m4 * s.arm.gravity, 1e-12);
    EXPECT_NEAR(x.tangential_force, 0.0, 1e-12);
  }
  EXPECT_NEAR(ev.min_normal_force, s.arm.m4 * s.arm.gravity, 1e-12);
  EXPECT_NEAR(ev.max_friction_ratio, 0.0, 1e-10);
}

TEST(ThrowContact, TangentialForceEqualsTheBallsSpinEquation) {
  // two routes to F_t (docs/throwing.md): Newton's law of the ball's centre, and its spin
  // I_Gb omega_b' = r_b F_t with omega_b' = qdd1 + qdd2 + qdd3 - (r4 / r_b) qdd4
  for (Motor2Mount mount : {Motor2Mount::kOnLink1, Motor2Mount::kOnBase}) {
    ThrowingSpec s = spec();
    s.arm.motor2 = mount;
    const ThrowSetup setup = make_throw_setup(s);
    std::vector<ThrowSample> samples;
    simulate_profile(setup, eq8(s, 16), &samples);
    double worst = 0, scale = 0;
    for (const ThrowSample& x : samples) {
      const double wdot = x.qdd[0] + x.qdd[1] + x.qdd[2] - (s.arm.r4 / s.arm.rb) * x.qdd[3];
      worst = std::max(worst, std::abs(s.arm.Ib * wdot / s.arm.rb - x.tangential_force));
      scale = std::max(scale, std::abs(x.tangential_force));
    }
    EXPECT_GT(scale, 1e-3);  // the throw does need friction
    EXPECT_LT(worst, 1e-9 * std::max(1.0, scale)) << "mount " << static_cast<int>(mount);
  }
}

TEST(ThrowContact, NormalForceEqualsTheRadialBalanceOfTheBall) {
  // an independent route to N: the ball's centre acceleration by finite differences of its
  // recorded positions (4x finer steps), N = m4 (g - a) . n
  ThrowingSpec s = spec();
  s.steps_per_stage = 80;
  const ThrowSetup setup = make_throw_setup(s);
  std::vector<ThrowSample> samples;
  simulate_profile(setup, eq8(s, 16), &samples);
  double worst = 0;
  for (size_t k = 1; k + 1 < samples.size(); ++k) {
    const ThrowSample &a = samples[k - 1], &b = samples[k], &c = samples[k + 1];
    if (!(a.t < b.t && b.t < c.t) || b.stage != a.stage || b.stage != c.stage) continue;
    const double h = b.t - a.t;
    const Eigen::Vector2d acc =
        (ball_position(setup.chain, c.q) - 2 * ball_position(setup.chain, b.q) +
         ball_position(setup.chain, a.q)) /
        (h * h);
    const double phi = b.q.sum();
    const Eigen::Vector2d n(std::cos(phi), std::sin(phi));
    const double N = s.arm.m4 * (Eigen::Vector2d(0, -s.arm.gravity) - acc).dot(n);
    worst = std::max(worst, std::abs(N - b.normal_force));
  }
  EXPECT_LT(worst, 1e-5);  // O(h^2) of the difference quotient, h = 6.25e-4 s
}

TEST(ThrowConstraints, ValuesAreTheNormalisedStageExtremes) {
  ThrowingSpec s = spec();
  s.tray_width = 0.1;  // far narrower than the ball's swing
  const ThrowSetup setup = make_throw_setup(s);
  const ProfileEvaluation ev = simulate_profile(setup, eq8(s, 16), nullptr, 0.01);
  const std::vector<double> g = constraint_values(setup, ev, 0.01);
  const int P = 16;
  ASSERT_EQ(g.size(), 6u * P + 1);
  const double w = s.arm.m4 * s.arm.gravity;
  for (int k = 0; k < P; ++k) {
    EXPECT_DOUBLE_EQ(g[k], (s.contact_margin - ev.stage_normal[k]) / w + 0.01);
    EXPECT_DOUBLE_EQ(g[2 * P + k], (ev.stage_theta4[k] - 0.05) / 0.05 + 0.01);
    EXPECT_DOUBLE_EQ(g[5 * P + k], (ev.stage_power[k] - s.power_max) / s.power_max + 0.01);
  }
  EXPECT_FALSE(ev.feasible);
  EXPECT_GT(ev.violation, 0.0);
  const auto worst = worst_constraints(setup, ev);
  EXPECT_NEAR(worst[static_cast<int>(ConstraintKind::kTray)], (ev.max_abs_theta4 - 0.05) / 0.05,
              1e-12);
  EXPECT_GT(ev.max_power, s.power_max);  // the raw eq. 8 start breaks the 60 W rating
}

}  // namespace
}  // namespace armstudy::studies
