// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The placement optimum says what decides it and is converged: the constrained
// refinement against an independent fine constrained search, margin binding and interior
// optima, admissible Pareto fronts, and singular motions that never print a number.
#include "studies/placement/refine.hpp"

#include <gtest/gtest.h>

#include <functional>

#include "studies/placement/geometry.hpp"
#include "studies/placement/quadrature.hpp"
#include "studies/placement/solve.hpp"
#include "testing/arms.hpp"

namespace armstudy::studies::placement {
namespace {

using armstudy::testing::kDeg;

// a coarse sweep (fast); the refinement has to do the rest
Spec small_spec(double fraction) {
  Spec s;
  s.chain = testing::thesis_arm();
  s.length = fraction * annulus(0.4, 0.2).lmax;
  s.nx_s = 16;
  s.phi_step = 3 * kDeg;
  s.map_nx = 8;
  s.map_ny = 4;
  s.sensitivity_margins = {0.005, 0.02, 0.05};
  return s;
}

struct Fine {
  double energy = std::numeric_limits<double>::infinity();
  double x_s = 0, phi = 0;
};

// independent of the refinement: only what the study classifies feasible competes
void consider(const Spec& s, const Arm2& arm, const ProgramTable& t, int config, double x, double p,
              Fine& best) {
  if (!(x > 0)) return;
  const Candidate c = evaluate_candidate(s, arm, t, config, x, p);
  if (c.status == CandidateStatus::kFeasible && c.metrics.energy < best.energy)
    best = {c.metrics.energy, x, p};
}

// a fine constrained search around the sweep's optimum (x0, p0), independent of the
// refinement: (1) a 25 x 25 grid over (x_s, phi) zoomed onto its best admissible node 40
// times; (2) along each family of lines on the admissible set's boundary (tangent to the
// circle |L1 - L2| + margin; start, or end, on the circle L1 + L2 - margin), x_s in closed
// form, a 2001-point scan of phi zoomed 30 times. The least of all.
Fine fine_constrained_search(const Spec& s, const Arm2& arm, const ProgramTable& t, int config,
                             double x0, double p0, double wx, double wp) {
  Fine best{std::numeric_limits<double>::infinity(), x0, p0};
  {
    Fine b = best;
    double ax = wx, ap = wp;
    for (int level = 0; level < 40; ++level) {
      const double cx = b.x_s, cp = b.phi;
      for (int i = 0; i <= 24; ++i)
        for (int j = 0; j <= 24; ++j)
          consider(s, arm, t, config, cx + ax * (i / 12.0 - 1), cp + ap * (j / 12.0 - 1), b);
      ax *= 0.6;
      ap *= 0.6;
    }
    if (b.energy < best.energy) best = b;
  }
  const Annulus an = annulus(arm.L1, arm.L2);
  const double ri = an.inner + s.singularity_margin, ro = an.outer - s.singularity_margin,
               L = s.length;
  const std::function<double(double)> families[] = {
      [&](double p) { return ri / std::sin(p); },  // tangent to the inner circle + margin
      [&](double p) {
        (void)p;
        return ro;
      },               // start on the outer circle - margin
      [&](double p) {  // end on the outer circle - margin
        const double d = ro * ro - L * L * std::sin(p) * std::sin(p);
        return d < 0 ? -1.0 : -L * std::cos(p) + std::sqrt(d);
      }};
  for (const auto& xs_of : families) {
    Fine b{std::numeric_limits<double>::infinity(), x0, p0};
    double c = p0, w = wp;
    for (int level = 0; level < 30; ++level) {
      const int n = level == 0 ? 2000 : 40;
      for (int j = 0; j <= n; ++j) {
        const double p = c + w * (2.0 * j / n - 1);
        consider(s, arm, t, config, xs_of(p), p, b);
      }
      if (!std::isfinite(b.energy)) break;
      c = b.phi;
      w *= level == 0 ? 0.01 : 0.3;
    }
    if (b.energy < best.energy) best = b;
  }
  return best;
}

TEST(PlacementRefine, ConstrainedRefinementEqualsAFineConstrainedSearch) {
  // line lengths no bundled case uses (they use 0.2, 0.4, 0.5, 0.8 and 1 Lmax)
  const struct {
    double fraction;
    core::MotionProgram program;
    int configuration;
  } runs[] = {{0.3, core::MotionProgram::kCycloidal, 1},
              {0.45, core::MotionProgram::kPoly345, 2},
              {0.6, core::MotionProgram::kCycloidal, 2},
              {0.7, core::MotionProgram::kPoly345, 1}};
  for (const auto& run : runs) {
    Spec s = small_spec(run.fraction);
    s.programs = {run.program};
    s.configurations = {run.configuration};
    const Result r = solve(s);
    ASSERT_EQ(r.cases.size(), 1u);
    const ProgramConfig& pc = r.cases[0];
    ASSERT_TRUE(pc.found) << run.fraction;
    EXPECT_TRUE(pc.refine_converged) << run.fraction << " " << pc.refine_tolerance_rel;
    EXPECT_LE(pc.refine_tolerance_rel, 1e-7);
    const Arm2 arm = make_arm2(s.chain);
    const ProgramTable t = make_program_table(run.program, s.duration, s.length, s.samples);
    const double hx = (0.6 - annulus(0.4, 0.2).inner) / s.nx_s;
    const Fine fine =
        fine_constrained_search(s, arm, t, run.configuration, pc.grid.x_s, pc.grid.phi, 3 * hx,
                                3 * std::max(s.phi_step, hx / pc.grid.x_s));
    // the refinement minimises the converged energy (the quadrature), the fine search the
    // sampled one: by the converged energy the refined optimum is not worse than the fine
    // search's point, and lies in the same basin (the sampled energy's O(h^2) error and
    // ripple move its optimum by ~1e-5 relative)
    const double e = pc.refined.convergence.energy;
    const EnergyQuadrature q_fine =
        energy_quadrature(arm, run.program, s.duration, s.length, thesis_line(fine.x_s, fine.phi),
                          run.configuration, 1e-11);
    std::printf(
        "L = %.2f Lmax: refined %.12g J (%s, %d evaluations), at the fine search's point %.12g "
        "J (its sampled energy %.12g J): lower by %.2e relative\n",
        run.fraction, e, binding_name(pc.decision.binding), pc.refine_evaluations, q_fine.energy,
        fine.energy, (q_fine.energy - e) / e);
    EXPECT_LE(e, q_fine.energy + pc.refined.convergence.energy_error + q_fine.error)
        << "L = " << run.fraction << " Lmax: refined " << e << " J at (" << pc.refined.x_s << ", "
        << pc.refined.phi / kDeg << " deg), fine search " << q_fine.energy << " J at (" << fine.x_s
        << ", " << fine.phi / kDeg << " deg), binding " << binding_name(pc.decision.binding);
    EXPECT_LT(q_fine.energy - e, 1e-4 * e) << run.fraction;
    EXPECT_EQ(pc.refined.status, CandidateStatus::kFeasible);
  }
}

TEST(PlacementRefine, MarginBoundOptimumSaysSoAndFallsWithTheMargin) {
  Spec s = small_spec(0.5);
  s.programs = {core::MotionProgram::kCycloidal};
  const Result r = solve(s);
  ASSERT_EQ(r.cases.size(), 2u);
  for (const ProgramConfig& pc : r.cases) {
    ASSERT_TRUE(pc.found);
    EXPECT_EQ(pc.decision.binding, Binding::kInnerClearance) << pc.configuration;
    EXPECT_NEAR(pc.decision.inner_slack, 0.0, 1e-9);
    EXPECT_GT(pc.decision.outer_slack, 1e-3);
    // re-solved at each margin: the energy falls as the margin shrinks
    ASSERT_EQ(pc.margin_sensitivity.size(), 4u);  // 0.005, 0.01 (the case's), 0.02, 0.05
    for (size_t k = 1; k < pc.margin_sensitivity.size(); ++k) {
      const MarginPoint& a = pc.margin_sensitivity[k - 1];
      const MarginPoint& b = pc.margin_sensitivity[k];
      ASSERT_TRUE(a.found && b.found);
      EXPECT_LT(a.margin, b.margin);
      EXPECT_LT(a.optimum.metrics.energy, b.optimum.metrics.energy) << a.margin << " " << b.margin;
      EXPECT_GE(b.optimum.boundary_distance, b.margin - 1e-12);
    }
  }
  EXPECT_NE(r.message.find("set by the 0.0100 m clearance margin to the inner circle"),
            std::string::npos)
      << r.message;
}

TEST(PlacementRefine, InteriorOptimumSaysInterior) {
  // a short line far from both circles: the energy's own minimum is admissible
  Spec s = small_spec(0.2);
  s.programs = {core::MotionProgram::kPoly345};
  s.configurations = {2};
  const Result r = solve(s);
  ASSERT_EQ(r.cases.size(), 1u);
  const ProgramConfig& pc = r.cases[0];
  ASSERT_TRUE(pc.found);
  EXPECT_EQ(pc.decision.binding, Binding::kInterior)
      << binding_name(pc.decision.binding) << " slacks " << pc.decision.inner_slack << " "
      << pc.decision.outer_slack;
  EXPECT_GT(std::min(pc.decision.inner_slack, pc.decision.outer_slack), 1e-4);
  EXPECT_TRUE(pc.margin_sensitivity.empty());
  EXPECT_NE(r.message.find("interior: no constraint binds"), std::string::npos) << r.message;
}

TEST(PlacementRefine, ParetoFrontsHoldAdmissiblePlacementsOnly) {
  Spec s = small_spec(0.5);
  s.programs = {core::MotionProgram::kPoly345};
  s.configurations = {2};
  const Result r = solve(s);
  const ProgramConfig& pc = r.cases.at(0);
  ASSERT_TRUE(pc.found);
  const Arm2 arm = make_arm2(s.chain);
  const ProgramTable t = make_program_table(pc.program, s.duration, s.length, s.samples);
  bool excluded_lower = false;
  for (int j = 0; j < 2; ++j) {
    ASSERT_FALSE(pc.pareto[j].empty());
    for (const ParetoPoint& p : pc.pareto[j]) {
      EXPECT_FALSE(p.singular);
      const Candidate c = evaluate_candidate(s, arm, t, pc.configuration, p.x_s, p.phi);
      EXPECT_EQ(c.status, CandidateStatus::kFeasible) << p.x_s << " " << p.phi;
      EXPECT_GE(c.boundary_distance, s.singularity_margin - 1e-12);
      // nothing on a front is below the reported optimum
      EXPECT_GE(p.energy, pc.refined.metrics.energy * (1 - 1e-12));
    }
    EXPECT_NEAR(pc.pareto[j].back().energy, pc.refined.metrics.energy, 1e-12);
    for (const ParetoPoint& p : pc.pareto_excluded[j]) {
      EXPECT_TRUE(p.singular);
      const Candidate c = evaluate_candidate(s, arm, t, pc.configuration, p.x_s, p.phi);
      EXPECT_EQ(c.status, CandidateStatus::kSingular);
      excluded_lower |= p.energy < pc.refined.metrics.energy;
    }
  }
  // inside the margin lies lower energy: that is why the margin decides the optimum
  EXPECT_TRUE(excluded_lower);
}

TEST(PlacementRefine, SingularMotionsYieldOnlyWhatConverges) {
  Spec s = small_spec(0.5);
  s.programs = {core::MotionProgram::kCycloidal};
  s.configurations = {2};
  // the thesis's printed optimum tangent to the inner circle (root at Y = 0.2000 m), a line
  // starting on the outer circle (stretched elbow at rest), and a regular one
  const double tangent_phi = core::kPi - std::asin(0.2 / 0.36);
  s.evaluations = {{"tangent", 0.36, tangent_phi},
                   {"outer-start", 0.6, 150 * kDeg},
                   {"regular", 0.5, 130 * kDeg}};
  const Result r = solve(s);
  ASSERT_EQ(r.evaluations.size(), 3u);
  for (int k = 0; k < 2; ++k) {
    const Evaluation& e = r.evaluations[size_t(k)];
    EXPECT_NE(e.candidate.status, CandidateStatus::kUnreachable) << e.label;
    EXPECT_TRUE(e.candidate.convergence.checked);
    EXPECT_TRUE(e.candidate.convergence.peak_withheld()) << e.label;
    EXPECT_FALSE(e.candidate.convergence.regular()) << e.label;
    EXPECT_TRUE(e.candidate.convergence.touches_boundary) << e.label;
  }
  // the tangent's energy is the limit of the lines just outside: its integral plus the
  // folded elbow's reversal term (PlacementQuadrature.TheFoldedElbowsEnergyIsTheLimitOf...);
  // the stretched start has a finite energy, with its error, and a saving
  const EnergyConvergence& tangent_c = r.evaluations[0].candidate.convergence;
  EXPECT_TRUE(tangent_c.touches_inner);
  EXPECT_TRUE(tangent_c.energy_converged());
  EXPECT_GT(tangent_c.energy_jump, 0.3 * tangent_c.energy);
  EXPECT_TRUE(r.evaluations[0].has_saving);
  const EnergyConvergence& outer_c = r.evaluations[1].candidate.convergence;
  EXPECT_FALSE(outer_c.touches_inner);
  EXPECT_TRUE(outer_c.energy_converged());
  EXPECT_LT(outer_c.energy_error, 1e-9 * outer_c.energy);
  EXPECT_DOUBLE_EQ(r.evaluations[1].candidate.metrics.energy, outer_c.energy);
  EXPECT_TRUE(r.evaluations[1].has_saving);
  // why: on the tangent the elbow folds and its rate jumps (an impulsive torque no sample
  // sees); at a stretched start the elbow rate has a square-root cusp and the sampled peak
  // torque grows like h^-1/2 without bound
  const Arm2 arm = make_arm2(s.chain);
  const Line tangent = thesis_line(0.36, tangent_phi);
  const double s_star = -tangent.start.dot(tangent.dir);
  for (const double eps : {1e-4, 1e-6, 1e-8}) {
    double qd2[2];
    for (int side = 0; side < 2; ++side) {
      const Eigen::Vector2d p = tangent.start + (s_star + (side ? eps : -eps)) * tangent.dir;
      qd2[side] = arm2_sample(arm, p.x(), p.y(), tangent.dir.x(), tangent.dir.y(), 0, 0, -1.0).qd2;
    }
    EXPECT_LT(qd2[0] * qd2[1], 0.0) << eps;  // the elbow rate reverses
    EXPECT_NEAR(std::abs(qd2[0]), std::abs(qd2[1]), 1e-3 * std::abs(qd2[0]));
    EXPECT_GT(std::abs(qd2[0]), 1.0) << eps;  // by a step that does not shrink
  }
  const auto& rows = r.evaluations[1].candidate.convergence.rows;
  ASSERT_GE(rows.size(), 3u);
  for (size_t k = 1; k < rows.size(); ++k)
    EXPECT_GT(rows[k].peak_torque, 1.3 * rows[k - 1].peak_torque) << rows[k].samples;
  const Evaluation& ok = r.evaluations[2];
  EXPECT_TRUE(ok.candidate.convergence.regular());
  EXPECT_TRUE(ok.has_saving);
  EXPECT_LT(ok.candidate.convergence.rel_change, 1e-4);
  EXPECT_LT(ok.candidate.convergence.energy_error, 1e-9 * ok.candidate.convergence.energy);
}

TEST(PlacementRefine, EveryOptimumHasItsOwnConvergenceAndCurveThroughItsOwnXs) {
  Spec s = small_spec(0.5);
  const Result r = solve(s);
  for (const ProgramConfig& pc : r.cases) {
    ASSERT_TRUE(pc.found);
    const EnergyConvergence& c = pc.refined.convergence;
    EXPECT_TRUE(c.checked && c.converged && c.regular());
    EXPECT_LT(c.rel_change, 1e-4);
    // the finer sample count of the converged pair, after at least two doublings (the peak's
    // change must shrink from one to the next)
    EXPECT_GE(c.samples, 4 * (s.samples - 1) + 1);
    EXPECT_EQ(c.rows.back().samples, c.samples);
    // the printed energy is the quadrature's, within its error of the sampled one's limit
    EXPECT_DOUBLE_EQ(c.metrics.energy, c.energy);
    EXPECT_LT(c.energy_error, 1e-9 * c.energy);
    EXPECT_NEAR(c.energy, pc.refined.metrics.energy, 1e-4 * c.energy);
    EXPECT_DOUBLE_EQ(pc.curve.x_s, pc.refined.x_s);
    bool through = false;
    for (size_t k = 0; k < pc.curve.phi.size(); ++k)
      through |=
          pc.curve.phi[k] == pc.refined.phi && pc.curve.energy[k] == pc.refined.metrics.energy;
    EXPECT_TRUE(through);
  }
}

TEST(PlacementRefine, ATorqueLimitThatBindsIsNamed) {
  Spec s = small_spec(0.5);
  s.programs = {core::MotionProgram::kPoly345};
  s.configurations = {1};
  const Result free = solve(s);
  ASSERT_TRUE(free.cases.at(0).found);
  const double limit = 0.8 * free.cases[0].refined.metrics.peak_torque[1];
  s.torque_limit = std::array<double, 2>{100.0, limit};
  const Result r = solve(s);
  const ProgramConfig& pc = r.cases.at(0);
  ASSERT_TRUE(pc.found);
  EXPECT_EQ(pc.decision.binding, Binding::kTorqueLimit) << binding_name(pc.decision.binding);
  EXPECT_EQ(pc.decision.joint, 1);
  EXPECT_LE(pc.refined.metrics.peak_torque[1], limit);
  EXPECT_LT(pc.decision.torque_slack[1], 1e-7 * limit);
  EXPECT_NE(r.message.find("set by the torque limit of joint 2"), std::string::npos) << r.message;
}

}  // namespace
}  // namespace armstudy::studies::placement
