// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// Velocity profiles of the active joints: eq. 8 (corrected) meets both end rates and the
// displacement; the piecewise-linear profile keeps angle and rate continuous at the nodes;
// the projection restores the release angles of any candidate exactly.
#include "studies/throwing/profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/types.hpp"

namespace armstudy::studies {
namespace {

const Eigen::Vector2d kQi(-core::kPi / 4, -core::kPi / 4),
    kQf(13 * core::kPi / 36, -7 * core::kPi / 36);
const Eigen::Vector2d kQdi(0.0, 0.0), kQdf(13.9, -1.1);

TEST(Profile, Eq8MeetsEndRatesAndIntegratesToTheDisplacement) {
  const double tf = 0.8;
  EXPECT_TRUE(eq8_rate(kQi, kQdi, kQf, kQdf, tf, 0.0).isApprox(kQdi, 1e-14) ||
              eq8_rate(kQi, kQdi, kQf, kQdf, tf, 0.0).norm() < 1e-14);
  EXPECT_TRUE(eq8_rate(kQi, kQdi, kQf, kQdf, tf, tf).isApprox(kQdf, 1e-12));
  // simpson's rule on the continuous eq. 8
  const int n = 2000;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int k = 0; k <= n; ++k) {
    const double wgt = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    sum += wgt * eq8_rate(kQi, kQdi, kQf, kQdf, tf, tf * k / n);
  }
  sum *= tf / n / 3;
  EXPECT_NEAR(sum[0], kQf[0] - kQi[0], 1e-10);
  EXPECT_NEAR(sum[1], kQf[1] - kQi[1], 1e-10);
}

TEST(Profile, SampledEq8ReachesTheReleaseAnglesExactly) {
  for (int P : {2, 5, 16, 40}) {
    const VelocityProfile p = eq8_profile(kQi, kQdi, kQf, kQdf, 0.8, P);
    const ActiveState end = evaluate_profile(p, 0.8);
    EXPECT_NEAR(end.q[0], kQf[0], 1e-12) << P;
    EXPECT_NEAR(end.q[1], kQf[1], 1e-12) << P;
    EXPECT_NEAR(end.qd[0], kQdf[0], 1e-12) << P;
    EXPECT_NEAR(end.qd[1], kQdf[1], 1e-12) << P;
  }
}

TEST(Profile, AngleAndRateAreContinuousAcrossStageNodes) {
  const VelocityProfile p = eq8_profile(kQi, kQdi, kQf, kQdf, 0.8, 8);
  const double h = p.stage_length();
  for (int k = 1; k < 8; ++k) {
    const ActiveState left = evaluate_profile(p, k - 1, k * h);
    const ActiveState right = evaluate_profile(p, k, k * h);
    EXPECT_TRUE((left.q - right.q).norm() < 1e-13);
    EXPECT_TRUE((left.qd - right.qd).norm() < 1e-13);
    // the acceleration of a stage is the slope of its rate
    const ActiveState mid = evaluate_profile(p, k, (k + 0.5) * h);
    EXPECT_TRUE(((mid.qd - right.qd) / (0.5 * h) - right.qdd).norm() < 1e-9);
  }
}

TEST(Profile, ProjectionRestoresTheDisplacementOfRandomCandidates) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5, 5);
  VelocityProfile p = eq8_profile(kQi, kQdi, kQf, kQdf, 0.8, 12);
  for (int trial = 0; trial < 20; ++trial) {
    VelocityProfile c = p;
    for (int k = 1; k < 12; ++k) c.v.col(k) += Eigen::Vector2d(u(rng), u(rng));
    project_displacement(c, kQf - kQi);
    EXPECT_TRUE((displacement(c) - (kQf - kQi)).norm() < 1e-12);
    // end rates untouched
    EXPECT_EQ(c.v.col(0), p.v.col(0));
    EXPECT_EQ(c.v.col(12), p.v.col(12));
  }
}

}  // namespace
}  // namespace armstudy::studies
