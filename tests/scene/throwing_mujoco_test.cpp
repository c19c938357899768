// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The throwing study's proof in MuJoCo: the motor voltages of an IDP-optimised
// throw, applied open loop to the generated MuJoCo model of the tray arm (rolling ball as a
// spin body with a joint equality, mjcf_writer.hpp), reproduce the planned motion of all
// four coordinates. The motor torques follow eq. 5-6 from MuJoCo's own joint rates at each
// step: tau_m = (kt/Ra)(e - kv qd_m) - Dm qd_m - tau_f sgn(qd_m).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "scene/chain_map.hpp"
#include "scene/mjcf_writer.hpp"
#include "scene/mujoco_model.hpp"
#include "scene/scene_error.hpp"
#include "studies/throwing/idp.hpp"
#include "studies/throwing/solve.hpp"

namespace armstudy::scene {
namespace {
namespace st = studies;

std::string sci3(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

void replay_in_mujoco(st::Motor2Mount mount) {
  take_mujoco_warnings();
  st::ThrowingSpec spec;
  spec.arm.motor2 = mount;
  spec.arm.rotor_inertia = 1e-6;  // exercised as armature-free spinners in MuJoCo too
  spec.stages = 8;
  spec.steps_per_stage = 20;
  const st::ThrowSetup setup = st::make_throw_setup(spec);
  // a quick IDP optimum (a few iterations) from eq. 8
  const st::VelocityProfile initial = st::eq8_profile(
      spec.start, Eigen::Vector2d::Zero(), spec.release, spec.release_rate, spec.tf, spec.stages);
  st::IdpSettings is;
  is.iterations = 3;
  is.max_passes = 1;
  is.candidates = 4;
  is.region = {5.0, 5.0};
  const st::IdpResult idp = st::run_idp(setup, initial, spec.release - spec.start, is);
  ASSERT_TRUE(st::better_profile(idp.evaluation, idp.initial_evaluation));
  // the plan with dense voltage samples (16x the steps: 3.125e-4 s)
  st::ThrowSetup fine = setup;
  fine.steps_per_stage = 16 * setup.steps_per_stage;
  std::vector<st::ThrowSample> plan;
  st::simulate_profile(fine, idp.best, &plan);
  const st::VoltageHistory vh = st::voltage_history(plan);

  MjcfOptions o;
  o.integrator = "RK4";
  const double sample_dt = spec.tf / spec.stages / fine.steps_per_stage;
  o.timestep = sample_dt / 4;
  MujocoModel mm(write_mjcf(setup.chain, o), "tray_arm");
  const ChainMap map(setup.chain, mm.model());
  core::JointVector q0(4);
  q0 << spec.start, spec.theta3_start, spec.theta4_start;
  mj_resetData(mm.model(), mm.data());
  map.set_state(mm.model(), mm.data(), q0, core::JointVector::Zero(4));
  mj_forward(mm.model(), mm.data());
  const Eigen::Matrix<double, 2, 4> B = st::motor_matrix(mount);
  const double h = spec.tf / spec.stages;
  const long steps = std::lround(spec.tf / o.timestep);
  double worst = 0, worst_t = 0;
  size_t next = 0;  // next plan sample to compare
  for (long k = 0; k <= steps; ++k) {
    const double t = k * o.timestep;
    const core::JointVector q = map.chain_q(mm.data()), qd = map.chain_qd(mm.data());
    // compare with every plan sample at this time
    while (next < plan.size() && plan[next].t <= t + 1e-9) {
      if (std::abs(plan[next].t - t) < 1e-9) {
        const double d = (q - plan[next].q).cwiseAbs().maxCoeff();
        if (d > worst) {
          worst = d;
          worst_t = t;
        }
      }
      ++next;
    }
    if (k == steps) break;
    // eq. 5-6 solved for the motor torque at MuJoCo's own rates (rotors are in the chain)
    const int stage = std::min(static_cast<int>(t / h), spec.stages - 1);
    const Eigen::Vector2d e = vh.at(stage, t);
    const Eigen::Matrix<double, 4, 1> qd4 = qd;
    const Eigen::Vector2d rate = B * qd4;
    Eigen::Vector2d tau_m;
    for (int m = 0; m < 2; ++m) {
      const core::DcMotor& mo = setup.motor[m];
      tau_m[m] = (mo.kt / mo.Ra) * (e[m] - mo.kv * rate[m]) - mo.Dm * rate[m] -
                 mo.tau_f * std::tanh(rate[m] / 1e-4);
    }
    const core::JointVector Q = st::joint_torques(mount, tau_m);
    mju_zero(mm.data()->qfrc_applied, mm.model()->nv);
    mm.data()->qfrc_applied[map.dof(0)] = Q[0];
    mm.data()->qfrc_applied[map.dof(1)] = Q[1];
    mj_step(mm.model(), mm.data());
  }
  EXPECT_EQ(next, plan.size());
  // stated tolerance: 5e-3 rad on every coordinate (the rolling equality is stiff but soft,
  // and the applied torque is held over each MuJoCo step)
  EXPECT_LT(worst, 5e-3) << "at t = " << worst_t << " s";
  ::testing::Test::RecordProperty(
      mount == st::Motor2Mount::kOnBase ? "max_q_delta_rad_on_base" : "max_q_delta_rad",
      sci3(worst));
  EXPECT_EQ(take_mujoco_warnings(), "");
}

TEST(ThrowingMujoco, OptimisedVoltagesOpenLoopReproduceThePlanMotor2OnLink1) {
  replay_in_mujoco(st::Motor2Mount::kOnLink1);
}

TEST(ThrowingMujoco, OptimisedVoltagesOpenLoopReproduceThePlanMotor2OnBase) {
  replay_in_mujoco(st::Motor2Mount::kOnBase);
}

}  // namespace
}  // namespace armstudy::scene
