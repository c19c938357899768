// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The pendulum of Sato et al. Sec. 3 (joints 1 and 2 locked: a chain whose
// base is the tray hinge, with the tray and the rolling ball) simulated in MuJoCo with RK4:
// it conserves mechanical energy and follows core's own simulation.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/dynamics.hpp"
#include "core/kinematics.hpp"
#include "scene/chain_map.hpp"
#include "scene/mjcf_writer.hpp"
#include "scene/mujoco_model.hpp"
#include "scene/replay.hpp"
#include "scene/scene_error.hpp"
#include "studies/pendulum/solve.hpp"
#include "testing/arms.hpp"

namespace armstudy::scene {
namespace {

// Sec. 3 values: m3 = 0.109 kg, m4 = 0.122 kg, r4 = 0.075 m, r_b = 0.015 m; the tray's
// length and inertia are not given for the rig (docs/assumptions.md), these are plausible choices
core::PlanarChain pendulum() {
  const double m3 = 0.109, m4 = 0.122, r4 = 0.075, rb = 0.015, l3 = 0.04;
  core::PlanarChain c;
  c.links = {{l3, m3, l3 / 2, 0.0, core::uniform_rod_inertia(m3, 0.16), false},
             {r4, 0.0, 0.0, 0.0, 0.0, false}};
  c.point_masses = {{1, r4, 0.0, m4}};
  core::SpinningInertia ball;
  ball.inertia = 0.4 * m4 * rb * rb;  // solid sphere
  ball.coeffs.resize(2);
  ball.coeffs << 1, -r4 / rb;  // omega = tray rate - (r4/r_b) theta4'
  c.spinners = {ball};
  c.gravity = 9.81;
  return core::make_chain(c);
}

struct State {
  core::JointVector q, qd;
};

// classical RK4 on core's forward dynamics (passive: zero torque)
State rk4_step(const core::PlanarChain& chain, const State& s, double h) {
  const core::JointVector zero = core::JointVector::Zero(s.q.size());
  auto f = [&](const State& x) {
    return State{x.qd, core::forward_dynamics(chain, x.q, x.qd, zero)};
  };
  auto add = [](const State& a, const State& b, double k) {
    return State{a.q + k * b.q, a.qd + k * b.qd};
  };
  const State k1 = f(s), k2 = f(add(s, k1, h / 2)), k3 = f(add(s, k2, h / 2)),
              k4 = f(add(s, k3, h));
  return State{s.q + h / 6 * (k1.q + 2 * k2.q + 2 * k3.q + k4.q),
               s.qd + h / 6 * (k1.qd + 2 * k2.qd + 2 * k3.qd + k4.qd)};
}

std::string sci(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

double energy(const core::PlanarChain& chain, const core::JointVector& q,
              const core::JointVector& qd) {
  return core::kinetic_energy(chain, q, qd) + core::potential_energy(chain, q);
}

TEST(PendulumMujoco, ConservesEnergyAndFollowsCoreOverTwoSeconds) {
  take_mujoco_warnings();
  const core::PlanarChain chain = pendulum();
  MjcfOptions o;
  o.timestep = 2e-4;
  o.integrator = "RK4";
  MujocoModel mm(write_mjcf(chain, o), "pendulum");
  mm.model()->opt.enableflags |= mjENBL_ENERGY;
  const ChainMap map(chain, mm.model());
  State s{core::JointVector(2), core::JointVector::Zero(2)};
  s.q << -core::kPi / 2, -core::kPi / 5;  // start of Sec. 3, at rest
  mj_resetData(mm.model(), mm.data());
  map.set_state(mm.model(), mm.data(), s.q, s.qd);
  mj_forward(mm.model(), mm.data());
  const double e0 = energy(chain, s.q, s.qd);
  const double mj_e0 = mm.data()->energy[0] + mm.data()->energy[1];
  double max_kinetic = 0, worst_e = 0, worst_mj_e = 0, worst_q = 0, swing = 0;
  const int steps = static_cast<int>(std::lround(2.0 / o.timestep));
  for (int k = 0; k < steps; ++k) {
    mj_step(mm.model(), mm.data());
    s = rk4_step(chain, s, o.timestep);
    const core::JointVector q = map.chain_q(mm.data()), qd = map.chain_qd(mm.data());
    max_kinetic = std::max(max_kinetic, core::kinetic_energy(chain, q, qd));
    worst_e = std::max(worst_e, std::abs(energy(chain, q, qd) - e0));
    worst_mj_e =
        std::max(worst_mj_e, std::abs(mm.data()->energy[0] + mm.data()->energy[1] - mj_e0));
    worst_q = std::max(worst_q, (q - s.q).cwiseAbs().maxCoeff());
    swing = std::max(swing, std::abs(q[1] - (-core::kPi / 5)));
  }
  // a real swing happened (the energy scale is the kinetic energy it reached)
  ASSERT_GT(swing, 0.5);
  ASSERT_GT(max_kinetic, 1e-3);
  // energy: as core counts it from MuJoCo's state, and as MuJoCo counts it itself
  EXPECT_LT(worst_e / max_kinetic, 1e-6) << "E0 " << e0;
  EXPECT_LT(worst_mj_e / max_kinetic, 1e-6);
  // the two simulations stay together (the rolling constraint is stiff but soft)
  EXPECT_LT(worst_q, 1e-4) << "rad";
  RecordProperty("energy_rel", sci(worst_e / max_kinetic));
  RecordProperty("mujoco_energy_rel", sci(worst_mj_e / max_kinetic));
  RecordProperty("max_q_delta_rad", sci(worst_q));
  EXPECT_EQ(take_mujoco_warnings(), "");
}

// the chain of joints k.. of `chain` with joints 0..k-1 locked at q_locked: its base is
// joint k's position, its base angle link k-1's absolute angle; spinners keep their
// coefficients on the free joints (those turning only with locked joints drop out)
core::PlanarChain lock_first_joints(const core::PlanarChain& chain, const core::JointVector& q,
                                    int k) {
  const core::ChainPose pose = core::forward_kinematics(chain, q);
  core::PlanarChain c;
  c.gravity = chain.gravity;
  c.base = pose.p_WJ.col(k);
  c.base_angle = pose.angle[k - 1];
  const int n = chain.num_links();
  for (int i = k; i < n; ++i) c.links.push_back(chain.links[i]);
  for (core::PointMass p : chain.point_masses)
    if (p.link >= k) {
      p.link -= k;
      c.point_masses.push_back(p);
    }
  for (const core::SpinningInertia& s : chain.spinners) {
    core::SpinningInertia t;
    t.inertia = s.inertia;
    t.coeffs = s.coeffs.tail(n - k);
    if (t.coeffs.cwiseAbs().maxCoeff() > 0) c.spinners.push_back(t);
  }
  return core::make_chain(c);
}

// MuJoCo's simulated replay (scene::simulate, mj_step with RK4) of the pendulum study's
// case follows the study's own DOPRI5 solution
TEST(PendulumMujoco, SimulatedReplayFollowsThePendulumStudy) {
  take_mujoco_warnings();
  const studies::PendulumSpec spec = studies::default_pendulum_spec();
  const studies::PendulumResult r = studies::solve_pendulum(spec);
  ASSERT_EQ(r.status, studies::Status::kSolved) << r.message;
  const core::PlanarChain full = studies::make_tray_arm(spec.arm);
  const core::PlanarChain chain = lock_first_joints(full, r.q.front(), 2);
  MjcfOptions o;
  o.timestep = 2e-4;
  MujocoModel mm(write_mjcf(chain, o), "pendulum");
  const ChainMap map(chain, mm.model());
  const PoseSample start{0.0, r.q.front().tail(2), r.qd.front().tail(2)};
  std::vector<double> times;
  for (size_t i = 0; i < r.t.size(); i += 10) times.push_back(r.t[i]);
  const std::vector<PoseSample> sim = simulate(mm, map, start, times);
  double worst = 0, swing = 0;
  for (size_t j = 0; j < sim.size(); ++j) {
    const core::JointVector& q = r.q[10 * j];
    worst = std::max(worst, (sim[j].q - q.tail(2)).cwiseAbs().maxCoeff());
    swing = std::max(swing, std::abs(q[3] - r.q.front()[3]));
  }
  EXPECT_GT(swing, 0.3);
  EXPECT_LT(worst, 1e-4) << "rad over " << r.t.back() << " s";
  RecordProperty("max_q_delta_vs_study_rad", sci(worst));
  EXPECT_EQ(take_mujoco_warnings(), "");
}

}  // namespace
}  // namespace armstudy::scene
