// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The placement optimum is the minimum of the converged energy (the adaptive quadrature),
// not of the 401-sample energy, and its printed figures carry their errors: the refined
// optimum against an independent nested golden-section search on the quadrature, the
// printed energy against the same solve at twice the samples, and a configuration against
// its mirror image.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <utility>

#include "studies/placement/geometry.hpp"
#include "studies/placement/quadrature.hpp"
#include "studies/placement/refine.hpp"
#include "studies/placement/solve.hpp"
#include "testing/arms.hpp"

namespace armstudy::studies::placement {
namespace {

using armstudy::testing::kDeg;

// the coarse sweep of placement_refine_test.cpp: the refinement does the rest
Spec converged_optimum_spec(double fraction, core::MotionProgram program) {
  Spec s;
  s.chain = testing::thesis_arm();
  s.length = fraction * annulus(0.4, 0.2).lmax;
  s.nx_s = 16;
  s.phi_step = 3 * kDeg;
  s.map_nx = 8;
  s.map_ny = 4;
  s.programs = {program};
  s.sensitivity_margins = {};
  return s;
}

// golden-section minimum of f on [a, b], to a bracket narrower than tol: (argmin, min)
std::pair<double, double> golden_minimum(const std::function<double(double)>& f, double a, double b,
                                         double tol) {
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - r * (b - a), d = a + r * (b - a), fc = f(c), fd = f(d);
  while (b - a > tol) {
    if (fc <= fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - r * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + r * (b - a);
      fd = f(d);
    }
  }
  return fc <= fd ? std::make_pair(c, fc) : std::make_pair(d, fd);
}

TEST(PlacementConvergedOptimum, TheRefinedOptimumIsTheQuadraturesMinimumWithinItsStatedError) {
  // interior optima, where the energy's own minimum decides: a short line far from both
  // circles (0.2 Lmax) and a long one (0.8 Lmax)
  const struct {
    double fraction;
    core::MotionProgram program;
    int configuration;
  } runs[] = {{0.2, core::MotionProgram::kPoly345, 2}, {0.8, core::MotionProgram::kPoly345, 2}};
  for (const auto& run : runs) {
    Spec s = converged_optimum_spec(run.fraction, run.program);
    s.configurations = {run.configuration};
    const Result r = solve(s);
    ASSERT_EQ(r.cases.size(), 1u);
    const ProgramConfig& pc = r.cases[0];
    ASSERT_TRUE(pc.found);
    ASSERT_EQ(pc.decision.binding, Binding::kInterior) << run.fraction;
    ASSERT_TRUE(pc.refine_converged) << pc.refine_tolerance_rel;
    // independent of the refinement: from the sweep's optimum, the least energy over phi
    // at each x_s (golden section), minimised over x_s (golden section), on the quadrature
    // asked for 1e-12
    const Arm2 arm = make_arm2(s.chain);
    const auto energy = [&](double x, double ph) {
      // only admissible lines compete (beyond the margin lie lower energies)
      const LineCheck chk = check_line(arm.L1, arm.L2, thesis_line(x, ph), s.length);
      if (chk.boundary_distance < s.singularity_margin)
        return std::numeric_limits<double>::infinity();
      return energy_quadrature(arm, run.program, s.duration, s.length, thesis_line(x, ph),
                               run.configuration, 1e-12)
          .energy;
    };
    // a bracket of one sweep step either side of the sweep's optimum
    const double wx = (0.6 - 0.2) / s.nx_s, wp = s.phi_step, tol_x = 1e-10, tol_p = 1e-10;
    double phi_at_best = 0;
    const auto least_over_phi = [&](double x) {
      const auto [ph, e] = golden_minimum([&](double p) { return energy(x, p); }, pc.grid.phi - wp,
                                          pc.grid.phi + wp, tol_p);
      phi_at_best = ph;
      return e;
    };
    const auto [x_ref, e_ref] =
        golden_minimum(least_over_phi, pc.grid.x_s - wx, pc.grid.x_s + wx, tol_x);
    least_over_phi(x_ref);
    const double phi_ref = phi_at_best;
    const double e = pc.refined.convergence.energy;
    std::printf(
        "L = %.2f Lmax: refined (%.12f m, %.10f deg) +- (%.1e m, %.1e deg), %.12g J; "
        "golden section (%.12f m, %.10f deg), %.12g J\n",
        run.fraction, pc.refined.x_s, pc.refined.phi / kDeg, pc.x_s_error, pc.phi_error / kDeg, e,
        x_ref, phi_ref / kDeg, e_ref);
    // agreement within the stated error (and the reference's own bracket)
    EXPECT_LE(std::abs(pc.refined.x_s - x_ref), pc.x_s_error + tol_x) << run.fraction;
    EXPECT_LE(std::abs(pc.refined.phi - phi_ref), pc.phi_error + tol_p) << run.fraction;
    EXPECT_LE(std::abs(e - e_ref), pc.energy_error()) << run.fraction;
    // and the stated error is not loose
    EXPECT_LT(pc.x_s_error, 1e-6 * pc.refined.x_s) << run.fraction;
    EXPECT_LT(pc.phi_error, 1e-6 * pc.refined.phi) << run.fraction;
    EXPECT_LT(pc.energy_error(), 1e-8 * e) << run.fraction;
  }
}

TEST(PlacementConvergedOptimum, ThePrintedEnergyHoldsAtTwiceTheSamplesAndInTheMirrorImage) {
  // an interior optimum (0.2 Lmax) and one on the clearance margin to the inner circle
  // (0.5 Lmax), both configurations (mirror images of each other)
  const struct {
    double fraction;
    core::MotionProgram program;
  } runs[] = {{0.2, core::MotionProgram::kPoly345}, {0.5, core::MotionProgram::kCycloidal}};
  for (const auto& run : runs) {
    Spec s = converged_optimum_spec(run.fraction, run.program);
    const Result r = solve(s);
    Spec s2 = s;
    s2.samples = 2 * (s.samples - 1) + 1;
    const Result r2 = solve(s2);
    ASSERT_EQ(r.cases.size(), 2u);
    ASSERT_EQ(r2.cases.size(), 2u);
    for (size_t k = 0; k < 2; ++k) {
      const ProgramConfig& a = r.cases[k];
      const ProgramConfig& b = r2.cases[k];
      ASSERT_TRUE(a.found && b.found);
      const double ea = a.refined.convergence.energy, eb = b.refined.convergence.energy;
      std::printf(
          "L = %.2f Lmax, configuration %d (%s): %.12g J +- %.1e at %d samples, %.12g J at %d "
          "(change %.1e)\n",
          run.fraction, a.configuration, binding_name(a.decision.binding), ea, a.energy_error(),
          s.samples, eb, s2.samples, eb - ea);
      EXPECT_LT(std::abs(eb - ea), a.energy_error()) << run.fraction << " " << a.configuration;
      EXPECT_LT(a.energy_error(), 1e-8 * ea);
    }
    // the mirror image: the same least energy within the two errors
    const ProgramConfig& c1 = r.cases[0];
    const ProgramConfig& c2 = r.cases[1];
    EXPECT_LE(std::abs(c1.refined.convergence.energy - c2.refined.convergence.energy),
              c1.energy_error() + c2.energy_error())
        << run.fraction;
  }
}

}  // namespace
}  // namespace armstudy::studies::placement
