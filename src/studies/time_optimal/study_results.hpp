// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The time-optimal study's part of results.json as a typed value: what the pipeline
/// writes (app/time_optimal_pipeline.cpp fills it from the Result) and what the report and
/// `armstudy merge` read back. `fields` names every key once: report/results_fields.hpp
/// turns it into the writer, the strict reader and the schema (results.schema.json). SI
/// units, angles in rad; per-joint quantities hold one value (or one row) per joint. The
/// path parameter s is the tip's arc length in m for a tip path (2 links) and the
/// joint-space chord length in rad for a joint-space path (any number of links): keys of s
/// and its derivatives carry no unit in their names, path.s_unit gives it ("m" or "rad").

#include <optional>
#include <string>
#include <vector>

#include "studies/replay_results.hpp"

namespace armstudy::studies::time_optimal {

struct StudyResults {
  using Rows = std::vector<std::vector<double>>;
  struct Path {
    std::string space, kind, s_unit;
    std::optional<Rows> points_m, points_rad, range_rad;
  };
  struct Limits {
    std::vector<double> velocity_rad_s, torque_Nm;
    std::optional<std::vector<double>> acceleration_rad_s2;
  };
  struct Ratio {
    std::vector<double> velocity, torque, acceleration;
  };
  struct Violation {
    double worst = 0;
    std::string text, kind;
    int joint = 1;
    double s = 0, t_s = 0;
    int interval = 0;
    Ratio ratio;
  };
  struct Samples {
    std::vector<double> t_s, s, sd, sdd;
    Rows q_rad, qd_rad_s, qdd_rad_s2, tau_Nm;
  };
  struct Solver {
    std::string name, method;
    bool solved = false;
    std::string message;
    double duration_s = 0, run_time_s = 0;
    int intervals = 0, levels = 0;
    long evaluations = 0;
    int iterations = 0;
    std::optional<Violation> violation;  ///< the rest: only when solved
    std::optional<std::vector<double>> node_s, node_sd, node_t_s;
    std::optional<int> node_stride;  ///< node_* hold every node_stride-th node and the last
    std::optional<Samples> samples;
  };
  struct Mvc {
    std::vector<double> s, sd, velocity_sd;
    std::optional<int> stride;  ///< every stride-th grid point and the last
  };
  struct ConvergenceRow {
    int segments = 0, levels = 0;
    bool solved = false;
    double duration_s = 0, excess = 0, run_time_s = 0, worst_violation = 0;
    std::string message;
  };
  struct Motion {
    std::vector<double> t_s, s;
    Rows tip_m, q_rad;
    std::optional<int> stride;  ///< every stride-th time step and the last
  };
  struct Extrapolation {
    int coarse_points = 0;
    double coarse_duration_s = 0;
    int quarter_points = 0;
    double quarter_duration_s = 0, order = 0;
    bool asymptotic = false;
    double duration_s = 0, one_grid_down_s = 0, two_grids_down_s = 0, error_s = 0;
  };
  struct Graded {
    int uniform_points = 0;
    double uniform_change = 0;
    int rounds = 0;
    double tolerance_rel = 0;
    int max_grid_points = 0;
    bool capped = false;
  };
  struct GridConvergence {
    int grid_points = 0, refined_points = 0;
    bool refined_solved = false;
    double duration_s = 0, refined_duration_s = 0, change = 0, tolerance = 0;
    bool passed = false;
    std::vector<double> s_range;
    std::vector<int> grid_point_range;
    double share = 0, max_sd = 0, min_abs_sin_q2 = 0, path_min_abs_sin_q2 = 0;
    std::string text;
    std::optional<Extrapolation> extrapolation;
    std::optional<Graded> graded;
  };
  Path path;
  double path_length = 0;
  int joints = 2;
  std::optional<int> configuration;
  Limits limits;
  std::vector<Solver> solvers;  ///< exact first
  Mvc mvc;
  std::vector<ConvergenceRow> convergence;
  Motion motion;
  std::optional<GridConvergence> grid_convergence;
  std::optional<ReplayResults> mujoco_replay;
  /// an arm read from a model file (arm.model): where it and each limit came from
  std::optional<std::vector<std::string>> arm_model;
};

template <class V>
void fields(V& v, StudyResults::Path& x) {
  v("space", x.space, "tip (a tip path of a 2-link arm) or joint (a path in joint space)");
  v("kind", x.kind, "line, polyline or spline");
  v("s_unit", x.s_unit,
    "unit of the path parameter s: m (tip arc length) or rad (joint-space chord length)");
  v("points_m", x.points_m, "the tip path's points [x, y] in m (null for a joint-space path)");
  v("points_rad", x.points_rad,
    "the joint-space path's waypoints [q1, ..., qn] in rad (null for a tip path)");
  v("range_rad", x.range_rad,
    "joint ranges [lo, hi] in rad the path must stay in (null: none given)");
}
template <class V>
void fields(V& v, StudyResults::Limits& x) {
  v("velocity_rad_s", x.velocity_rad_s, "joint velocity limits, per joint");
  v("torque_Nm", x.torque_Nm, "joint torque limits, per joint");
  v("acceleration_rad_s2", x.acceleration_rad_s2,
    "joint acceleration limits, per joint (null: none)");
}
template <class V>
void fields(V& v, StudyResults::Ratio& x) {
  v("velocity", x.velocity, "largest |qd| / limit, per joint");
  v("torque", x.torque, "largest |tau| / limit, per joint");
  v("acceleration", x.acceleration, "largest |qdd| / limit, per joint");
}
template <class V>
void fields(V& v, StudyResults::Violation& x) {
  v("worst", x.worst, "largest limit use - 1 over the dense resampling (<= 0: every limit met)");
  v("text", x.text, "names the grid point, binding limit and margin");
  v("kind", x.kind, "the limit of the worst use: velocity, torque or acceleration");
  v("joint", x.joint, "joint of the worst use (1-based)");
  v("s", x.s, "path position of the worst use (path.s_unit)");
  v("t_s", x.t_s, "time of the worst use");
  v("interval", x.interval, "solver interval of the worst use");
  v("ratio", x.ratio, "largest use of each limit");
}
template <class V>
void fields(V& v, StudyResults::Samples& x) {
  v("t_s", x.t_s, "sample times");
  v("s", x.s, "path position (path.s_unit)");
  v("sd", x.sd, "path speed s' (path.s_unit per s)");
  v("sdd", x.sdd, "path acceleration s'' (path.s_unit per s^2)");
  v("q_rad", x.q_rad, "joint angles, one row per joint");
  v("qd_rad_s", x.qd_rad_s, "joint velocities, one row per joint");
  v("qdd_rad_s2", x.qdd_rad_s2, "joint accelerations, one row per joint");
  v("tau_Nm", x.tau_Nm, "joint torques (inverse dynamics), one row per joint");
}
template <class V>
void fields(V& v, StudyResults::Solver& x) {
  v("name", x.name, "exact, dp, dp_joint1 or complex");
  v("method", x.method, "the method as a sentence");
  v("solved", x.solved, "whether the solver found a motion");
  v("message", x.message, "why not, when not solved");
  v("duration_s", x.duration_s, "duration of the motion (null when not solved)");
  v("run_time_s", x.run_time_s, "wall time of the solver");
  v("intervals", x.intervals, "path intervals N");
  v("levels", x.levels, "DP velocity levels (0 otherwise)");
  v("evaluations", x.evaluations, "DP transitions or Complex objective calls");
  v("iterations", x.iterations, "Complex reflections");
  v.optional("violation", x.violation, "limit use over the dense resampling (when solved)");
  v.optional("node_s", x.node_s, "path position at the solver's nodes, path.s_unit (when solved)");
  v.optional("node_sd", x.node_sd,
             "path speed at the solver's nodes, path.s_unit per s (when solved)");
  v.optional("node_t_s", x.node_t_s, "time at the solver's nodes (when solved)");
  v.optional("node_stride", x.node_stride,
             "node_s, node_sd and node_t_s hold every node_stride-th node and the last (1: "
             "every node; a grid beyond 2001 nodes is stored as this subsample)");
  v.optional("samples", x.samples, "dense samples for plots (when solved)");
}
template <class V>
void fields(V& v, StudyResults::Mvc& x) {
  v("s", x.s, "path position on the exact grid (path.s_unit)");
  v("sd", x.sd, "maximum velocity curve, every limit (path.s_unit per s)");
  v("velocity_sd", x.velocity_sd,
    "maximum velocity curve of the velocity limits alone (path.s_unit per s)");
  v.optional("stride", x.stride,
             "s, sd and velocity_sd hold every stride-th grid point and the last (1: every "
             "point; a grid beyond 2001 points is stored as this subsample)");
}
template <class V>
void fields(V& v, StudyResults::ConvergenceRow& x) {
  v("segments", x.segments, "DP path segments");
  v("levels", x.levels, "DP velocity levels");
  v("solved", x.solved, "whether the DP found a motion");
  v("duration_s", x.duration_s, "duration (null when not solved)");
  v("excess", x.excess, "duration / exact - 1 (null when not solved)");
  v("run_time_s", x.run_time_s, "wall time");
  v("worst_violation", x.worst_violation, "largest limit use - 1 (null when not solved)");
  v("message", x.message, "why not, when not solved");
}
template <class V>
void fields(V& v, StudyResults::Motion& x) {
  v("t_s", x.t_s, "equal time steps");
  v("s", x.s, "path position (path.s_unit)");
  v("tip_m", x.tip_m, "tip [x, y] per sample (m)");
  v("q_rad", x.q_rad, "joint angles per sample");
  v.optional("stride", x.stride,
             "the samples are every stride-th time step and the last (1: every step; more "
             "than 2001 steps are stored as this subsample)");
}
template <class V>
void fields(V& v, StudyResults::Extrapolation& x) {
  v("coarse_points", x.coarse_points, "grid points of the coarser grid (about half the intervals)");
  v("coarse_duration_s", x.coarse_duration_s, "duration on it (null when not solved)");
  v("quarter_points", x.quarter_points,
    "grid points of the quarter grid (half the coarser one's intervals; 0: none)");
  v("quarter_duration_s", x.quarter_duration_s, "duration on it (null when none or not solved)");
  v("order", x.order,
    "observed order p of T(I) = T_inf + C I^-p over the coarser, case and refined grids "
    "(null: the changes differ in sign or p is outside [0.5, 4]); the scheme's is 1");
  v("asymptotic", x.asymptotic, "the observed order was found");
  v("duration_s", x.duration_s,
    "the converged duration: Richardson at order 1 over the case's and the refined grid");
  v("one_grid_down_s", x.one_grid_down_s,
    "the same over the coarser and the case's grid (null when the coarser was not solved)");
  v("two_grids_down_s", x.two_grids_down_s,
    "the same over the quarter and the coarser grid (null when none)");
  v("error_s", x.error_s,
    "its error estimate: 4 x max(|duration - one grid down|, |one grid down - two grids "
    "down| / 2)");
}
template <class V>
void fields(V& v, StudyResults::Graded& x) {
  v("uniform_points", x.uniform_points, "points of the case's uniform grid it was graded from");
  v("uniform_change", x.uniform_change,
    "relative change of the uniform grid's duration with every interval halved");
  v("rounds", x.rounds, "rounds of bisecting the intervals that hold half the change");
  v("tolerance_rel", x.tolerance_rel,
    "exact.tolerance_rel: the relative change the grading aims for");
  v("max_grid_points", x.max_grid_points, "exact.max_grid_points: the node cap");
  v("capped", x.capped, "the grading stopped at the node cap before reaching tolerance_rel");
}
template <class V>
void fields(V& v, StudyResults::GridConvergence& x) {
  v("grid_points", x.grid_points,
    "grid points the exact solver used: the case's uniform grid, or the graded grid");
  v("refined_points", x.refined_points, "2 grid_points - 1");
  v("refined_solved", x.refined_solved, "whether the refined grid solved");
  v("duration_s", x.duration_s, "duration on the case's grid");
  v("refined_duration_s", x.refined_duration_s,
    "duration on the refined grid (null when not solved)");
  v("change", x.change, "|duration / refined duration - 1| (null: the refined solve failed)");
  v("tolerance", x.tolerance, "allowed change (check exact_grid_converged)");
  v("passed", x.passed, "change <= tolerance");
  v("s_range", x.s_range, "[lo, hi] path range where the change arises (path.s_unit)");
  v("grid_point_range", x.grid_point_range, "[lo, hi] grid points of that range");
  v("share", x.share, "share of the change from that range");
  v("max_sd", x.max_sd, "largest path speed there (path.s_unit per s)");
  v("min_abs_sin_q2", x.min_abs_sin_q2, "smallest |sin q2| there (null for a joint-space path)");
  v("path_min_abs_sin_q2", x.path_min_abs_sin_q2,
    "smallest |sin q2| along the path (null for a joint-space path)");
  v.optional("extrapolation", x.extrapolation,
             "Richardson extrapolation over a coarser, the case's and the refined grid");
  v.optional("graded", x.graded,
             "the graded grid, when the uniform grid's change exceeded exact.tolerance_rel "
             "(null: the uniform grid was kept)");
  v("text", x.text, "the sentence for the check and the page");
}
template <class V>
void fields(V& v, StudyResults& x) {
  v("path", x.path, "the path: a tip path (2 links) or a path in joint space");
  v("path_length", x.path_length, "length of the path (path.s_unit)");
  v("joints", x.joints, "number of joints of the chain");
  v("configuration", x.configuration,
    "elbow configuration of a tip path, 1 or 2 (null for a joint-space path)");
  v("limits", x.limits, "the joint limits");
  v("solvers", x.solvers, "every solver, exact first");
  v("mvc", x.mvc, "the maximum velocity curve on the exact grid");
  v("convergence", x.convergence, "the DP at finer grids against the exact duration");
  v("motion", x.motion, "the exact motion at equal time steps (what the frames show)");
  v.optional("grid_convergence", x.grid_convergence,
             "the exact solver again with every grid interval halved (check exact_grid_converged)");
  v.optional(
      "mujoco_replay", x.mujoco_replay,
      "the exact solution's torques applied open loop in MuJoCo (check mujoco_dynamic_replay)");
  v.optional("arm_model", x.arm_model,
             "an arm read from a URDF or MJCF file (arm.model): the file, the plane and gravity "
             "it was solved in, and where each limit came from (the model or the case); absent "
             "for an arm written out in the case");
}

}  // namespace armstudy::studies::time_optimal
