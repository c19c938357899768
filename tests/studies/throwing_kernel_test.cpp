// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The simulation kernel (simulate_kernel.hpp), one profile at a time and two to five at once, gives
// the Planner's evaluations (ThrowSetup::kernel_lanes 0, one evaluation at a time) bit for
// bit: feasible, infeasible, early-stopped and diverging profiles, in pairs whose lanes end
// at different points, resumed from checkpoints, and through IDP and the SLSQP gradient's
// neighbours.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <set>

#include "studies/throwing/idp.hpp"
#include "studies/throwing/simulate.hpp"
#include "studies/throwing/simulate_kernel.hpp"
#include "studies/throwing/solve.hpp"

namespace armstudy::studies {
namespace {

uint64_t bits(double x) { return std::bit_cast<uint64_t>(x); }

// every field of two evaluations, bit for bit (NaN included)
void expect_bitwise(const ProfileEvaluation& a, const ProfileEvaluation& b, const std::string& at) {
  SCOPED_TRACE(at);
  EXPECT_EQ(bits(a.energy), bits(b.energy));
  EXPECT_EQ(bits(a.max_abs_theta4), bits(b.max_abs_theta4));
  EXPECT_EQ(bits(a.max_voltage), bits(b.max_voltage));
  EXPECT_EQ(bits(a.max_current), bits(b.max_current));
  EXPECT_EQ(bits(a.max_power), bits(b.max_power));
  EXPECT_EQ(bits(a.min_normal_force), bits(b.min_normal_force));
  EXPECT_EQ(bits(a.max_friction_ratio), bits(b.max_friction_ratio));
  EXPECT_EQ(bits(a.max_friction_excess), bits(b.max_friction_excess));
  EXPECT_EQ(bits(a.theta3_final), bits(b.theta3_final));
  EXPECT_EQ(bits(a.theta4_final), bits(b.theta4_final));
  EXPECT_EQ(bits(a.theta3_rate_final), bits(b.theta3_rate_final));
  EXPECT_EQ(bits(a.theta4_rate_final), bits(b.theta4_rate_final));
  EXPECT_EQ(bits(a.violation), bits(b.violation));
  EXPECT_EQ(a.finite, b.finite);
  EXPECT_EQ(a.feasible, b.feasible);
  EXPECT_EQ(a.stopped, b.stopped);
  auto same = [](const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() != y.size()) return false;
    for (size_t i = 0; i < x.size(); ++i)
      if (bits(x[i]) != bits(y[i])) return false;
    return true;
  };
  EXPECT_TRUE(same(a.stage_theta4, b.stage_theta4));
  EXPECT_TRUE(same(a.stage_voltage, b.stage_voltage));
  EXPECT_TRUE(same(a.stage_current, b.stage_current));
  EXPECT_TRUE(same(a.stage_power, b.stage_power));
  EXPECT_TRUE(same(a.stage_normal, b.stage_normal));
  EXPECT_TRUE(same(a.stage_friction, b.stage_friction));
}

struct Case {
  ThrowingSpec spec;
  ThrowSetup setup;
  VelocityProfile eq8;
  Eigen::Vector2d delta;
  explicit Case(Motor2Mount mount, double rotor_inertia, int stages = 16, int steps = 20) {
    spec.arm.motor2 = mount;
    spec.arm.rotor_inertia = rotor_inertia;
    spec.stages = stages;
    spec.steps_per_stage = steps;
    setup = make_throw_setup(spec);
    eq8 = eq8_profile(spec.start, Eigen::Vector2d::Zero(), spec.release, spec.release_rate, spec.tf,
                      spec.stages);
    delta = spec.release - spec.start;
  }
  ThrowSetup with_lanes(int lanes) const {
    ThrowSetup s = setup;
    s.kernel_lanes = lanes;
    return s;
  }
  // eq. 8 moved by `scale` times a random direction (projected)
  VelocityProfile random(std::mt19937& rng, double scale) const {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    VelocityProfile p = eq8;
    for (int k = 1; k < p.stages(); ++k) p.v.col(k) += scale * Eigen::Vector2d(u(rng), u(rng));
    project_displacement(p, delta);
    return p;
  }
};

TEST(ThrowKernel, AppliesToTheTrayArmOnly) {
  Case c(Motor2Mount::kOnLink1, 0.0);
  EXPECT_TRUE(kernel_applies(c.setup));
  ThrowSetup g = c.setup;
  g.generic_dynamics = true;
  EXPECT_FALSE(kernel_applies(g));
  EXPECT_THROW(simulate_kernel(g, c.eq8, 0.02, false), std::invalid_argument);
}

TEST(ThrowKernel, OneToFiveAtOnceEqualThePlannerBitForBit) {
  // the bundled case's limits (most random profiles break some limit, many early) and wide
  // ones (eq. 8 and the small moves feasible; once without regeneration); the large moves
  // make some diverge
  int stopped = 0, feasible = 0, diverged = 0, total = 0;
  for (Motor2Mount mount : {Motor2Mount::kOnLink1, Motor2Mount::kOnBase})
    for (double rotor : {0.0, 2e-6}) {
      Case c(mount, rotor);
      if (rotor > 0) {
        c.spec.power_max = 200;
        c.spec.current_max = 10;
        c.spec.release_tolerance = 0.6;
        // eq. 7 without regeneration on one mount
        c.spec.count_regeneration = mount == Motor2Mount::kOnBase;
        c.setup = make_throw_setup(c.spec);
      }
      const ThrowSetup planner = c.with_lanes(0), one = c.with_lanes(1);
      std::mt19937 rng(11);
      std::vector<VelocityProfile> ps;
      for (double scale : {0.05, 0.3, 1.0, 3.0, 30.0, 300.0})
        for (int i = 0; i < 6; ++i) ps.push_back(c.random(rng, scale));
      ps.push_back(c.eq8);
      for (bool stop : {false, true}) {
        std::vector<ProfileEvaluation> ref;
        for (size_t i = 0; i < ps.size(); ++i) {
          ref.push_back(simulate_profile(planner, ps[i], nullptr, 0.02, stop));
          const std::string at = "profile " + std::to_string(i) + (stop ? " stop" : "");
          expect_bitwise(simulate_profile(one, ps[i], nullptr, 0.02, stop), ref[i], at);
          ++total;
          stopped += ref[i].stopped;
          feasible += ref[i].feasible;
          diverged += !ref[i].finite;
        }
        // pairs and quadruples of many combinations, so that lanes end at different points
        for (size_t i = 0; i < ps.size(); i += 3)
          for (size_t j = 0; j < ps.size(); j += 2) {
            ProfileEvaluation two[2];
            simulate_kernel_lanes(one, {&ps[i], &ps[j]}, 2, 0.02, stop, two);
            const std::string at = "pair " + std::to_string(i) + ", " + std::to_string(j);
            expect_bitwise(two[0], ref[i], at);
            expect_bitwise(two[1], ref[j], at);
            const size_t idx[5] = {i, j, (i + 7 * j + 1) % ps.size(), (3 * i + j + 5) % ps.size(),
                                   (5 * i + 3 * j + 2) % ps.size()};
            for (int w : {3, 4, 5}) {
              std::vector<const VelocityProfile*> group;
              for (int q = 0; q < w; ++q) group.push_back(&ps[idx[q]]);
              ProfileEvaluation evs[5];
              simulate_kernel_lanes(one, group, w, 0.02, stop, evs);
              for (int q = 0; q < w; ++q)
                expect_bitwise(evs[q], ref[idx[q]],
                               std::to_string(w) + " lanes, lane " + std::to_string(q) + " " + at);
            }
          }
        for (int lanes : {2, 3, 4, 5}) {
          const auto evs = evaluate_profiles(c.with_lanes(lanes), ps, 2, 0.02, stop);
          for (size_t i = 0; i < ps.size(); ++i)
            expect_bitwise(evs[i], ref[i], "evaluate_profiles " + std::to_string(i));
        }
      }
    }
  // the cases the lanes must keep apart occurred
  EXPECT_GT(stopped, 20);
  EXPECT_GT(feasible, 5);
  EXPECT_GT(diverged, 5);
  EXPECT_GT(total - stopped - diverged, 20);
}

TEST(ThrowKernel, ProfilesOfOtherStagesOrFinalTimesRunApart) {
  // a group of lanes holds profiles of the same stages and final time only; the others run
  // in groups of their own (and a width above five runs as five)
  Case c(Motor2Mount::kOnLink1, 0.0);
  Case eight(Motor2Mount::kOnLink1, 0.0, 8);
  VelocityProfile later = c.eq8;
  later.tf = 0.85;
  project_displacement(later, c.delta);
  std::mt19937 rng(2);
  const std::vector<VelocityProfile> ps{
      c.random(rng, 0.3), eight.eq8,         c.random(rng, 0.3), later, c.eq8,
      c.random(rng, 1.0), c.random(rng, 0.3)};
  std::vector<const VelocityProfile*> group;
  for (const VelocityProfile& p : ps) group.push_back(&p);
  for (int width : {2, 4, 7}) {
    std::vector<ProfileEvaluation> evs(ps.size());
    simulate_kernel_lanes(c.setup, group, width, 0.02, false, evs.data());
    for (size_t i = 0; i < ps.size(); ++i)
      expect_bitwise(evs[i], simulate_profile(c.with_lanes(0), ps[i], nullptr, 0.02),
                     "width " + std::to_string(width) + ", profile " + std::to_string(i));
  }
  EXPECT_EQ(simulate_profile(c.setup, eight.eq8).stage_power.size(), 8u);
}

TEST(ThrowKernel, NeighboursResumedInLanesEqualThePlanner) {
  for (Motor2Mount mount : {Motor2Mount::kOnLink1, Motor2Mount::kOnBase}) {
    Case c(mount, 2e-6);
    std::mt19937 rng(5);
    const VelocityProfile x = c.random(rng, 0.5);
    std::vector<VelocityProfile> ps{x};
    std::vector<int> first{0};
    for (int k = 1; k < x.stages(); ++k)
      for (int j = 0; j < 2; ++j)
        for (double step : {1e-5, -1e-5, 3.0}) {
          VelocityProfile p = x;
          p.v(j, k) += step;
          ps.push_back(p);
          first.push_back(k - 1);
        }
    const auto ref = evaluate_neighbours(c.with_lanes(0), ps, first, 1, 0.02);
    for (int lanes : {1, 2, 3, 4, 5}) {
      const auto evs = evaluate_neighbours(c.with_lanes(lanes), ps, first, 2, 0.02);
      ASSERT_EQ(ref.size(), evs.size());
      for (size_t i = 0; i < ps.size(); ++i)
        expect_bitwise(evs[i], ref[i],
                       std::to_string(lanes) + " lanes, neighbour " + std::to_string(i));
    }
    // checkpoints of the kernel equal the Planner's
    SimulationCheckpoints a, b;
    expect_bitwise(simulate_profile(c.with_lanes(0), x, a, 0.02),
                   simulate_profile(c.with_lanes(1), x, b, 0.02), "checkpointed");
    ASSERT_EQ(a.x.size(), b.x.size());
    for (size_t k = 0; k < a.x.size(); ++k) {
      for (int i = 0; i < 5; ++i) EXPECT_EQ(bits(a.x[k][i]), bits(b.x[k][i])) << k;
      EXPECT_EQ(bits(a.friction_ratio[k]), bits(b.friction_ratio[k])) << k;
    }
  }
}

TEST(ThrowKernel, IdpInLanesMakesThePlannersChoices) {
  Case c(Motor2Mount::kOnLink1, 0.0, 8, 8);
  c.spec.power_max = 200;
  c.spec.current_max = 10;
  c.spec.release_tolerance = 0.6;
  c.setup = make_throw_setup(c.spec);
  IdpSettings s;
  s.iterations = 3;
  s.max_passes = 3;
  s.threads = 2;
  s.backoff = 0.02;
  const IdpResult b = run_idp(c.with_lanes(0), c.eq8, c.delta, s);
  for (int lanes : {2, 4, 5}) {
    const IdpResult a = run_idp(c.with_lanes(lanes), c.eq8, c.delta, s);
    EXPECT_EQ(a.best.v, b.best.v);
    expect_bitwise(a.evaluation, b.evaluation, "best");
    EXPECT_EQ(a.evaluations, b.evaluations);
    ASSERT_EQ(a.history.size(), b.history.size());
    for (size_t i = 0; i < a.history.size(); ++i) {
      EXPECT_EQ(bits(a.history[i].energy), bits(b.history[i].energy));
      EXPECT_EQ(a.history[i].improvements, b.history[i].improvements);
    }
  }
  EXPECT_LT(b.evaluation.energy, b.initial_evaluation.energy);  // it did move
}

TEST(ThrowKernel, SeedsSideBySideRunEachSeedsOwnIdp) {
  // eq. 8 a fifth over the power limit: the seeds become feasible at different nodes, so their
  // candidates in one group of lanes stop early or not each by its own seed's best
  Case c(Motor2Mount::kOnLink1, 0.0, 8, 8);
  c.spec.current_max = 10;
  c.spec.release_tolerance = 0.6;
  c.setup = make_throw_setup(c.spec);
  c.spec.power_max = simulate_profile(c.setup, c.eq8).max_power / 1.2;
  c.setup = make_throw_setup(c.spec);
  ASSERT_FALSE(simulate_profile(c.setup, c.eq8, nullptr, 0.02).feasible);
  IdpSettings s;
  s.iterations = 2;
  s.max_passes = 4;
  s.seeds = 3;
  s.backoff = 0.02;
  std::vector<IdpResult> alone;
  for (int i = 0; i < s.seeds; ++i) {
    IdpSettings one = s;
    one.seed = s.seed + static_cast<unsigned>(i);
    one.threads = 1;
    alone.push_back(run_idp(c.with_lanes(0), c.eq8, c.delta, one));
  }
  // the iteration in which each seed's best first is feasible: not the same for all
  std::set<size_t> first_feasible;
  for (const IdpResult& r : alone) {
    size_t k = 0;
    while (k < r.history.size() && r.history[k].violation > 0) ++k;
    first_feasible.insert(k);
  }
  EXPECT_GT(first_feasible.size(), 1u);
  EXPECT_LT(*first_feasible.begin(), alone[0].history.size());
  for (int threads : {1, 2})
    for (bool side : {false, true}) {
      s.threads = threads;
      s.seeds_side_by_side = side;
      const auto runs = run_idp_seeds(c.setup, c.eq8, c.delta, s);
      ASSERT_EQ(runs.size(), alone.size());
      for (size_t i = 0; i < runs.size(); ++i) {
        const std::string at = std::to_string(threads) + " threads, side by side " +
                               std::to_string(side) + ", seed " + std::to_string(i);
        EXPECT_EQ(runs[i].best.v, alone[i].best.v) << at;
        expect_bitwise(runs[i].evaluation, alone[i].evaluation, at);
        EXPECT_EQ(runs[i].evaluations, alone[i].evaluations) << at;
        EXPECT_EQ(runs[i].passes, alone[i].passes) << at;
        EXPECT_EQ(runs[i].converged, alone[i].converged) << at;
        ASSERT_EQ(runs[i].history.size(), alone[i].history.size()) << at;
        for (size_t k = 0; k < runs[i].history.size(); ++k) {
          EXPECT_EQ(bits(runs[i].history[k].energy), bits(alone[i].history[k].energy)) << at;
          EXPECT_EQ(runs[i].history[k].improvements, alone[i].history[k].improvements) << at;
        }
      }
    }
}

}  // namespace
}  // namespace armstudy::studies
