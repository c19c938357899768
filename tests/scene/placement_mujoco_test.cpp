// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The placement study's energies against an independent model: MuJoCo's mj_inverse on the
// MJCF generated from the same chain, along the optimal motions, integrated the same way.
#include <gtest/gtest.h>

#include <cmath>

#include "core/energy.hpp"
#include "scene/chain_map.hpp"
#include "scene/mjcf_writer.hpp"
#include "scene/mujoco_model.hpp"
#include "scene/scene_error.hpp"
#include "studies/placement/geometry.hpp"
#include "studies/placement/solve.hpp"
#include "testing/arms.hpp"

namespace armstudy::scene {
namespace {

namespace pl = studies::placement;

class PlacementMujoco : public ::testing::Test {
 protected:
  void SetUp() override { take_mujoco_warnings(); }
  void TearDown() override { EXPECT_EQ(take_mujoco_warnings(), ""); }
};

// torques of MuJoCo along a series, and the energy and signed work integrated from them
struct MujocoReplay {
  std::vector<Eigen::Vector2d> tau;
  double energy = 0, signed_work = 0;
};

MujocoReplay replay(const core::PlanarChain& chain, const pl::TimeSeries& s) {
  MujocoModel mm(write_mjcf(chain), "placement");
  const ChainMap map(chain, mm.model());
  MujocoReplay r;
  std::vector<double> p_abs, p_signed;
  for (size_t k = 0; k < s.t.size(); ++k) {
    core::JointVector q(2), qd(2), qdd(2);
    q << s.q[k][0], s.q[k][1];
    qd << s.qd[k][0], s.qd[k][1];
    qdd << s.qdd[k][0], s.qdd[k][1];
    mj_resetData(mm.model(), mm.data());
    map.set_state(mm.model(), mm.data(), q, qd, &qdd);
    mj_inverse(mm.model(), mm.data());
    const core::JointVector tau = map.project(mm.data()->qfrc_inverse);
    r.tau.emplace_back(tau[0], tau[1]);
    p_abs.push_back(core::absolute_power(tau, qd));
    p_signed.push_back(core::signed_power(tau, qd));
  }
  r.energy = core::integrate_trapezoid(s.t, p_abs);
  r.signed_work = core::integrate_trapezoid(s.t, p_signed);
  return r;
}

TEST_F(PlacementMujoco, MjInverseTorquesAndEnergiesEqualTheStudysAlongEveryOptimum) {
  pl::Spec spec;
  spec.chain = testing::thesis_arm();
  spec.length = 0.4 * pl::annulus(0.4, 0.2).lmax;
  spec.nx_s = 20;
  spec.phi_step = 2 * core::kPi / 180;
  spec.map_nx = 20;
  spec.map_ny = 10;
  spec.evaluations = {{"thesis-config-1", 0.52, 130.89 * core::kPi / 180}};
  const pl::Result r = pl::solve(spec);
  ASSERT_EQ(r.status, studies::Status::kSolved) << r.message;
  std::vector<const pl::TimeSeries*> series;
  std::vector<double> energies;
  for (const auto& pc : r.cases) {
    ASSERT_TRUE(pc.found);
    series.push_back(&pc.series);
    energies.push_back(pc.refined.metrics.energy);
  }
  for (const auto& e : r.evaluations) {
    series.push_back(&e.series);
    // the sampled energy where the doubling converged, the series' samples (the printed
    // energy is the quadrature's)
    double sampled = NAN;
    for (const pl::ConvergenceRow& row : e.candidate.convergence.rows)
      if (row.samples == e.candidate.convergence.samples) sampled = row.energy;
    energies.push_back(sampled);
  }
  for (size_t i = 0; i < series.size(); ++i) {
    const pl::TimeSeries& s = *series[i];
    const MujocoReplay m = replay(spec.chain, s);
    double scale = 0, err = 0;
    for (size_t k = 0; k < s.t.size(); ++k) {
      scale = std::max(scale, s.tau[k].cwiseAbs().maxCoeff());
      err = std::max(err, (m.tau[k] - s.tau[k]).cwiseAbs().maxCoeff());
    }
    EXPECT_LE(err, 1e-9 * scale) << "motion " << i;
    EXPECT_TRUE(testing::near_rel(m.energy, energies[i], 1e-9)) << "motion " << i;
    // and MuJoCo's signed work of the rest-to-rest motion vanishes (trapezoid: O(h^4))
    EXPECT_LT(std::abs(m.signed_work), 1e-7 * energies[i]) << "motion " << i;
  }
}

}  // namespace
}  // namespace armstudy::scene
