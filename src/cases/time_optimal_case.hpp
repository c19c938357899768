// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// `study: time_optimal` case files -> studies::time_optimal::Spec.
///
/// The arm (`arm:`, see arm_loader.hpp) has active joints only: 2 links for a tip path
/// (`path`), 2 to core::kMaxLinks links for a path in joint space (`joint_path`, exactly one
/// of the two); a tip path for a redundant arm is refused (it fixes no joint motion). With a
/// joint path of other than 2 joints the velocity and torque limits must be given (the
/// defaults are the 2-link source's). Without `arm:` it is the source's model (Ozkipcak 1994):
/// massless links with a 1.0 kg point mass at the end of each, in a horizontal plane, with L1 = 0.5
/// m and L2 = 0.4 m (the source gives no lengths; studies::time_optimal::default_arm says why
/// these). `gravity:` may be non-zero: the torque limits must then also hold the arm up.
///
/// ```yaml
/// time_optimal:
///   path:
///     kind: line             # line (2 points), polyline (stops at every corner) or spline
///                            # (natural cubic through the points); default line
///     points_m: [[0.6, -0.3], [0.3, 0.5]]   # tip points, m, in the arm's base frame (>= 2)
///   joint_path:              # instead of `path`: the joint motion q(s) itself, s its
///                            # chord length in joint space (rad; see joint_path.hpp)
///     kind: spline           # line (2 waypoints), polyline (stops at every corner) or
///                            # spline (natural cubic through the waypoints); default line
///     points_rad: [[-2.3, 0.5, 0.4], [-1.2, -0.2, -0.1], [-0.8, -0.5, -0.4]]
///                            # waypoints, one relative joint angle (rad) per link (>= 2)
///     range_rad: [[-3, 0], [-1.5, 1.5], [-1.5, 1.5]]   # optional [lo, hi] per joint: the
///                            # whole path (the spline between waypoints too) must stay inside
///   configuration: 1         # tip paths: elbow 1 has q2 in (0, pi), 2 has q2 in (-pi, 0)
///                            # (default 1); not with a joint_path
///   velocity_limit_rad_s: [3.0, 4.0]        # |q_j'| per joint (one per link), rad/s, >= 0
///                                           # (default 3, 4 for 2 links)
///   torque_limit_Nm: [10.0, 4.0]            # |tau_j| per joint, N m, >= 0 (default 10, 4)
///   acceleration_limit_rad_s2: [50, 80]     # optional |q_j''| per joint, rad/s^2, >= 0
///   dp:                      # dynamic programming as in the source
///     segments: 10           # N, constant acceleration in each (default 10), in [2, 2000]
///                            # (a polyline: at least 2 per piece, the arm stops at corners)
///     levels: 200            # velocity levels per interior node (default 200), in [2, 20000]
///     checks_per_segment: 8  # points per segment where limits are checked, +1 (default 8)
///     states: [path_speed]   # one DP run per entry: path_speed (s', default) and/or
///                            # joint1_velocity (q1', the source's; needs q1 monotonic)
///     convergence_segments: [10, 20, 50, 100, 200]   # N of the convergence table ([]: none),
///                            # each with levels x N / segments velocity levels
///   complex:                 # Box's Complex method on the DP's segments
///     enabled: true          # default true
///     max_iterations: 20000  # reflections at most (default 20000)
///     tolerance: 1.0e-10     # relative spread of the complex's times at convergence
///     seed: 1                # of its random start points (default 1)
///   exact:                   # reachability analysis on a fine grid
///     grid_points: 1000      # nodes (default 1000), in [3, 100000]
///     checks_per_interval: 2 # sub-intervals per grid interval where limits hold (default 2)
///     grid_tolerance: 1.0e-3 # > 0: largest relative change of the duration when the exact
///                            # solver runs again with every grid interval halved (default
///                            # 1e-3); beyond it the check exact_grid_converged FAILS the case
///                            # and names the stretch of the path where the grid is too coarse
///     tolerance_rel: 1.0e-4  # graded grid: when the uniform grid changes by more than this
///                            # with every interval halved, its intervals holding half the
///                            # change are bisected, round after round, until the change is
///                            # within it (default 1e-4, >= 0; 0: keep the uniform grid)
///     max_grid_points: 200000 # most nodes of the graded grid (default 200000, at most 1e6)
///   motion_steps: 200        # equal time steps of the motion the frames show (default 200)
/// ```

#include "cases/yaml_reader.hpp"
#include "studies/time_optimal/spec.hpp"

namespace armstudy::cases {

/// The work and memory `spec` asks for (cases/budget.hpp), reported at `mark`.
Demand time_optimal_demand(const studies::time_optimal::Spec& spec, const YAML::Mark& mark);

/// Reads `arm:`, `gravity:` and `time_optimal:` from the case's root mapping. Every
/// problem is recorded in root.diag() at its file:line:col; the returned spec is
/// meaningful only when no error was recorded.
studies::time_optimal::Spec load_time_optimal(Map& root);

}  // namespace armstudy::cases
