// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The time-optimal study's torques against MuJoCo: along the exact solution, mj_inverse of
// the generated model gives the torques the study computed, and those equal the path-
// projected dynamics tau = a s'' + b s'^2 + c that the solvers constrain.
#include <gtest/gtest.h>

#include <vector>

#include "scene/mujoco_check.hpp"
#include "studies/time_optimal/path.hpp"
#include "studies/time_optimal/solve.hpp"

namespace armstudy::scene {
namespace {
namespace to = studies::time_optimal;

TEST(TimeOptimalMujoco, ExactSolutionTorquesAreMujocosInverseDynamicsAndThePathProjection) {
  for (int configuration : {1, 2}) {
    to::Spec spec;
    spec.chain = to::default_arm();
    spec.chain.point_masses.back().mass = 1.5;  // a heavier tip, to differ from the default
    spec.path.kind = to::PathKind::kSpline;
    spec.path.points = {{0.6, -0.2}, {0.55, 0.25}, {0.2, 0.5}};
    spec.configuration = configuration;
    spec.exact.grid_points = 300;
    spec.dp.states = {};
    spec.dp.convergence_segments = {};
    spec.complex.enabled = false;
    const to::Result r = to::solve(spec);
    ASSERT_EQ(r.status, studies::Status::kSolved) << r.message;
    const to::MotionSamples& m = r.solvers.front().samples;
    ASSERT_GT(m.t.size(), 100u);

    std::vector<core::JointVector> q, qd, qdd, tau;
    const to::PathGeometry path(spec.path);
    double projection_error = 0, scale = 0;
    for (size_t k = 0; k < m.t.size(); ++k) {
      q.emplace_back(m.q.col(k));
      qd.emplace_back(m.qd.col(k));
      qdd.emplace_back(m.qdd.col(k));
      tau.emplace_back(m.tau.col(k));
      to::PathTrouble trouble;
      const auto jp = to::joint_point(spec.chain, path, configuration, m.s[k], false, &trouble);
      ASSERT_TRUE(jp) << trouble.message;
      for (int j = 0; j < 2; ++j) {
        const double projected = jp->a[j] * m.sdd[k] + jp->b[j] * m.sd[k] * m.sd[k] + jp->c[j];
        projection_error = std::max(projection_error, std::abs(projected - m.tau(j, k)));
        scale = std::max(scale, std::abs(m.tau(j, k)));
      }
    }
    EXPECT_LT(projection_error, 1e-9 * scale) << "configuration " << configuration;
    const MujocoAgreement a = mujoco_agreement(spec.chain, q, qd, qdd, tau);
    EXPECT_EQ(a.samples, static_cast<int>(m.t.size()));
    EXPECT_LT(a.torque_rel, 1e-9) << "configuration " << configuration << ", sample "
                                  << a.worst_sample;
  }
}

}  // namespace
}  // namespace armstudy::scene
