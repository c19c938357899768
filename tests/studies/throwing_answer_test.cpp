// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The throwing study's answer is an optimum, not an early stop, and it is reproducible:
// - the bundled case's answer moves by less than 0.5 % when the release angle moves by
//   1 ulp (-52.5 deg against the code's -7 pi/24) or by 1e-5 deg, the reproducibility the
//   report states (a single SLSQP start moved 2-70 % under such changes);
// - on the control grids (16 and 32 stages) a tighter problem is never cheaper than the
//   nominal one, beyond that stated error: 40 W (a subset of the 60 W problem), a 0.022 N
//   contact margin, friction 0.45 or a 0.5 deg release tolerance; nor is a throw that a
//   looser problem (the motor ratings lifted) finds within the nominal limits;
// - a run cut by its budget, or stopped by a tolerance too loose for the first-order test,
//   fails its convergence check; a case no throw can meet is not solved and quotes no saving.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "core/types.hpp"
#include "studies/throwing/solve.hpp"

namespace armstudy::studies {
namespace {

constexpr double kReproducible = 0.005;  // the stated error: 0.5 %

// the answer's energy; `converged`: its SLSQP run must be first-order converged (the
// invariant below needs a feasible throw only: a tighter answer not converged on its grid
// still may not be cheaper)
double answer_energy(const ThrowingSpec& s, bool converged = true) {
  const ThrowingResult r = solve_throwing(s);
  EXPECT_EQ(r.status, Status::kSolved) << r.message;
  EXPECT_EQ(r.answer, "slsqp");
  if (converged) {
    EXPECT_TRUE(r.nlopt_run.converged) << r.message;
  }
  EXPECT_TRUE(r.nlopt_check.feasible) << r.message;
  return r.nlopt.evaluation.energy;
}

// the bundled case (reports/cases/throwing.yaml) as the code's defaults give it
ThrowingSpec bundled() { return ThrowingSpec{}; }

TEST(ThrowingAnswer, ALastDigitChangeOfTheReleaseAngleMovesTheAnswerByLessThanHalfAPercent) {
  ThrowingSpec s = bundled();
  s.grid.refinements = 0;  // the search on its first grid (the control grids: below)
  const double e0 = answer_energy(s);
  // the bundled file's -52.5 deg: one ulp from -7 pi / 24
  s.theta3_release = -52.5 * (core::kPi / 180);
  ASSERT_NE(s.theta3_release, bundled().theta3_release);
  const double e_ulp = answer_energy(s);
  s.theta3_release = -52.50001 * (core::kPi / 180);
  const double e_5 = answer_energy(s);
  EXPECT_LT(std::abs(e_ulp - e0), kReproducible * e0) << e0 << " J vs " << e_ulp << " J";
  EXPECT_LT(std::abs(e_5 - e0), kReproducible * e0) << e0 << " J vs " << e_5 << " J";
  // (40 W, a subset of the 60 W throws: on the control grids in the test below)
}

// the bundled answer (on its control grids) against four tighter problems, each a subset of
// the nominal one: none may come out cheaper (beyond the stated 0.5 %). Before the control
// grids and the refinement of the best few 16-stage optima, a 0.022 N contact margin
// answered 4.56 J where the nominal answered 6.29 J.
//
// On the case's first two control grids (16 and 32 stages, grid.refinements 1), the nominal
// and every tighter problem alike: the invariant is a property of the search on the grids it
// has, and the 64-stage grid would make each of the five solves about twice as dear.
ThrowingSpec bundled_on_two_grids() {
  ThrowingSpec s = bundled();
  s.grid.refinements = 1;
  return s;
}

TEST(ThrowingAnswer, ATighterProblemIsNeverCheaperThanTheNominalAnswer) {
  const double e0 = answer_energy(bundled_on_two_grids());
  ThrowingSpec w40 = bundled_on_two_grids(), contact = bundled_on_two_grids(),
               mu = bundled_on_two_grids(), release = bundled_on_two_grids();
  w40.power_max = 40;
  contact.contact_margin = 0.022;
  mu.friction_coefficient = 0.45;
  release.release_tolerance = 0.5 * core::kDeg;
  for (const auto& [name, spec] :
       {std::pair{"40 W", w40}, std::pair{"contact 0.022 N", contact},
        std::pair{"friction 0.45", mu}, std::pair{"release 0.5 deg", release}}) {
    const double e = answer_energy(spec, false);
    std::printf("%s: %.6f J against the nominal %.6f J\n", name, e, e0);
    EXPECT_GE(e, e0 * (1 - kReproducible)) << name << ": " << e << " J, nominal " << e0 << " J";
  }
}

// The global phase (nlopt.smooth_starts): the bundled case with its motor ratings lifted
// (x 1000) reaches, on its 16 stages, a throw that needs no more than the nominal ratings
// (feasible for the nominal problem in the 4x re-check); the nominal answer may then not
// cost more than it. Before the smooth starts the nominal answered 6.29 J, the lifted one
// 4.53 J, within 60 % of the ratings.
TEST(ThrowingAnswer, AThrowOfALooserProblemThatMeetsTheNominalLimitsIsNeverCheaper) {
  ThrowingSpec nominal = bundled();
  nominal.grid.refinements = 0;
  ThrowingSpec lifted = nominal;
  lifted.voltage_max *= 1000;
  lifted.current_max *= 1000;
  lifted.power_max *= 1000;
  const ThrowingResult l = solve_throwing(lifted);
  ASSERT_EQ(l.status, Status::kSolved) << l.message;
  // the cheapest local optimum of the lifted search that the nominal limits allow
  const ThrowSetup setup = make_throw_setup(nominal);
  double allowed = INFINITY;
  for (const auto& start : l.slsqp_starts) {
    if (start.run.best.v.size() == 0) continue;
    const Verification v = verify_profile(setup, start.run.best, nominal.check_refinement);
    if (v.feasible) allowed = std::min(allowed, v.evaluation.energy);
  }
  ASSERT_TRUE(std::isfinite(allowed))
      << "no optimum of the lifted search meets the nominal limits: the test no longer tests";
  const double e0 = answer_energy(nominal);
  std::printf("nominal %.6f J, the lifted search's best allowed throw %.6f J\n", e0, allowed);
  EXPECT_LE(e0, allowed * (1 + kReproducible))
      << "the nominal answer " << e0 << " J costs more than a throw it allows, " << allowed << " J";
}

// a small throw (8 stages) with the bundled limits loosened so that it is feasible
ThrowingSpec small() {
  ThrowingSpec s;
  s.stages = 8;
  s.steps_per_stage = 20;
  s.idp.iterations = 2;
  s.idp.max_passes = 3;
  s.idp.seeds = 1;
  s.power_max = 200;
  s.current_max = 10;
  s.grid.refinements = 0;  // one grid (the control grids: throwing_grid_test.cpp)
  return s;
}

TEST(ThrowingAnswer, ABudgetCutOrATooLooseToleranceFailsTheConvergenceCheck) {
  ThrowingSpec s = small();
  s.nlopt.hops = 0;
  const ThrowingResult ok = solve_throwing(s);
  ASSERT_EQ(ok.status, Status::kSolved) << ok.message;
  EXPECT_TRUE(ok.nlopt_run.converged) << ok.message;
  EXPECT_LE(ok.nlopt_run.kkt_residual, s.nlopt.kkt_tolerance);

  ThrowingSpec cut = s;
  cut.nlopt.max_evaluations = 3;
  const ThrowingResult rc = solve_throwing(cut);
  EXPECT_FALSE(rc.nlopt_run.converged) << rc.nlopt_run.return_code;
  EXPECT_EQ(rc.message.rfind("NOT converged", 0), 0u) << rc.message;

  ThrowingSpec loose = s;
  loose.nlopt.ftol_rel = loose.nlopt.xtol_rel = 0.05;
  loose.nlopt.restarts = 0;
  loose.nlopt.kkt_tolerance = 1e-6;
  const ThrowingResult rl = solve_throwing(loose);
  EXPECT_FALSE(rl.nlopt_run.converged) << rl.nlopt_run.kkt_residual;
  EXPECT_GT(rl.nlopt_run.kkt_residual, loose.nlopt.kkt_tolerance);
}

TEST(ThrowingAnswer, ACaseNoThrowCanMeetIsNotSolvedAndQuotesNoSaving) {
  ThrowingSpec s = small();
  s.power_max = 60;
  s.current_max = 0.5;  // 0.5 A cannot lift the arm to its release
  s.nlopt.hops = 0;
  const ThrowingResult r = solve_throwing(s);
  EXPECT_EQ(r.status, Status::kUnsolvable) << r.message;
  EXPECT_EQ(r.message.rfind("no feasible throw found", 0), 0u) << r.message;
  EXPECT_NE(r.message.find("current"), std::string::npos) << r.message;
  EXPECT_TRUE(std::isnan(r.saving_percent));
}

}  // namespace
}  // namespace armstudy::studies
