// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The time-optimal study in the pipeline: case -> studies::time_optimal::solve -> results.json.
//
// results.json "time_optimal" section: studies/time_optimal/study_results.hpp (every key,
// typed; written from it here, read back from it by the report and merge).
#include <cmath>
#include <limits>
#include <optional>

#include "app/export_records.hpp"
#include "app/json_numbers.hpp"
#include "app/pipeline.hpp"
#include "app/replay_json.hpp"
#include "app/stored_series.hpp"
#include "app/study_entry.hpp"
#include "cases/time_optimal_case.hpp"
#include "report/motion_csv.hpp"
#include "report/results_fields.hpp"
#include "report/study_sections.hpp"
#include "scene/model_export.hpp"
#include "scene/mujoco_check.hpp"
#include "scene/replay_frames.hpp"
#include "scene/study_replays.hpp"
#include "scene/time_optimal_frames.hpp"
#include "studies/time_optimal/solve.hpp"
#include "studies/time_optimal/study_results.hpp"

namespace armstudy::app {
namespace {
namespace to = studies::time_optimal;
using nlohmann::json;

using Results = to::StudyResults;

std::vector<double> pair(const Eigen::Vector2d& v) { return {v[0], v[1]}; }

// one number per joint
std::vector<double> joints(const core::JointVector& v) { return {v.data(), v.data() + v.size()}; }

// a joints x N matrix as per-joint rows
Results::Rows rows(const Eigen::MatrixXd& m) {
  Results::Rows out;
  for (int j = 0; j < m.rows(); ++j) {
    std::vector<double> r;
    for (int k = 0; k < m.cols(); ++k) r.push_back(m(j, k));
    out.push_back(std::move(r));
  }
  return out;
}

const char* path_kind(to::PathKind k) {
  switch (k) {
    case to::PathKind::kLine: return "line";
    case to::PathKind::kPolyline: return "polyline";
    case to::PathKind::kSpline: return "spline";
  }
  return "line";
}

Results::Violation violation_section(const to::Violation& v, int nj) {
  Results::Violation o;
  o.worst = v.worst;
  o.text = v.text;
  o.kind = to::limit_name(v.kind);
  o.joint = v.joint + 1;
  o.s = v.s;
  o.t_s = v.t;
  o.interval = v.interval;
  o.ratio.velocity.assign(v.ratio[0], v.ratio[0] + nj);
  o.ratio.torque.assign(v.ratio[1], v.ratio[1] + nj);
  o.ratio.acceleration.assign(v.ratio[2], v.ratio[2] + nj);
  return o;
}

Results::Solver solver_section(const to::SolverResult& r, int nj) {
  Results::Solver o;
  o.name = r.name;
  o.method = r.method;
  o.solved = r.solved;
  o.message = r.message;
  o.duration_s = r.solved ? r.duration : NAN;
  o.run_time_s = r.run_time;
  o.intervals = r.intervals;
  o.levels = r.levels;
  o.evaluations = r.evaluations;
  o.iterations = r.iterations;
  if (!r.solved) return o;
  o.violation = violation_section(r.violation, nj);
  // a huge grid as a subsample (app/stored_series.hpp); the study keeps every node
  const int stride = stored_stride(r.node_s.size());
  o.node_s = stored(r.node_s, stride);
  o.node_sd = stored(r.node_sd, stride);
  o.node_t_s = stored(r.node_t, stride);
  o.node_stride = stride;
  const to::MotionSamples& s = r.samples;
  o.samples =
      Results::Samples{s.t, s.s, s.sd, s.sdd, rows(s.q), rows(s.qd), rows(s.qdd), rows(s.tau)};
  return o;
}

class TimeOptimalRun final : public TypedStudyRun<to::Spec, to::Result, Results> {
 public:
  using TypedStudyRun::TypedStudyRun;

  studies::Status solve(const studies::ProgressFn& progress) override {
    result_ = to::solve(spec_, progress);
    // MuJoCo's own dynamics on the exact solution's torques
    if (result_.status == studies::Status::kSolved && !lean_) {
      if (progress) progress(0.97, "MuJoCo dynamic replay");
      replay_ = scene::replay_time_optimal(spec_, result_);
    }
    return result_.status;
  }

  // the study's own checks, and MuJoCo's inverse dynamics along the exact solution
  std::vector<studies::Check> checks() const override {
    std::vector<studies::Check> c = to::checks(result_);
    if (result_.status != studies::Status::kSolved) return c;
    const to::MotionSamples& s = result_.solvers.front().samples;
    std::vector<core::JointVector> q, qd, qdd, tau;
    for (int k = 0; k < s.q.cols(); ++k) {
      q.emplace_back(s.q.col(k));
      qd.emplace_back(s.qd.col(k));
      qdd.emplace_back(s.qdd.col(k));
      tau.emplace_back(s.tau.col(k));
    }
    for (auto& m :
         scene::mujoco_checks(scene::mujoco_agreement(spec_.chain, q, qd, qdd, tau), false))
      c.push_back(std::move(m));
    if (replay_)
      c.push_back(scene::replay_check(*replay_, "mujoco_dynamic_replay", "the exact solution"));
    return c;
  }

  Results study_results() const override;

  std::vector<KeyFigure> key_figures() const override {
    std::vector<KeyFigure> k;
    if (result_.status != studies::Status::kSolved) return k;
    const double exact = result_.solvers.front().duration;
    const auto& g = result_.grid;
    if (g.extrapolation_computed && std::isfinite(g.extrapolated)) {
      k.push_back({"duration_s[converged]", g.extrapolated, "s",
                   "shortest duration, extrapolated (the converged duration)"});
      k.push_back({"duration_error_s[converged]", g.extrapolation_error, "s",
                   "error estimate of the converged duration"});
    }
    k.push_back({"duration_s[exact]", exact, "s", "shortest duration on the case's grid"});
    for (const auto& r : result_.solvers) {
      if (r.name == "exact" || !r.solved) continue;
      k.push_back({"duration_s[" + r.name + "]", r.duration, "s", "duration (" + r.words() + ")"});
      k.push_back({"excess_percent[" + r.name + "]",
                   100.0 * (r.duration / g.reference_duration(exact) - 1), "%",
                   // "exact": the converged duration where the grids were extrapolated
                   "excess over exact (" + r.words() + ")"});
    }
    k.push_back(
        {"run_time_s[exact]", result_.solvers.front().run_time, "s", "run time (exact solver)"});
    if (result_.grid.computed)
      k.push_back({"grid_change[exact]", result_.grid.change, "",
                   "duration change on a finer grid (relative)"});
    if (replay_)
      k.push_back({"mujoco_replay_deviation_rad", replay_->max_deviation, "rad",
                   "largest MuJoCo replay deviation"});
    k.push_back({std::string("path_length_") + result_.s_unit(), result_.path_length,
                 result_.s_unit(), "path length"});
    return k;
  }

  scene::Rendered render(const std::filesystem::path& dir, const cases::CaseInfo& info) override {
    scene::Rendered out = scene::render_time_optimal_frames(spec_, result_, info.render, dir);
    if (replay_)
      for (auto& f : scene::render_time_optimal_replay(spec_, result_, *replay_, info.render, dir))
        out.frames.push_back(std::move(f));
    return out;
  }

  std::vector<report::ExportRecord> write_exports(const std::filesystem::path& dir,
                                                  const cases::CaseInfo& info) override;

  // a sensitivity step: the exact solver alone (it needs no start: it is fast), without the
  // DP, the Complex method and MuJoCo's replay
  bool warm_start(const StudyRun&) override {
    spec_.dp.states.clear();
    spec_.dp.convergence_segments.clear();
    spec_.complex.enabled = false;
    lean_ = true;
    return false;
  }
  // the limits the exact solution reaches (within 0.1 %) somewhere along the path
  std::vector<std::string> binding() const override {
    std::vector<std::string> b;
    if (result_.solvers.empty() || !result_.solvers.front().solved) return b;
    const to::Violation& v = result_.solvers.front().violation;
    for (int kind = 0; kind < 3; ++kind)
      for (int j = 0; j < spec_.chain.num_links(); ++j)
        if (v.ratio[kind][j] >= 0.999)
          b.push_back(std::string(to::limit_name(static_cast<to::LimitKind>(kind))) +
                      " limit, joint " + std::to_string(j + 1));
    return b;
  }

 private:
  std::optional<scene::DynamicReplay> replay_;
  bool lean_ = false;  ///< a sensitivity step: no replay
};

// (over 60 lines, kept whole: a flat list of the typed results's fields, in their fields() order)
Results TimeOptimalRun::study_results() const {
  const to::Result& r = result_;
  const bool joint_space = spec_.space == to::PathSpace::kJoint;
  const int nj = spec_.chain.num_links();
  Results o;
  o.path.space = joint_space ? "joint" : "tip";
  o.path.s_unit = r.s_unit();
  if (joint_space) {
    o.path.kind = path_kind(spec_.joint_path.kind);
    o.path.points_rad.emplace();
    for (const auto& q : spec_.joint_path.points) o.path.points_rad->push_back(joints(q));
    if (!spec_.joint_path.range.empty()) {
      o.path.range_rad.emplace();
      for (const auto& lh : spec_.joint_path.range) o.path.range_rad->push_back(pair(lh));
    }
  } else {
    o.path.kind = path_kind(spec_.path.kind);
    o.path.points_m.emplace();
    for (const auto& p : spec_.path.points) o.path.points_m->push_back(pair(p));
    o.configuration = spec_.configuration;
  }
  o.path_length = r.path_length;
  o.joints = nj;
  o.limits.velocity_rad_s = joints(spec_.velocity_limit);
  o.limits.torque_Nm = joints(spec_.torque_limit);
  if (spec_.acceleration_limit) o.limits.acceleration_rad_s2 = joints(*spec_.acceleration_limit);
  for (const auto& s : r.solvers) o.solvers.push_back(solver_section(s, nj));
  const int mvc_stride = stored_stride(r.mvc_s.size());
  o.mvc = {stored(r.mvc_s, mvc_stride), stored(r.mvc_sd, mvc_stride),
           stored(r.mvc_velocity_sd, mvc_stride), mvc_stride};
  for (const auto& row : r.convergence)
    o.convergence.push_back({row.segments, row.levels, row.solved, row.solved ? row.duration : NAN,
                             row.solved ? row.excess : NAN, row.run_time,
                             row.solved ? row.worst_violation : NAN, row.message});
  const int motion_stride = stored_stride(r.motion_t.size());
  o.motion.t_s = stored(r.motion_t, motion_stride);
  o.motion.s = stored(r.motion_s, motion_stride);
  o.motion.stride = motion_stride;
  for (size_t k : stored_indices(static_cast<size_t>(r.motion_p.cols()), motion_stride)) {
    o.motion.tip_m.push_back(pair(r.motion_p.col(static_cast<Eigen::Index>(k))));
    o.motion.q_rad.push_back(joints(r.motion_q.col(static_cast<Eigen::Index>(k))));
  }
  if (r.grid.computed) {
    const to::GridConvergence& g = r.grid;
    o.grid_convergence = Results::GridConvergence{g.grid_points,
                                                  g.refined_points,
                                                  g.refined_solved,
                                                  g.duration,
                                                  g.refined_solved ? g.refined_duration : NAN,
                                                  g.change,
                                                  g.tolerance,
                                                  g.change <= g.tolerance,
                                                  {g.s_lo, g.s_hi},
                                                  {g.point_lo, g.point_hi},
                                                  g.share,
                                                  g.max_sd,
                                                  joint_space ? NAN : g.min_sin_q2,
                                                  joint_space ? NAN : g.path_min_sin_q2,
                                                  g.text,
                                                  std::nullopt,
                                                  std::nullopt};
    if (g.extrapolation_computed)
      o.grid_convergence->extrapolation = Results::Extrapolation{g.coarse_points,
                                                                 g.coarse_duration,
                                                                 g.quarter_points,
                                                                 g.quarter_duration,
                                                                 g.order,
                                                                 g.asymptotic,
                                                                 g.extrapolated,
                                                                 g.extrapolated_coarse,
                                                                 g.extrapolated_quarter,
                                                                 g.extrapolation_error};
    if (g.graded)
      o.grid_convergence->graded =
          Results::Graded{g.uniform_points,   g.uniform_change, g.graded_rounds,
                          g.graded_tolerance, g.max_points,     g.capped};
  }
  if (replay_) o.mujoco_replay = replay_results(*replay_);
  if (spec_.arm_origin.from_model()) o.arm_model = spec_.arm_origin.lines();
  return o;
}

// model.xml (the frames' scene, keyframes at the strip's times) and one CSV per solver
std::vector<report::ExportRecord> TimeOptimalRun::write_exports(const std::filesystem::path& dir,
                                                                const cases::CaseInfo& info) {
  std::vector<report::ExportRecord> out;
  if (result_.status != studies::Status::kSolved) return out;
  const scene::ArmScene sc = scene::time_optimal_scene(spec_, result_, info.render);
  const auto keys = scene::strip_keyframes(scene::time_optimal_motion(result_), info.render.frames);
  const std::string motion = "the exact (reachability) solution";
  out.push_back(model_export_entry(
      scene::write_model_xml(dir, sc.chain, sc.mjcf, keys, motion, info.path), motion, keys));
  const std::string u = result_.s_unit();
  for (const to::SolverResult& r : result_.solvers) {
    if (!r.solved) continue;
    const to::MotionSamples& s = r.samples;
    report::MotionCsv t;
    t.file = "motion_" + r.name + ".csv";
    t.what = "the " + r.name + " solution (" + r.method +
             "), the samples of results.json time_optimal.solvers[" + r.name +
             "].samples: time, path position s, speed s' and acceleration s'' (s in " + u +
             "), joint angles, rates, accelerations and torques (inverse dynamics)";
    t.add("t", "s", s.t);
    t.add("s", u, s.s);
    t.add("sd", u + "/s", s.sd);
    t.add("sdd", u + "/s^2", s.sdd);
    t.add_rows("q", "rad", s.q);
    t.add_rows("qd", "rad/s", s.qd);
    t.add_rows("qdd", "rad/s^2", s.qdd);
    t.add_rows("tau", "N m", s.tau);
    report::write_motion_csv(dir, t);
    out.push_back(csv_export_entry(t, r.name));
  }
  return out;
}

}  // namespace

StudyParts time_optimal_parts() {
  return study_parts<TimeOptimalRun>(
      "fastest motion along a given tip path under joint velocity, torque and acceleration limits",
      &report::time_optimal_sections, &report::time_optimal_answer);
}

}  // namespace armstudy::app
