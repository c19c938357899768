// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The throw's constraints sample by sample (throw_derivatives' per_sample rows, the smooth
// form IPOPT was tried on) and, when built with ARMSTUDY_WITH_IPOPT, the IPOPT solver of
// studies/throwing/ipopt_solve.hpp:
// - each stage constraint of constraint_values is the largest of that stage's sample rows
//   (voltage, current and power: over both motors), to rounding;
// - a sample row's derivative equals the central differences of that row (step 1e-6 rad/s)
//   to 1e-5 of the row's size, on the bundled case at its eq. 8 profile (16 stages);
// - IPOPT's answer from eq. 8 on 16 stages meets every constraint when re-simulated with 4x
//   the RK4 steps; and a tighter contact margin (+10 %) is never cheaper: IPOPT on the
//   nominal problem from the tighter answer (feasible for it) ends no higher than that.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "studies/throwing/solve.hpp"
#include "studies/throwing/throw_gradient.hpp"
#if ARMSTUDY_WITH_IPOPT
#include "studies/throwing/ipopt_solve.hpp"
#endif

namespace armstudy::studies {
namespace {

struct Bundled {
  ThrowingSpec spec;
  ThrowSetup setup = make_throw_setup(spec);
  VelocityProfile eq8 = eq8_profile(spec.start, Eigen::Vector2d::Zero(), spec.release,
                                    spec.release_rate, spec.tf, spec.stages);
  Eigen::Vector2d delta = spec.release - spec.start;
};

TEST(ThrowingSampleRows, StageConstraintsAreTheLargestSampleRows) {
  const Bundled b;
  const ThrowDerivatives d = throw_derivatives(b.setup, b.eq8, 0.02, true);
  const int P = b.eq8.stages(), samples = b.setup.steps_per_stage + 1;
  ASSERT_EQ(static_cast<int>(d.sample_stage.size()), P * samples);
  ASSERT_EQ(static_cast<int>(d.sample_constraints.size()), P * samples * kSampleRows);
  // the kinds of the sample rows: contact, friction, tray, then voltage, current, power of
  // motor 1 and motor 2
  const int kind[kSampleRows] = {0, 1, 2, 3, 4, 5, 3, 4, 5};
  for (int k = 0; k < P; ++k)
    for (int c = 0; c < 6; ++c) {
      double largest = -INFINITY;
      for (int s = 0; s < samples; ++s) {
        EXPECT_EQ(d.sample_stage[size_t(k * samples + s)], k);
        for (int r = 0; r < kSampleRows; ++r)
          if (kind[r] == c)
            largest = std::max(largest,
                               d.sample_constraints[size_t((k * samples + s) * kSampleRows + r)]);
      }
      EXPECT_NEAR(largest, d.constraints[size_t(c * P + k)], 1e-12)
          << "stage " << k << " kind " << c;
    }
}

TEST(ThrowingSampleRows, DerivativesEqualCentralDifferences) {
  const Bundled b;
  const ThrowDerivatives d = throw_derivatives(b.setup, b.eq8, 0.02, true);
  const int n = 2 * (b.eq8.stages() - 1);
  const double h = 1e-6;
  double worst = 0;
  for (int i = 0; i < n; i += 3) {
    VelocityProfile pp = b.eq8, pm = b.eq8;
    pp.v(i % 2, i / 2 + 1) += h;
    pm.v(i % 2, i / 2 + 1) -= h;
    const ThrowDerivatives dp = throw_derivatives(b.setup, pp, 0.02, true);
    const ThrowDerivatives dm = throw_derivatives(b.setup, pm, 0.02, true);
    for (size_t r = 0; r < d.sample_constraints.size(); ++r) {
      // |value| rows are kinked where the value crosses 0: skip a row that changes sign
      const double v0 = d.sample_constraints[r], vp = dp.sample_constraints[r],
                   vm = dm.sample_constraints[r];
      if (std::abs((vp - v0) - (v0 - vm)) > 1e-9) continue;
      const double central = (vp - vm) / (2 * h);
      const double size =
          std::max(1.0, d.sample_jacobian.row(Eigen::Index(r)).cwiseAbs().maxCoeff());
      worst = std::max(worst, std::abs(d.sample_jacobian(Eigen::Index(r), i) - central) / size);
    }
  }
  EXPECT_LT(worst, 1e-5);
}

#if ARMSTUDY_WITH_IPOPT
TEST(ThrowingIpopt, AnswerIsFeasibleWhenResimulated) {
  const Bundled b;
  NloptSettings ns;
  ns.max_evaluations = 600;
  const NloptOutcome o = run_ipopt(b.setup, b.eq8, b.delta, ns);
  ASSERT_TRUE(o.feasible) << o.return_code;
  EXPECT_GT(o.simulations, 1);
  const Verification v = verify_profile(b.setup, o.best, 4);
  EXPECT_TRUE(v.feasible) << "energy " << v.evaluation.energy;
  EXPECT_NEAR(v.evaluation.energy, o.evaluation.energy, 1e-3 * o.evaluation.energy);
}

TEST(ThrowingIpopt, TighterContactMarginIsNeverCheaper) {
  Bundled b;
  NloptSettings ns;
  ns.max_evaluations = 600;
  const NloptOutcome nominal = run_ipopt(b.setup, b.eq8, b.delta, ns);
  ASSERT_TRUE(nominal.feasible) << nominal.return_code;
  ThrowingSpec tight_spec = b.spec;
  tight_spec.contact_margin = 1.1 * b.spec.contact_margin;
  const ThrowSetup tight = make_throw_setup(tight_spec);
  const NloptOutcome t = run_ipopt(tight, nominal.best, b.delta, ns);
  ASSERT_TRUE(t.feasible) << t.return_code;
  // the tighter answer meets the nominal limits: restarted from it, the nominal answer
  // costs no more than the tighter one
  const NloptOutcome again = run_ipopt(b.setup, t.best, b.delta, ns);
  ASSERT_TRUE(again.feasible) << again.return_code;
  EXPECT_LE(again.evaluation.energy, t.evaluation.energy * (1 + 1e-9));
}
#endif

}  // namespace
}  // namespace armstudy::studies
