// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// MuJoCo's own dynamics on the plans of the placement and time-optimal studies:
// the planned joint torques applied open loop through mj_step in the generated MJCF, from
// the plan's initial state, reproduce the planned motion within the tolerance h^2 V of
// scene/dynamic_replay.hpp for every bundled case; the deviation falls as h^2; a torque 5 %
// too large makes the check fail.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "cases/placement_case.hpp"
#include "cases/time_optimal_case.hpp"
#include "cases/yaml_reader.hpp"
#include "scene/dynamic_replay.hpp"
#include "scene/mujoco_model.hpp"
#include "scene/scene_error.hpp"
#include "scene/study_replays.hpp"
#include "studies/placement/solve.hpp"
#include "studies/time_optimal/solve.hpp"
#include "testing/case_keys.hpp"

namespace armstudy::scene {
namespace {
namespace to = studies::time_optimal;
namespace pl = studies::placement;

std::string bundled(const std::string& name) {
  return std::string(ARMSTUDY_SOURCE_DIR) + "/reports/cases/" + name + ".yaml";
}

template <typename Load>
auto load_bundled(const std::string& name, Load&& load) {
  const std::string path = bundled(name);
  cases::Diagnostics d(path);
  std::string text;
  const auto node = cases::parse_file(path, d, &text);
  EXPECT_TRUE(node) << path;
  cases::Map root(*node, d, "");
  testing::mark_cli_keys(root);
  auto spec = load(root);
  root.finish();
  EXPECT_TRUE(d.empty()) << path;
  return spec;
}

class DynamicReplayMujoco : public ::testing::Test {
 protected:
  void SetUp() override { take_mujoco_warnings(); }
  void TearDown() override { EXPECT_EQ(take_mujoco_warnings(), ""); }
};

void expect_faithful(const DynamicReplay& r, const std::string& what) {
  EXPECT_GT(r.tolerance, 0) << what;
  EXPECT_LE(r.max_deviation, r.tolerance) << what << " at t = " << r.max_deviation_t << " s";
  EXPECT_TRUE(replay_check(r, "mujoco_dynamic_replay", what).passed) << what;
  // the deviation is the torque hold's second-order error: about 4x at twice the step
  EXPECT_GT(r.observed_order, 1.5)
      << what << ": " << r.coarse_max_deviation << " at 2h, " << r.max_deviation << " at h";
  // the simulated motion covers the plan: recorded from start to end
  ASSERT_GE(r.t.size(), 100u);
  EXPECT_NEAR(r.t.back(), r.duration, 1e-9 * r.duration) << what;
  char b[64];
  std::snprintf(b, sizeof b, "%.3g of %.3g", r.max_deviation, r.tolerance);
  ::testing::Test::RecordProperty(what + "_max_deviation_rad", b);
}

TEST_F(DynamicReplayMujoco,
       EveryBundledTimeOptimalPlanReplaysWithinItsToleranceAndAWrongTorqueFails) {
  for (const char* name :
       {"time-optimal-source", "time-optimal-spline", "time-optimal-nonmonotonic"}) {
    to::Spec spec =
        load_bundled(name, [](cases::Map& root) { return cases::load_time_optimal(root); });
    // only the exact solution is replayed: the other solvers are not needed here
    spec.dp.states = {};
    spec.dp.convergence_segments = {};
    spec.complex.enabled = false;
    const to::Result res = to::solve(spec);
    ASSERT_EQ(res.status, studies::Status::kSolved) << name << ": " << res.message;
    const DynamicReplay r = replay_time_optimal(spec, res);
    EXPECT_NEAR(r.duration, res.solvers.front().duration, 1e-12) << name;
    expect_faithful(r, name);
    // the same plan with every torque 5 % too large: far outside the tolerance
    const DynamicReplay wrong = replay_time_optimal(spec, res, 1.05);
    EXPECT_FALSE(replay_check(wrong, "mujoco_dynamic_replay", name).passed) << name;
    EXPECT_GT(wrong.max_deviation, 10 * wrong.tolerance) << name;
  }
}

TEST_F(DynamicReplayMujoco,
       EveryBundledPlacementOptimumReplaysWithinItsToleranceAndAWrongTorqueFails) {
  for (int n = 1; n <= 5; ++n) {
    const std::string name = "placement-example-" + std::to_string(n);
    pl::Spec spec =
        load_bundled(name, [](cases::Map& root) { return cases::load_placement(root); });
    // the bundled arm, line, duration and programs on a coarser sweep (seconds, not minutes):
    // the optima move a little, the motions replayed are of the same kind
    spec.nx_s = 12;
    spec.phi_step = 4 * core::kPi / 180;
    spec.map_nx = 8;
    spec.map_ny = 4;
    spec.evaluations.clear();
    const pl::Result res = pl::solve(spec);
    // example 1 (L = Lmax) has no admissible placement by design ('expect: unsolvable'):
    // there is no plan to replay
    if (n == 1) {
      EXPECT_EQ(res.status, studies::Status::kUnsolvable) << name;
      continue;
    }
    ASSERT_EQ(res.status, studies::Status::kSolved) << name << ": " << res.message;
    const std::vector<PlacementReplay> rs = replay_placement(spec, res);
    int found = 0;
    for (const auto& pc : res.cases) found += pc.found;
    ASSERT_EQ(static_cast<int>(rs.size()), found) << name;
    ASSERT_GT(found, 0) << name;
    for (const PlacementReplay& r : rs)
      expect_faithful(r.replay, name + "_" + std::string(core::program_name(r.program)) + "_c" +
                                    std::to_string(r.configuration));
    const std::vector<PlacementReplay> wrong = replay_placement(spec, res, 1.05);
    for (const PlacementReplay& r : wrong) {
      EXPECT_FALSE(replay_check(r.replay, "mujoco_dynamic_replay", name).passed) << name;
      EXPECT_GT(r.replay.max_deviation, 10 * r.replay.tolerance) << name;
    }
  }
}

}  // namespace
}  // namespace armstudy::scene
