// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The throw's exact derivatives (studies/throwing/throw_gradient.hpp), forward sensitivities
// of the RK4 simulation:
// - the values they come with are the simulation's own (simulate_profile's evaluation and
//   constraint values, bit for bit);
// - the derivatives of the energy and of every constraint value equal the central
//   differences of the existing simulation (step 1e-6 rad/s) to 1e-6 of the row's size,
//   wherever the function is smooth there (the one-sided differences agree: a stage's
//   worst sample does not change within the step), on the bundled case at a perturbed
//   eq. 8 point (16 stages) and at its 16- and 64-stage answers (the node rates of
//   throwing_gradient_answers.inc, written by armstudy at the commit that added this test).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "studies/throwing/grid_sequence.hpp"
#include "studies/throwing/nlopt_solve.hpp"
#include "studies/throwing/solve.hpp"
#include "studies/throwing/throw_gradient.hpp"

namespace armstudy::studies {
namespace {

#include "studies/throwing_gradient_answers.inc"

std::vector<double> quantities(const ThrowSetup& s, const VelocityProfile& p, double backoff) {
  const ProfileEvaluation e = simulate_profile(s, p, nullptr, backoff);
  std::vector<double> q = constraint_values(s, e, backoff);
  q.insert(q.begin(), e.energy);
  return q;
}

struct Agreement {
  int compared = 0, skipped = 0;
  double worst = 0;  // max |exact - central| / row size over the compared entries
};

// the derivatives against central differences of simulate_profile (row 0 the energy)
Agreement compare(const ThrowSetup& s, const VelocityProfile& p, double backoff) {
  const ThrowDerivatives d = throw_derivatives(s, p, backoff);
  const int P = p.stages(), n = 2 * (P - 1), m = 6 * P + 2;
  Eigen::MatrixXd exact(m, n), central(m, n), kink(m, n);
  exact.row(0) = d.energy_gradient.transpose();
  exact.bottomRows(m - 1) = d.constraint_jacobian;
  const std::vector<double> q0 = quantities(s, p, backoff);
  const double h = 1e-6;
  for (int i = 0; i < n; ++i) {
    VelocityProfile pp = p, pm = p;
    pp.v(i % 2, i / 2 + 1) += h;
    pm.v(i % 2, i / 2 + 1) -= h;
    const std::vector<double> qp = quantities(s, pp, backoff), qm = quantities(s, pm, backoff);
    for (int r = 0; r < m; ++r) {
      central(r, i) = (qp[r] - qm[r]) / (2 * h);
      kink(r, i) = std::abs((qp[r] - q0[r]) - (q0[r] - qm[r])) / h;
    }
  }
  Agreement a;
  for (int r = 0; r < m; ++r) {
    const double size = std::max(central.row(r).cwiseAbs().maxCoeff(), 1e-6);
    for (int i = 0; i < n; ++i) {
      // smooth: the one-sided differences agree (a switch of the worst sample changes the
      // slope by O(size), curvature by far less than 1e-3 of it over 1e-6 rad/s)
      if (kink(r, i) > 1e-3 * size) {
        ++a.skipped;
        continue;
      }
      ++a.compared;
      a.worst = std::max(a.worst, std::abs(exact(r, i) - central(r, i)) / size);
    }
  }
  std::cout << "  " << P << " stages: " << a.compared << " derivatives compared, worst " << a.worst
            << " of the row's size; " << a.skipped << " at a kink\n";
  return a;
}

void expect_values_are_the_simulations(const ThrowSetup& s, const VelocityProfile& p) {
  const double backoff = 0.02;
  const ThrowDerivatives d = throw_derivatives(s, p, backoff);
  for (int lanes : {0, 4}) {
    ThrowSetup sl = s;
    sl.kernel_lanes = lanes;
    const ProfileEvaluation e = simulate_profile(sl, p, nullptr, backoff);
    EXPECT_EQ(d.evaluation.energy, e.energy) << lanes;
    EXPECT_EQ(d.evaluation.theta3_final, e.theta3_final) << lanes;
    EXPECT_EQ(d.evaluation.max_friction_ratio, e.max_friction_ratio) << lanes;
    EXPECT_EQ(d.constraints, constraint_values(s, e, backoff)) << lanes;
  }
}

VelocityProfile perturbed_eq8(const ThrowingSpec& spec) {
  VelocityProfile p = eq8_profile(spec.start, Eigen::Vector2d::Zero(), spec.release,
                                  spec.release_rate, spec.tf, spec.stages);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (int k = 1; k < p.stages(); ++k) p.v.col(k) += Eigen::Vector2d(u(rng), u(rng));
  project_displacement(p, spec.release - spec.start);
  return p;
}

VelocityProfile answer_profile(const ThrowingSpec& spec, const std::vector<double>& rates) {
  VelocityProfile p;
  p.tf = spec.tf;
  p.q0 = spec.start;
  const int P = static_cast<int>(rates.size()) / 2 - 1;
  p.v.resize(2, P + 1);
  for (int k = 0; k <= P; ++k) p.v.col(k) = Eigen::Vector2d(rates[2 * k], rates[2 * k + 1]);
  return p;
}

TEST(ThrowGradient, ItsValuesAreTheSimulationsBitForBit) {
  const ThrowingSpec spec;
  const ThrowSetup s = make_throw_setup(spec);
  expect_values_are_the_simulations(s, perturbed_eq8(spec));
  expect_values_are_the_simulations(s, answer_profile(spec, kAnswer16));
}

TEST(ThrowGradient, EqualsCentralDifferencesAtAPerturbedStart) {
  const ThrowingSpec spec;
  const ThrowSetup s = make_throw_setup(spec);
  const Agreement a = compare(s, perturbed_eq8(spec), 0.02);
  EXPECT_GT(a.compared, 20 * a.skipped);
  EXPECT_LT(a.worst, 1e-6) << a.compared << " compared, " << a.skipped << " at kinks";
}

TEST(ThrowGradient, EqualsCentralDifferencesAtTheSixteenStageAnswer) {
  const ThrowingSpec spec;
  const ThrowSetup s = make_throw_setup(spec);
  const VelocityProfile p = answer_profile(spec, kAnswer16);
  ASSERT_EQ(p.stages(), 16);
  ASSERT_TRUE(simulate_profile(s, p).feasible);
  const Agreement a = compare(s, p, 0.02);
  EXPECT_GT(a.compared, 10 * a.skipped);
  EXPECT_LT(a.worst, 1e-6) << a.compared << " compared, " << a.skipped << " at kinks";
}

TEST(ThrowGradient, EqualsCentralDifferencesAtTheSixtyFourStageAnswer) {
  const ThrowingSpec spec;
  const VelocityProfile p = answer_profile(spec, kAnswer64);
  ASSERT_EQ(p.stages(), 64);
  const ThrowSetup s = grid_setup(make_throw_setup(spec), spec.stages, p.stages());
  ASSERT_TRUE(simulate_profile(s, p).feasible);
  const Agreement a = compare(s, p, 0.02);
  EXPECT_GT(a.compared, 10 * a.skipped);
  EXPECT_LT(a.worst, 1e-6) << a.compared << " compared, " << a.skipped << " at kinks";
}

// the bundled case's SLSQP settings with exact derivatives
NloptSettings exact_settings(const ThrowingSpec& spec) {
  NloptSettings settings = spec.nlopt;
  settings.backoff = spec.backoff;
  settings.exact_gradient = true;
  return settings;
}

// SLSQP with the exact derivatives (nlopt.exact_gradient) from the 16-stage answer of the
// central differences stays there: feasible, first-order converged, the same energy to 0.1 %,
// one simulation per gradient
TEST(ThrowGradient, SlsqpWithExactDerivativesHoldsTheSixteenStageAnswer) {
  const ThrowingSpec spec;
  const VelocityProfile p = answer_profile(spec, kAnswer16);
  const ThrowSetup s = make_throw_setup(spec);
  const NloptOutcome out = run_nlopt(s, p, spec.release - spec.start, exact_settings(spec));
  const double e0 = simulate_profile(s, p).energy;
  EXPECT_TRUE(out.feasible);
  EXPECT_TRUE(out.converged) << out.kkt_residual << " " << out.restart_gain;
  EXPECT_NEAR(out.evaluation.energy, e0, 1e-3 * e0);
  EXPECT_EQ(out.simulations, out.iterations);
  EXPECT_FALSE(out.central_polish);
}

// A run that exact derivatives leave short of the first-order test is finished by central
// differences, with restarts of their own, so its verdict is theirs (a first-order test no
// run can pass forces it here)
TEST(ThrowGradient, ARunExactDerivativesLeaveShortOfTheTestIsFinishedByCentralDifferences) {
  const ThrowingSpec spec;
  const ThrowSetup s = make_throw_setup(spec);
  const VelocityProfile p = answer_profile(spec, kAnswer16);
  NloptSettings settings = exact_settings(spec);
  settings.kkt_tolerance = 1e-12;
  settings.restarts = 1;
  const NloptOutcome out = run_nlopt(s, p, spec.release - spec.start, settings);
  EXPECT_TRUE(out.central_polish);
  EXPECT_FALSE(out.converged);
  EXPECT_TRUE(out.feasible);
  EXPECT_EQ(out.restarts, 2 * settings.restarts + 1);  // rounds 0-1 exact, 2-3 central
  // central differences cost 2n + 1 = 61 simulations a gradient on 16 stages
  EXPECT_GT(out.simulations, out.iterations + 30);
  const double e0 = simulate_profile(s, p).energy;
  EXPECT_LE(out.evaluation.energy, e0 * (1 + 1e-3));
}

}  // namespace
}  // namespace armstudy::studies
