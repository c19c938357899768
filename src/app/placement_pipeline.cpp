// The placement study in the pipeline: case -> studies::placement::solve -> results.json.
//
// results.json "placement" section (SI; keys ending in _deg are degrees):
//   lmax_m, length_m, length_fraction, duration_s, samples, singularity_margin_m,
//   annulus_m [inner, outer], torque_limits_Nm / power_limits_W (null when not given),
//   thesis_intervals {x_s_case, x_s_init_m, x_s_fin_m},
//   counts {total, unreachable, singular, clear, thesis_admitted, thesis_rejected_by_exact_check,
//           exact_accepted_outside_thesis}: the geometric sweep (x_s grid x phi in [0, 180] deg),
//   optima [{program, configuration, energy_J, x_s_m, phi_deg, root_xy_m [X, Y], grid_energy_J,
//            grid_x_s_m, grid_phi_deg, min_abs_sin_elbow, boundary_distance_m,
//            peak_torque_Nm [j1, j2], peak_power_W [j1, j2], signed_work_J, singular (false),
//            singular_trajectory, energy_convergence {converged, touches_boundary, singular,
//            samples, rel_change, tolerance_rel, rows [{samples, energy_J, peak_torque_Nm}]},
//            decided_by {binding (interior | inner_clearance | outer_clearance | torque_limit |
//            power_limit), joint, margin_m, inner_slack_m, outer_slack_m, torque_slack_Nm,
//            power_slack_W, set_by_margin}, refinement {method, final_tolerance_rel, target_rel,
//            converged, evaluations}, margin_sensitivity [{margin_m, found, energy_J, x_s_m,
//            phi_deg, root_xy_m, binding, refine_converged, refine_tolerance_rel, ...}] (when a
//            clearance binds), refine_evaluations, line_start_m, line_end_m (arm frame),
//            counts {...}, series}],
//   A singular motion (touching a boundary, or energy not converged to 1e-4 by doubling the
//   samples up to 409601) has energy_J and peak_torque_Nm null, singular_trajectory true and
//   note "singular: energy not converged, peak torque unbounded" (optima, thesis_search,
//   evaluations, margin_sensitivity); its saving is null.
//   unsolved [{program, configuration, reason}]: pairs without an admissible placement,
//   thesis_search [{program, configuration, energy_J, x_s_m, phi_deg, root_xy_m, status,
//                   singular, boundary_distance_m, min_abs_sin_elbow}]: the least energy among
//                   the thesis's own candidates (4.7-4.13), whatever their status,
//   evaluations [{label, program, configuration, x_s_m, phi_deg, root_xy_m, energy_J, status,
//                 singular, boundary_distance_m, min_abs_sin_elbow, peak_torque_Nm,
//                 saving_J, saving_percent, series}],
//   curves [{program, configuration, x_s_m, phi_deg [...], energy_J [... null], status "..."}],
//   pareto [{program, configuration, joint (1 or 2), peak_torque_Nm [[j1, j2] ...],
//            energy_J [...], x_s_m [...], phi_deg [...], singular [...] (all false: the front
//            holds admissible placements only), excluded {what, peak_torque_Nm, energy_J}: the
//            same front over the candidates inside the margin}] (thinned to steps of >= 0.2 %
//            in energy),
//   maps [{program, configuration, x_m [...], y_m [...], optimum_xy_m, encoding,
//          energy_J_rows ["e e e ...", ...], status_rows ["..sxo", ...]}]: row j is y_m[j];
//          energies at 4 significant digits, '-' where unreachable; status characters
//          '.' unreachable, 's' singular, 'x' over a limit, 'o' feasible. Maps are rows of
//          text so that a 200 x 100 map stays ~100 kB and one line per row;
//   convergence {program, configuration, rows [{samples, energy_J}]},
//   solve_seconds, samples_evaluated,
//   mujoco_replay [{program, configuration, ...app/replay_json.hpp}]: each optimum's torques
//   applied open loop through mj_step (checks mujoco_dynamic_replay.<program>.<configuration>).
// series: {stride, t_s, q1_rad, q2_rad, qd1_rad_s, qd2_rad_s, qdd1_rad_s2, qdd2_rad_s2,
//          tau1_Nm, tau2_Nm, power1_W, power2_W, energy_J} every `stride`-th sample (<= 101
//          points; the full series is in the Result for the scene).
#include <cmath>
#include <cstdio>
#include <limits>

#include "cases/placement_case.hpp"
#include "app/json_numbers.hpp"
#include "app/pipeline.hpp"
#include "app/replay_json.hpp"
#include "report/case_report.hpp"
#include "scene/placement_frames.hpp"
#include "scene/replay_frames.hpp"
#include "scene/study_replays.hpp"
#include "core/motion_program.hpp"
#include "studies/placement/refine.hpp"
#include "studies/placement/solve.hpp"

namespace armstudy::app {
namespace {
namespace pl = studies::placement;
using nlohmann::json;
constexpr double kDeg = core::kPi / 180.0;

json num(double v) { return json_number(v); }

json pair(const Eigen::Vector2d& v) { return json::array({num(v.x()), num(v.y())}); }

json series_json(const pl::TimeSeries& s) {
  json j;
  const size_t n = s.t.size();
  const size_t stride = n > 101 ? (n - 1 + 99) / 100 : 1;
  j["stride"] = stride;
  json t = json::array(), q1 = json::array(), q2 = json::array(), qd1 = json::array(), qd2 = json::array(),
       a1 = json::array(), a2 = json::array(), u1 = json::array(), u2 = json::array(), p1 = json::array(),
       p2 = json::array(), e = json::array();
  for (size_t k = 0; k < n; k += stride) {
    t.push_back(num(s.t[k]));
    q1.push_back(num(s.q[k][0]));
    q2.push_back(num(s.q[k][1]));
    qd1.push_back(num(s.qd[k][0]));
    qd2.push_back(num(s.qd[k][1]));
    a1.push_back(num(s.qdd[k][0]));
    a2.push_back(num(s.qdd[k][1]));
    u1.push_back(num(s.tau[k][0]));
    u2.push_back(num(s.tau[k][1]));
    p1.push_back(num(s.power[k][0]));
    p2.push_back(num(s.power[k][1]));
    e.push_back(num(s.energy[k]));
    if (k + stride >= n && k != n - 1) k = n - 1 - stride;  // always end on the last sample
  }
  j["t_s"] = t;
  j["q1_rad"] = q1;
  j["q2_rad"] = q2;
  j["qd1_rad_s"] = qd1;
  j["qd2_rad_s"] = qd2;
  j["qdd1_rad_s2"] = a1;
  j["qdd2_rad_s2"] = a2;
  j["tau1_Nm"] = u1;
  j["tau2_Nm"] = u2;
  j["power1_W"] = p1;
  j["power2_W"] = p2;
  j["energy_J"] = e;
  return j;
}

json counts_json(const pl::Counts& c) {
  return {{"total", c.total},
          {"unreachable", c.unreachable},
          {"singular", c.singular},
          {"over_limit", c.over_limit},
          {"feasible", c.feasible},
          {"thesis_admitted", c.thesis_total},
          {"thesis_rejected_by_exact_check", c.thesis_rejected},
          {"exact_accepted_outside_thesis", c.exact_outside_thesis}};
}

std::string prog(core::MotionProgram p) { return std::string(core::program_name(p)); }

// the doubling of one motion's samples (converge.hpp)
json convergence_json(const pl::EnergyConvergence& c) {
  json rows = json::array();
  for (const auto& r : c.rows)
    rows.push_back({{"samples", r.samples}, {"energy_J", num(r.energy)}, {"peak_torque_Nm", num(r.peak_torque)}});
  return {{"converged", c.converged},
          {"touches_boundary", c.touches_boundary},
          {"singular", c.singular()},
          {"samples", c.samples},
          {"rel_change", num(c.rel_change)},
          {"peak_torque_rel_change", num(c.peak_rel_change)},
          {"tolerance_rel", num(c.tolerance)},
          {"rows", rows}};
}

// energy, peak torque, peak power of a candidate: null (and a note) for a singular motion
void metrics_json(json& o, const pl::Candidate& c) {
  const bool singular = c.convergence.singular();
  const pl::LineMetrics& m = c.reported_metrics();
  o["energy_J"] = singular ? json(nullptr) : num(m.energy);
  o["peak_torque_Nm"] = singular ? json(nullptr)
                                 : json::array({num(m.peak_torque[0]), num(m.peak_torque[1])});
  if (c.convergence.checked) o["energy_samples"] = c.convergence.samples;
  o["singular_trajectory"] = singular;
  if (singular) o["note"] = pl::kSingularNote;
  if (c.convergence.checked) o["energy_convergence"] = convergence_json(c.convergence);
}

// what decides an optimum (refine.hpp)
json decision_json(const pl::Spec& spec, const pl::Decision& d) {
  json j = {{"binding", pl::binding_name(d.binding)},
            {"inner_slack_m", num(d.inner_slack)},
            {"outer_slack_m", num(d.outer_slack)},
            {"margin_m", num(spec.singularity_margin)}};
  j["joint"] = d.joint >= 0 ? json(d.joint + 1) : json(nullptr);
  j["torque_slack_Nm"] = json::array({num(d.torque_slack[0]), num(d.torque_slack[1])});
  j["power_slack_W"] = json::array({num(d.power_slack[0]), num(d.power_slack[1])});
  j["set_by_margin"] = d.binding == pl::Binding::kInnerClearance || d.binding == pl::Binding::kOuterClearance;
  return j;
}

class PlacementRun final : public StudyRun {
 public:
  explicit PlacementRun(pl::Spec spec) : spec_(std::move(spec)) {}

  studies::Status solve(const studies::ProgressFn& progress) override {
    result_ = pl::solve(spec_, progress);
    // MuJoCo's own dynamics on every optimum's torques (scene/dynamic_replay.hpp)
    if (result_.status == studies::Status::kSolved) {
      if (progress) progress(0.97, "MuJoCo dynamic replay");
      replays_ = scene::replay_placement(spec_, result_);
    }
    return result_.status;
  }
  std::string message() const override { return result_.message; }
  std::vector<studies::Check> checks() const override {
    std::vector<studies::Check> c = result_.checks;
    for (const scene::PlacementReplay& r : replays_) {
      // check names are [a-z0-9_.]+ (results.schema.json)
      const std::string id = prog(r.program) + "." + std::to_string(r.configuration);
      c.push_back(scene::replay_check(r.replay, "mujoco_dynamic_replay." + id,
                                      "the optimum " + prog(r.program) + ", configuration " +
                                          std::to_string(r.configuration)));
    }
    return c;
  }
  // the study report: one call, everything else is src/report's
  void report(const std::filesystem::path& dir, const cases::CaseInfo& info,
              const nlohmann::json& results_json) override {
    report::write_case_report(dir, info, results_json);
  }
  nlohmann::json results() const override;

  // per program and configuration: the refined optimum's energy and root location
  std::vector<KeyFigure> key_figures() const override {
    std::vector<KeyFigure> k;
    double best = std::numeric_limits<double>::infinity();
    for (const pl::ProgramConfig& pc : result_.cases) {
      if (!pc.found || pc.refined.convergence.singular()) continue;
      const std::string id = "[" + prog(pc.program) + "," + std::to_string(pc.configuration) + "]";
      const std::string who = ", " + prog(pc.program) + " " + std::to_string(pc.configuration);
      const double energy = pc.refined.reported_metrics().energy;
      k.push_back({"energy_J" + id, energy, "J", "energy" + who});
      k.push_back({"root_x_m" + id, pc.refined.root.x(), "m", "root x" + who});
      k.push_back({"root_y_m" + id, pc.refined.root.y(), "m", "root y" + who});
      best = std::min(best, energy);
    }
    if (std::isfinite(best)) k.insert(k.begin(), {"min_energy_J", best, "J", "lowest energy (the optimum)"});
    if (!result_.cases.empty()) {
      const pl::Counts& c = result_.cases.front().counts;
      k.push_back({"candidates_clear", double(c.feasible + c.over_limit), "", "candidate lines clear"});
      k.push_back({"candidates_singular", double(c.singular), "", "candidate lines singular"});
    }
    return k;
  }

  // frames: the optimum of every program and configuration (src/scene)
  std::vector<std::string> render(const std::filesystem::path& dir,
                                  const cases::CaseInfo& info) override {
    std::vector<std::string> files = scene::render_placement_frames(spec_, result_, info.render, dir);
    for (auto& f : scene::render_placement_replay(spec_, result_, replays_, info.render, dir))
      files.push_back(std::move(f));
    return files;
  }

 private:
  pl::Spec spec_;
  pl::Result result_;
  std::vector<scene::PlacementReplay> replays_;
};

json PlacementRun::results() const {
  const pl::Result& r = result_;
  json j;
  j["lmax_m"] = num(r.lmax);
  j["length_m"] = num(r.length);
  j["length_fraction"] = num(r.lmax > 0 ? r.length / r.lmax : 0.0);
  j["duration_s"] = num(spec_.duration);
  j["samples"] = spec_.samples;
  j["singularity_margin_m"] = num(spec_.singularity_margin);
  j["annulus_m"] = json::array({num(r.inner), num(r.outer)});
  j["torque_limits_Nm"] = spec_.torque_limit
                              ? json::array({(*spec_.torque_limit)[0], (*spec_.torque_limit)[1]})
                              : json(nullptr);
  j["power_limits_W"] = spec_.power_limit
                            ? json::array({(*spec_.power_limit)[0], (*spec_.power_limit)[1]})
                            : json(nullptr);
  j["thesis_intervals"] = {{"x_s_case", r.thesis_xs_case},
                           {"x_s_init_m", num(r.xs_init)},
                           {"x_s_fin_m", num(r.xs_fin)}};
  if (!r.cases.empty()) {
    const pl::Counts& c = r.cases.front().counts;
    j["counts"] = {{"total", c.total},
                   {"unreachable", c.unreachable},
                   {"singular", c.singular},
                   {"clear", c.feasible + c.over_limit},
                   {"thesis_admitted", c.thesis_total},
                   {"thesis_rejected_by_exact_check", c.thesis_rejected},
                   {"exact_accepted_outside_thesis", c.exact_outside_thesis}};
  }
  json optima = json::array(), unsolved = json::array(), thesis = json::array(), curves = json::array(),
       pareto = json::array(), maps = json::array();
  for (const pl::ProgramConfig& pc : r.cases) {
    const json id = {{"program", prog(pc.program)}, {"configuration", pc.configuration}};
    if (pc.found) {
      const pl::Candidate& c = pc.refined;
      json o = id;
      metrics_json(o, c);
      o["x_s_m"] = num(c.x_s);
      o["phi_deg"] = num(c.phi / kDeg);
      o["root_xy_m"] = pair(c.root);
      o["grid_energy_J"] = num(pc.grid.metrics.energy);
      o["grid_x_s_m"] = num(pc.grid.x_s);
      o["grid_phi_deg"] = num(pc.grid.phi / kDeg);
      o["min_abs_sin_elbow"] = num(c.min_abs_sin);
      o["boundary_distance_m"] = num(c.boundary_distance);
      o["peak_power_W"] = json::array({num(c.metrics.peak_power[0]), num(c.metrics.peak_power[1])});
      o["signed_work_J"] = num(c.metrics.signed_work);
      o["singular"] = c.status != pl::CandidateStatus::kFeasible || c.convergence.singular();
      o["refine_evaluations"] = pc.refine_evaluations;
      o["decided_by"] = decision_json(spec_, pc.decision);
      o["refinement"] = {{"method", pc.refine_method.empty() ? json(nullptr) : json(pc.refine_method)},
                         {"final_tolerance_rel", pc.refine_method.empty() ? json(nullptr) : num(pc.refine_tolerance_rel)},
                         {"target_rel", 1e-7},
                         {"converged", pc.refine_converged},
                         {"evaluations", pc.refine_evaluations}};
      json ms = json::array();
      for (const pl::MarginPoint& m : pc.margin_sensitivity) {
        json mj = {{"margin_m", num(m.margin)}, {"found", m.found}};
        if (m.found) {
          metrics_json(mj, m.optimum);
          mj["x_s_m"] = num(m.optimum.x_s);
          mj["phi_deg"] = num(m.optimum.phi / kDeg);
          mj["root_xy_m"] = pair(m.optimum.root);
          mj["binding"] = pl::binding_name(m.decision.binding);
          mj["refine_converged"] = m.refine_converged;
          mj["refine_tolerance_rel"] = num(m.refine_tolerance_rel);
        }
        ms.push_back(mj);
      }
      o["margin_sensitivity"] = ms;
      o["line_start_m"] = pair(pc.placement.start);
      o["line_end_m"] = pair(pc.placement.end);
      o["counts"] = counts_json(pc.counts);
      o["series"] = series_json(pc.series);
      optima.push_back(o);
    } else {
      json u = id;
      u["reason"] = pc.reason;
      u["counts"] = counts_json(pc.counts);
      unsolved.push_back(u);
    }
    if (pc.thesis_found) {
      const pl::Candidate& c = pc.thesis_best;
      json t = id;
      metrics_json(t, c);
      t["x_s_m"] = num(c.x_s);
      t["phi_deg"] = num(c.phi / kDeg);
      t["root_xy_m"] = pair(c.root);
      t["status"] = pl::status_name(c.status);
      t["singular"] = c.status == pl::CandidateStatus::kSingular;
      t["boundary_distance_m"] = num(c.boundary_distance);
      t["min_abs_sin_elbow"] = num(c.min_abs_sin);
      thesis.push_back(t);
    }
    {
      json cj = id;
      cj["x_s_m"] = num(pc.curve.x_s);
      json phi = json::array(), e = json::array();
      std::string st;
      for (size_t k = 0; k < pc.curve.phi.size(); ++k) {
        phi.push_back(num(pc.curve.phi[k] / kDeg));
        e.push_back(num(pc.curve.energy[k]));
        st += pl::status_char(pc.curve.status[k]);
      }
      cj["phi_deg"] = phi;
      cj["energy_J"] = e;
      cj["status"] = st;
      curves.push_back(cj);
    }
    for (int joint = 0; joint < 2; ++joint) {
      json pj = id;
      pj["joint"] = joint + 1;
      json pk = json::array(), e = json::array(), xs = json::array(), ph = json::array(), sg = json::array();
      const auto& front = pc.pareto[joint];
      double last = std::numeric_limits<double>::infinity();
      for (size_t k = 0; k < front.size(); ++k) {
        // thin: keep the first, the last, and steps of >= 0.2 % in energy
        if (k != 0 && k + 1 != front.size() && front[k].energy > last * (1 - 2e-3)) continue;
        last = front[k].energy;
        pk.push_back(json::array({num(front[k].peak_torque[0]), num(front[k].peak_torque[1])}));
        e.push_back(num(front[k].energy));
        xs.push_back(num(front[k].x_s));
        ph.push_back(num(front[k].phi / kDeg));
        sg.push_back(front[k].singular);
      }
      pj["peak_torque_Nm"] = pk;
      pj["energy_J"] = e;
      pj["x_s_m"] = xs;
      pj["phi_deg"] = ph;
      pj["singular"] = sg;
      // the inadmissible candidates inside the margin: drawn distinctly, never the front
      json xk = json::array(), xe = json::array();
      last = std::numeric_limits<double>::infinity();
      const auto& ex = pc.pareto_excluded[joint];
      for (size_t k = 0; k < ex.size(); ++k) {
        if (k != 0 && k + 1 != ex.size() && ex[k].energy > last * (1 - 2e-3)) continue;
        last = ex[k].energy;
        xk.push_back(json::array({num(ex[k].peak_torque[0]), num(ex[k].peak_torque[1])}));
        xe.push_back(num(ex[k].energy));
      }
      pj["excluded"] = {{"what", "candidates inside the clearance margin (inadmissible), energy converged"},
                        {"peak_torque_Nm", xk},
                        {"energy_J", xe}};
      pareto.push_back(pj);
    }
    {
      const pl::EnergyMap& m = pc.map;
      json mj = id;
      json x = json::array(), y = json::array(), er = json::array(), sr = json::array();
      for (double v : m.x) x.push_back(num(v));
      for (double v : m.y) y.push_back(num(v));
      const size_t nx = m.x.size();
      for (size_t row = 0; row < m.y.size(); ++row) {
        std::string e, s;
        for (size_t i = 0; i < nx; ++i) {
          const float v = m.energy[row * nx + i];
          if (i) e += ' ';
          if (std::isfinite(v)) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.4g", double(v));
            e += buf;
          } else {
            e += '-';
          }
          s += pl::status_char(m.status[row * nx + i]);
        }
        er.push_back(e);
        sr.push_back(s);
      }
      mj["x_m"] = x;
      mj["y_m"] = y;
      mj["optimum_xy_m"] = pc.found ? pair(pc.refined.root) : json(nullptr);
      mj["encoding"] =
          "row j is y_m[j]; energy_J_rows: space-separated energies in J at 4 significant digits, "
          "'-' where unreachable or the sampled energy is not converged to 1e-4; status_rows: '.' unreachable, 's' singular, 'x' over a limit, "
          "'o' feasible; Y < 0 is the mirror image with the configurations swapped";
      mj["energy_J_rows"] = er;
      mj["status_rows"] = sr;
      maps.push_back(mj);
    }
  }
  j["optima"] = optima;
  j["unsolved"] = unsolved;
  j["thesis_search"] = thesis;
  json evals = json::array();
  for (const pl::Evaluation& e : r.evaluations) {
    json ej = {{"label", e.label}, {"program", prog(e.program)}, {"configuration", e.configuration}};
    const pl::Candidate& c = e.candidate;
    ej["x_s_m"] = num(c.x_s);
    ej["phi_deg"] = num(c.phi / kDeg);
    ej["root_xy_m"] = pair(c.root);
    const bool reachable = c.status != pl::CandidateStatus::kUnreachable;
    if (reachable) {
      metrics_json(ej, c);
    } else {
      ej["energy_J"] = nullptr;
      ej["peak_torque_Nm"] = nullptr;
    }
    ej["status"] = pl::status_name(c.status);
    ej["singular"] = c.status == pl::CandidateStatus::kSingular;
    ej["boundary_distance_m"] = num(c.boundary_distance);
    ej["min_abs_sin_elbow"] = num(c.min_abs_sin);
    ej["saving_J"] = e.has_saving ? num(e.saving) : json(nullptr);
    ej["saving_percent"] = e.has_saving ? num(e.saving_percent) : json(nullptr);
    ej["line_start_m"] = pair(e.placement.start);
    ej["line_end_m"] = pair(e.placement.end);
    if (!e.series.t.empty()) ej["series"] = series_json(e.series);
    evals.push_back(ej);
  }
  j["evaluations"] = evals;
  j["curves"] = curves;
  j["pareto"] = pareto;
  j["maps"] = maps;
  json conv = json::array();
  for (const auto& row : r.convergence) conv.push_back({{"samples", row.samples}, {"energy_J", num(row.energy)}});
  for (const auto& pc : r.cases) {
    if (!pc.found) continue;
    j["convergence"] = {{"program", prog(pc.program)}, {"configuration", pc.configuration}, {"rows", conv}};
    break;
  }
  json replays = json::array();
  for (const scene::PlacementReplay& rp : replays_) {
    json rj = {{"program", prog(rp.program)}, {"configuration", rp.configuration}};
    rj.update(replay_json(rp.replay));
    replays.push_back(rj);
  }
  j["mujoco_replay"] = replays;
  j["solve_seconds"] = num(r.seconds);
  j["samples_evaluated"] = r.samples_evaluated;
  return j;
}

std::unique_ptr<StudyRun> load(cases::Map& root, const cases::CaseInfo&) {
  pl::Spec spec = cases::load_placement(root);
  if (!root.diag().empty()) return nullptr;
  return std::make_unique<PlacementRun>(std::move(spec));
}

}  // namespace

StudyEntry placement_entry() {
  return {"placement", "energy-optimal root location of a 2-link arm for a straight-line task", &load};
}

}  // namespace armstudy::app
