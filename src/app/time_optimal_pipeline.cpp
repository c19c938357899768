// The time-optimal study in the pipeline: case -> studies::time_optimal::solve -> results.json.
//
// results.json "time_optimal" section (SI units, angles in rad):
//   path {kind, points_m [[x, y]...]}, path_length_m, configuration,
//   limits {velocity_rad_s [j1, j2], torque_Nm [j1, j2], acceleration_rad_s2 [j1, j2] or null},
//   solvers [{name ("exact", "dp", "dp_joint1", "complex"), method, solved, message,
//             duration_s, run_time_s, intervals, levels, evaluations, iterations,
//             violation {worst (largest limit use - 1; <= 0: every limit met), text, kind,
//                        joint (1-based), s_m, t_s, interval,
//                        ratio {velocity [j1, j2], torque [j1, j2], acceleration [j1, j2]}},
//             node_s_m, node_sd_m_s, node_t_s,
//             samples {t_s, s_m, sd_m_s, sdd_m_s2, q_rad [[j1...], [j2...]], qd_rad_s,
//                      qdd_rad_s2, tau_Nm (per joint rows)}}]: exact first,
//   mvc {s_m, sd_m_s, velocity_sd_m_s}: the maximum velocity curve on the exact grid,
//   convergence [{segments, levels, solved, duration_s, excess, run_time_s, worst_violation,
//                 message (why not, when not solved)}],
//   motion {t_s, s_m, tip_m [[x, y]...], q_rad [[q1, q2]...]}: the exact motion at equal
//   time steps (what the frames show),
//   grid_convergence {grid_points, refined_points, refined_solved, duration_s,
//                     refined_duration_s, change, tolerance, passed, s_range_m [lo, hi],
//                     grid_point_range [lo, hi], share, max_sd_m_s, min_abs_sin_q2,
//                     path_min_abs_sin_q2, text}: the exact solver again with every grid
//                     interval halved (check exact_grid_converged),
//   mujoco_replay {...}: the exact solution's torques applied open loop through mj_step
//                  (app/replay_json.hpp; check mujoco_dynamic_replay).
#include <cmath>
#include <limits>
#include <optional>

#include "cases/time_optimal_case.hpp"
#include "app/json_numbers.hpp"
#include "app/pipeline.hpp"
#include "app/replay_json.hpp"
#include "report/case_report.hpp"
#include "scene/mujoco_check.hpp"
#include "scene/replay_frames.hpp"
#include "scene/study_replays.hpp"
#include "scene/time_optimal_frames.hpp"
#include "studies/time_optimal/solve.hpp"

namespace armstudy::app {
namespace {
namespace to = studies::time_optimal;
using nlohmann::json;

json num(double v) { return json_number(v); }

json list(const std::vector<double>& v) {
  json a = json::array();
  for (double x : v) a.push_back(num(x));
  return a;
}

json pair(const Eigen::Vector2d& v) { return json::array({num(v[0]), num(v[1])}); }

// a 2 x N matrix as two per-joint rows
json rows(const Eigen::Matrix2Xd& m) {
  json out = json::array();
  for (int j = 0; j < 2; ++j) {
    json r = json::array();
    for (int k = 0; k < m.cols(); ++k) r.push_back(num(m(j, k)));
    out.push_back(r);
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

json violation_json(const to::Violation& v) {
  json ratio = json::object();
  for (int kind = 0; kind < 3; ++kind)
    ratio[to::limit_name(static_cast<to::LimitKind>(kind))] =
        json::array({num(v.ratio[kind][0]), num(v.ratio[kind][1])});
  return {{"worst", num(v.worst)},          {"text", v.text},
          {"kind", to::limit_name(v.kind)}, {"joint", v.joint + 1},
          {"s_m", num(v.s)},                {"t_s", num(v.t)},
          {"interval", v.interval},         {"ratio", ratio}};
}

json solver_json(const to::SolverResult& r) {
  json j = {{"name", r.name},
            {"method", r.method},
            {"solved", r.solved},
            {"message", r.message},
            {"duration_s", r.solved ? num(r.duration) : json(nullptr)},
            {"run_time_s", num(r.run_time)},
            {"intervals", r.intervals},
            {"levels", r.levels},
            {"evaluations", r.evaluations},
            {"iterations", r.iterations}};
  if (!r.solved) return j;
  j["violation"] = violation_json(r.violation);
  j["node_s_m"] = list(r.node_s);
  j["node_sd_m_s"] = list(r.node_sd);
  j["node_t_s"] = list(r.node_t);
  const to::MotionSamples& s = r.samples;
  j["samples"] = {{"t_s", list(s.t)},          {"s_m", list(s.s)},       {"sd_m_s", list(s.sd)},
                  {"sdd_m_s2", list(s.sdd)},   {"q_rad", rows(s.q)},     {"qd_rad_s", rows(s.qd)},
                  {"qdd_rad_s2", rows(s.qdd)}, {"tau_Nm", rows(s.tau)}};
  return j;
}

class TimeOptimalRun final : public StudyRun {
 public:
  explicit TimeOptimalRun(to::Spec spec) : spec_(std::move(spec)) {}

  studies::Status solve(const studies::ProgressFn& progress) override {
    result_ = to::solve(spec_, progress);
    // MuJoCo's own dynamics on the exact solution's torques
    if (result_.status == studies::Status::kSolved) {
      if (progress) progress(0.97, "MuJoCo dynamic replay");
      replay_ = scene::replay_time_optimal(spec_, result_);
    }
    return result_.status;
  }
  std::string message() const override { return result_.message; }

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
    for (auto& m : scene::mujoco_checks(scene::mujoco_agreement(spec_.chain, q, qd, qdd, tau), false))
      c.push_back(std::move(m));
    if (replay_) c.push_back(scene::replay_check(*replay_, "mujoco_dynamic_replay", "the exact solution"));
    return c;
  }

  nlohmann::json results() const override;

  std::vector<KeyFigure> key_figures() const override {
    std::vector<KeyFigure> k;
    if (result_.status != studies::Status::kSolved) return k;
    const double exact = result_.solvers.front().duration;
    k.push_back({"duration_s[exact]", exact, "s", "shortest duration (exact solver)"});
    for (const auto& r : result_.solvers) {
      if (r.name == "exact" || !r.solved) continue;
      k.push_back({"duration_s[" + r.name + "]", r.duration, "s", "duration (" + r.name + ")"});
      k.push_back({"excess_percent[" + r.name + "]", 100.0 * (r.duration / exact - 1), "%", "excess over exact (" + r.name + ")"});
    }
    k.push_back({"run_time_s[exact]", result_.solvers.front().run_time, "s", "run time (exact solver)"});
    if (result_.grid.computed) k.push_back({"grid_change[exact]", result_.grid.change, "", "duration change on a finer grid (relative)"});
    if (replay_) k.push_back({"mujoco_replay_deviation_rad", replay_->max_deviation, "rad", "largest MuJoCo replay deviation"});
    k.push_back({"path_length_m", result_.path_length, "m", "path length"});
    return k;
  }

  std::vector<std::string> render(const std::filesystem::path& dir,
                                  const cases::CaseInfo& info) override {
    std::vector<std::string> files = scene::render_time_optimal_frames(spec_, result_, info.render, dir);
    if (replay_)
      for (auto& f : scene::render_time_optimal_replay(spec_, result_, *replay_, info.render, dir))
        files.push_back(std::move(f));
    return files;
  }

  void report(const std::filesystem::path& dir, const cases::CaseInfo& info,
              const nlohmann::json& results_json) override {
    report::write_case_report(dir, info, results_json);
  }

 private:
  to::Spec spec_;
  to::Result result_;
  std::optional<scene::DynamicReplay> replay_;
};

json TimeOptimalRun::results() const {
  const to::Result& r = result_;
  json pts = json::array();
  for (const auto& p : spec_.path.points) pts.push_back(pair(p));
  json j;
  j["path"] = {{"kind", path_kind(spec_.path.kind)}, {"points_m", pts}};
  j["path_length_m"] = num(r.path_length);
  j["configuration"] = spec_.configuration;
  j["limits"] = {{"velocity_rad_s", pair(spec_.velocity_limit)},
                 {"torque_Nm", pair(spec_.torque_limit)},
                 {"acceleration_rad_s2", spec_.acceleration_limit ? pair(*spec_.acceleration_limit) : json(nullptr)}};
  json solvers = json::array();
  for (const auto& s : r.solvers) solvers.push_back(solver_json(s));
  j["solvers"] = solvers;
  j["mvc"] = {{"s_m", list(r.mvc_s)}, {"sd_m_s", list(r.mvc_sd)}, {"velocity_sd_m_s", list(r.mvc_velocity_sd)}};
  json conv = json::array();
  for (const auto& row : r.convergence)
    conv.push_back({{"segments", row.segments},
                    {"levels", row.levels},
                    {"solved", row.solved},
                    {"duration_s", row.solved ? num(row.duration) : json(nullptr)},
                    {"excess", row.solved ? num(row.excess) : json(nullptr)},
                    {"run_time_s", num(row.run_time)},
                    {"worst_violation", row.solved ? num(row.worst_violation) : json(nullptr)},
                    {"message", row.message}});
  j["convergence"] = conv;
  json tip = json::array(), q = json::array();
  for (int k = 0; k < r.motion_p.cols(); ++k) {
    tip.push_back(pair(r.motion_p.col(k)));
    q.push_back(pair(r.motion_q.col(k)));
  }
  j["motion"] = {{"t_s", list(r.motion_t)}, {"s_m", list(r.motion_s)}, {"tip_m", tip}, {"q_rad", q}};
  if (r.grid.computed) {
    const to::GridConvergence& g = r.grid;
    j["grid_convergence"] = {{"grid_points", g.grid_points},
                             {"refined_points", g.refined_points},
                             {"refined_solved", g.refined_solved},
                             {"duration_s", num(g.duration)},
                             {"refined_duration_s", g.refined_solved ? num(g.refined_duration) : json(nullptr)},
                             {"change", num(g.change)},
                             {"tolerance", num(g.tolerance)},
                             {"passed", g.change <= g.tolerance},
                             {"s_range_m", json::array({num(g.s_lo), num(g.s_hi)})},
                             {"grid_point_range", json::array({g.point_lo, g.point_hi})},
                             {"share", num(g.share)},
                             {"max_sd_m_s", num(g.max_sd)},
                             {"min_abs_sin_q2", num(g.min_sin_q2)},
                             {"path_min_abs_sin_q2", num(g.path_min_sin_q2)},
                             {"text", g.text}};
  }
  if (replay_) j["mujoco_replay"] = replay_json(*replay_);
  return j;
}

std::unique_ptr<StudyRun> load(cases::Map& root, const cases::CaseInfo&) {
  to::Spec spec = cases::load_time_optimal(root);
  if (!root.diag().empty()) return nullptr;
  return std::make_unique<TimeOptimalRun>(std::move(spec));
}

}  // namespace

StudyEntry time_optimal_entry() {
  return {"time_optimal",
          "fastest motion along a given tip path under joint velocity, torque and acceleration limits",
          &load};
}

}  // namespace armstudy::app
