// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The placement study in the pipeline: case -> studies::placement::solve -> results.json.
//
// results.json "placement" section: studies/placement/study_results.hpp (every key, typed;
// written from it here, read back from it by the report and merge).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "app/export_records.hpp"
#include "app/json_numbers.hpp"
#include "app/pipeline.hpp"
#include "app/placement_cycle_time_section.hpp"
#include "app/replay_json.hpp"
#include "app/study_entry.hpp"
#include "cases/placement_case.hpp"
#include "core/motion_program.hpp"
#include "report/motion_csv.hpp"
#include "report/results_fields.hpp"
#include "report/study_sections.hpp"
#include "scene/model_export.hpp"
#include "scene/placement_frames.hpp"
#include "scene/replay_frames.hpp"
#include "scene/study_replays.hpp"
#include "studies/placement/refine.hpp"
#include "studies/placement/solve.hpp"
#include "studies/placement/study_results.hpp"
#include "studies/placement/warm_solve.hpp"

namespace armstudy::app {
namespace {
namespace pl = studies::placement;
using core::kDeg;
using nlohmann::json;

using Results = pl::StudyResults;

Results::Pair pair(const Eigen::Vector2d& v) { return {v.x(), v.y()}; }

Results::Series series_section(const pl::TimeSeries& s) {
  Results::Series o;
  const size_t n = s.t.size();
  const size_t stride = n > 101 ? (n - 1 + 99) / 100 : 1;
  o.stride = static_cast<int>(stride);
  for (size_t k = 0; k < n; k += stride) {
    o.t_s.push_back(s.t[k]);
    o.q1_rad.push_back(s.q[k][0]);
    o.q2_rad.push_back(s.q[k][1]);
    o.qd1_rad_s.push_back(s.qd[k][0]);
    o.qd2_rad_s.push_back(s.qd[k][1]);
    o.qdd1_rad_s2.push_back(s.qdd[k][0]);
    o.qdd2_rad_s2.push_back(s.qdd[k][1]);
    o.tau1_Nm.push_back(s.tau[k][0]);
    o.tau2_Nm.push_back(s.tau[k][1]);
    o.power1_W.push_back(s.power[k][0]);
    o.power2_W.push_back(s.power[k][1]);
    o.energy_J.push_back(s.energy[k]);
    if (k + stride >= n && k != n - 1) k = n - 1 - stride;  // always end on the last sample
  }
  return o;
}

Results::SweepCounts counts_section(const pl::Counts& c) {
  return {c.total,    c.unreachable,  c.singular,        c.over_limit,
          c.feasible, c.thesis_total, c.thesis_rejected, c.exact_outside_thesis};
}

std::string prog(core::MotionProgram p) { return std::string(core::program_name(p)); }

Results::Id id_of(core::MotionProgram p, int configuration) { return {prog(p), configuration}; }

// the doubling of one motion's samples (converge.hpp)
Results::EnergyConvergence convergence_section(const pl::EnergyConvergence& c) {
  Results::EnergyConvergence o;
  for (const auto& r : c.rows) o.rows.push_back({r.samples, r.energy, r.peak_torque});
  o.converged = c.converged;
  o.touches_boundary = c.touches_boundary;
  o.singular = !c.regular();
  o.samples = c.samples;
  o.rel_change = c.rel_change;
  o.peak_torque_rel_change = c.peak_rel_change;
  o.tolerance_rel = c.tolerance;
  o.peak_converged = c.peak_converged;
  if (c.quadrature) {
    Results::Quadrature q;
    q.energy_J = c.energy;
    q.error_J = c.energy_error;
    q.tolerance_rel = c.quadrature_tolerance;
    q.converged = c.energy_converged();
    q.intervals = c.quadrature_intervals;
    q.evaluations = c.quadrature_evaluations;
    o.quadrature = q;
  }
  return o;
}

// energy (with its error), peak torque of a candidate: null (and a note) where withheld
void set_metrics(Results::Metrics& o, const pl::Candidate& c) {
  const pl::EnergyConvergence& conv = c.convergence;
  const bool no_energy = conv.energy_withheld(), no_peak = conv.peak_withheld();
  const pl::LineMetrics& m = c.reported_metrics();
  o.energy_J = no_energy ? NAN : m.energy;
  if (!no_energy && conv.quadrature) o.energy_error_J = conv.energy_error;
  if (!no_energy && !no_peak) o.peak_torque_Nm = Results::Pair{m.peak_torque[0], m.peak_torque[1]};
  if (conv.checked) o.energy_samples = conv.samples;
  o.singular_trajectory = no_energy || no_peak;
  if (no_energy)
    o.note = pl::kSingularNote;
  else if (no_peak)
    o.note = conv.energy_jump > 0 ? pl::kFoldedElbowNote : pl::kPeakUnboundedNote;
  if (conv.checked) o.energy_convergence = convergence_section(conv);
}

// what decides an optimum (refine.hpp)
Results::Decision decision_section(const pl::Spec& spec, const pl::Decision& d) {
  Results::Decision o;
  o.binding = pl::binding_name(d.binding);
  o.inner_slack_m = d.inner_slack;
  o.outer_slack_m = d.outer_slack;
  o.margin_m = spec.singularity_margin;
  if (d.joint >= 0) o.joint = d.joint + 1;
  o.torque_slack_Nm = {d.torque_slack[0], d.torque_slack[1]};
  o.power_slack_W = {d.power_slack[0], d.power_slack[1]};
  for (const pl::ActiveConstraint& a : d.active) {
    Results::Active s;
    s.constraint = pl::binding_name(a.kind);
    if (a.joint >= 0) s.joint = a.joint + 1;
    s.slack = a.slack;
    o.active.push_back(std::move(s));
  }
  o.set_by_margin = d.margin_active();
  return o;
}

class PlacementRun final : public TypedStudyRun<pl::Spec, pl::Result, Results> {
 public:
  using TypedStudyRun::TypedStudyRun;

  studies::Status solve(const studies::ProgressFn& progress) override {
    std::optional<pl::Result> warm;
    if (warm_from_) warm = pl::solve_warm(spec_, *warm_from_);
    warm_used_ = warm.has_value();
    result_ = warm ? std::move(*warm) : pl::solve(spec_, progress);
    // MuJoCo's own dynamics on every optimum's torques (scene/dynamic_replay.hpp)
    if (result_.status == studies::Status::kSolved && !lean_) {
      if (progress) progress(0.97, "MuJoCo dynamic replay");
      replays_ = scene::replay_placement(spec_, result_);
    }
    return result_.status;
  }
  std::vector<studies::Check> checks() const override {
    std::vector<studies::Check> c = result_.checks;
    for (const scene::PlacementReplay& r : replays_) {
      // check names are [a-z0-9_.]+ (results.schema.json)
      const std::string id = prog(r.program) + "." + std::to_string(r.configuration);
      c.push_back(scene::replay_check(
          r.replay, "mujoco_dynamic_replay." + id,
          "the optimum " + prog(r.program) + ", configuration " + std::to_string(r.configuration)));
    }
    return c;
  }
  Results study_results() const override;

  // per program and configuration: the refined optimum's energy and root location
  std::vector<KeyFigure> key_figures() const override {
    std::vector<KeyFigure> k;
    double best = std::numeric_limits<double>::infinity();
    for (const pl::ProgramConfig& pc : result_.cases) {
      if (!pc.found || pc.refined.convergence.energy_withheld()) continue;
      const std::string id = "[" + prog(pc.program) + "," + std::to_string(pc.configuration) + "]";
      const std::string who = ", " + prog(pc.program) + " " + std::to_string(pc.configuration);
      const double energy = pc.refined.reported_metrics().energy;
      k.push_back({"energy_J" + id, energy, "J", "energy" + who});
      k.push_back({"root_x_m" + id, pc.refined.root.x(), "m", "root x" + who});
      k.push_back({"root_y_m" + id, pc.refined.root.y(), "m", "root y" + who});
      best = std::min(best, energy);
    }
    if (std::isfinite(best))
      k.insert(k.begin(), {"min_energy_J", best, "J", "lowest energy (the optimum)"});
    // the cycle-time objective's answer first when the case asks for it
    const pl::CycleTimeOptimum* fast = nullptr;
    for (const pl::CycleTime& c : result_.cycle_time)
      if (c.optimum.found &&
          (!fast || c.optimum.converged.duration < fast->converged.duration - fast->duration_error))
        fast = &c.optimum;
    if (fast) {
      std::vector<KeyFigure> f{{"min_cycle_time_s", fast->converged.duration, "s",
                                "fastest cycle (the cycle-time optimum)"}};
      if (fast->fast_energy.computed)
        f.push_back({"fastest_cycle_energy_J", fast->fast_energy.energy, "J",
                     "energy of the fastest cycle"});
      k.insert(k.begin(), f.begin(), f.end());
    }
    if (!result_.cases.empty()) {
      const pl::Counts& c = result_.cases.front().counts;
      k.push_back(
          {"candidates_clear", double(c.feasible + c.over_limit), "", "candidate lines clear"});
      k.push_back({"candidates_singular", double(c.singular), "", "candidate lines singular"});
    }
    return k;
  }

  // model.xml (the least-energy optimum's scene, keyframes at its strip's times) and one
  // CSV per optimum
  std::vector<report::ExportRecord> write_exports(const std::filesystem::path& dir,
                                                  const cases::CaseInfo& info) override {
    std::vector<report::ExportRecord> out;
    const pl::ProgramConfig* best = nullptr;
    for (const pl::ProgramConfig& pc : result_.cases) {
      if (!pc.found || pc.series.t.size() < 2) continue;
      // energies equal within their error estimates (mirror-image optima) are a tie: the
      // first stays, as in the answer's sentence
      const bool regular = pc.refined.convergence.regular();
      if (!best || (regular && (!best->refined.convergence.regular() ||
                                pc.refined.reported_metrics().energy <
                                    best->refined.reported_metrics().energy -
                                        (pc.refined.convergence.energy_error +
                                         best->refined.convergence.energy_error))))
        best = &pc;
    }
    if (!best) return out;
    const auto name = [](const pl::ProgramConfig& pc) {
      return "placement_" + std::string(core::program_name(pc.program)) + "_c" +
             std::to_string(pc.configuration);
    };
    const std::string motion =
        "the " + prog(best->program) + " optimum, configuration " +
        std::to_string(best->configuration) + " (" + name(*best) +
        "_strip.png, drawn in the line's frame: the arm at its optimal root)";
    const scene::ArmScene sc = scene::placement_scene(spec_, *best, info.render);
    const auto keys = scene::strip_keyframes(scene::placement_motion(*best), info.render.frames);
    out.push_back(model_export_entry(
        scene::write_model_xml(dir, sc.chain, sc.mjcf, keys, motion, info.path), motion, keys));
    for (const pl::ProgramConfig& pc : result_.cases) {
      if (!pc.found || pc.series.t.size() < 2) continue;
      const pl::TimeSeries& ser = pc.series;
      report::MotionCsv t;
      t.file = "motion_" + name(pc) + ".csv";
      t.what =
          "the refined " + prog(pc.program) + " optimum, configuration " +
          std::to_string(pc.configuration) +
          " (results.json placement.optima[].series): time, tip in the arm's frame, joint angles, "
          "rates, "
          "accelerations, torques, signed joint powers and the energy consumed so far (integral of "
          "|P1| + |P2|); no motors";
      t.add("t", "s", ser.t);
      t.add_joints("tip_", "m", ser.tip);
      t.columns[t.columns.size() - 2].name = "tip_x";
      t.columns[t.columns.size() - 1].name = "tip_y";
      t.add_joints("q", "rad", ser.q);
      t.add_joints("qd", "rad/s", ser.qd);
      t.add_joints("qdd", "rad/s^2", ser.qdd);
      t.add_joints("tau", "N m", ser.tau);
      t.add_joints("power", "W", ser.power);
      t.add("energy", "J", ser.energy);
      report::write_motion_csv(dir, t);
      out.push_back(csv_export_entry(t, prog(pc.program) + "." + std::to_string(pc.configuration)));
    }
    return out;
  }

  // frames: the optimum of every program and configuration (src/scene)
  scene::Rendered render(const std::filesystem::path& dir, const cases::CaseInfo& info) override {
    scene::Rendered out = scene::render_placement_frames(spec_, result_, info.render, dir);
    for (auto& f : scene::render_placement_replay(spec_, result_, replays_, info.render, dir))
      out.frames.push_back(std::move(f));
    return out;
  }

 private:
  std::vector<scene::PlacementReplay> replays_;
  const pl::Result* warm_from_ = nullptr;  ///< a sensitivity step's nominal answer
  bool lean_ = false;                      ///< a sensitivity step: no report extras
  bool warm_used_ = false;                 ///< the last solve refined the nominal optimum

 public:
  // a sensitivity step: refined from the nominal optimum (studies/placement/warm_solve.hpp);
  // where that optimum is not admissible at the step, solved anew without the map, the
  // margin sweep, the evaluations and MuJoCo's replay
  bool warm_start(const StudyRun& nominal) override {
    lean_ = true;
    spec_.map_nx = spec_.map_ny = 2;
    spec_.sensitivity_margins.clear();
    spec_.evaluations.clear();
    const auto* n = dynamic_cast<const PlacementRun*>(&nominal);
    if (!n || n->result_.status != studies::Status::kSolved) return false;
    warm_from_ = &n->result_;
    return true;
  }
  bool warm_started() const override { return warm_used_; }
  // the active constraints of the least-energy optimum (refine.hpp's order)
  std::vector<std::string> binding() const override {
    const pl::ProgramConfig* best = nullptr;
    for (const pl::ProgramConfig& pc : result_.cases)
      if (pc.found && !pc.refined.convergence.energy_withheld() &&
          (!best || pc.refined.reported_metrics().energy < best->refined.reported_metrics().energy))
        best = &pc;
    std::vector<std::string> b;
    if (!best) return b;
    for (const pl::ActiveConstraint& a : best->decision.active) {
      std::string words = pl::binding_name(a.kind);  // inner_clearance -> inner clearance
      std::replace(words.begin(), words.end(), '_', ' ');
      b.push_back(words + (a.joint >= 0 ? ", joint " + std::to_string(a.joint + 1) : ""));
    }
    return b;
  }
};

// the placement of a candidate: x_S, phi and the root in the line's frame
template <class T>
void set_place(T& o, const pl::Candidate& c) {
  o.x_s_m = c.x_s;
  o.phi_deg = c.phi / kDeg;
  o.root_xy_m = pair(c.root);
}

// the optimum of one program and configuration, with its margin sweep
Results::Optimum optimum_section(const pl::Spec& spec, const pl::ProgramConfig& pc,
                                 const Results::Id& id) {
  const pl::Candidate& c = pc.refined;
  Results::Optimum o;
  static_cast<Results::Id&>(o) = id;
  set_metrics(o, c);
  set_place(o, c);
  o.grid_energy_J = pc.grid.metrics.energy;
  o.grid_x_s_m = pc.grid.x_s;
  o.grid_phi_deg = pc.grid.phi / kDeg;
  o.min_abs_sin_elbow = c.min_abs_sin;
  o.boundary_distance_m = c.boundary_distance;
  o.peak_power_W = {c.metrics.peak_power[0], c.metrics.peak_power[1]};
  o.signed_work_J = c.metrics.signed_work;
  o.singular = c.status != pl::CandidateStatus::kFeasible || !c.convergence.regular();
  o.refine_evaluations = pc.refine_evaluations;
  o.decided_by = decision_section(spec, pc.decision);
  if (!pc.refine_method.empty()) o.refinement.method = pc.refine_method;
  o.refinement.final_tolerance_rel = pc.refine_method.empty() ? NAN : pc.refine_tolerance_rel;
  o.refinement.target_rel = 1e-7;
  o.refinement.converged = pc.refine_converged;
  o.refinement.evaluations = pc.refine_evaluations;
  o.refinement.x_s_error_m = pc.x_s_error;
  o.refinement.phi_error_deg = pc.phi_error / kDeg;
  o.refinement.root_error_m = std::hypot(pc.x_s_error, c.x_s * pc.phi_error);
  o.refinement.energy_error_J = pc.energy_error();
  for (const pl::MarginPoint& m : pc.margin_sensitivity) {
    Results::MarginPoint mp;
    mp.margin_m = m.margin;
    mp.found = m.found;
    if (m.found) {
      Results::MarginOptimum mo;
      set_metrics(mo, m.optimum);
      set_place(mo, m.optimum);
      mo.binding = pl::binding_name(m.decision.binding);
      mo.refine_converged = m.refine_converged;
      mo.refine_tolerance_rel = m.refine_tolerance_rel;
      mo.x_s_error_m = m.x_s_error;
      mo.phi_error_deg = m.phi_error / kDeg;
      mp.optimum = std::move(mo);
    }
    o.margin_sensitivity.push_back(std::move(mp));
  }
  o.line_start_m = pair(pc.placement.start);
  o.line_end_m = pair(pc.placement.end);
  o.counts = counts_section(pc.counts);
  o.series = series_section(pc.series);
  return o;
}

// the least energy among the thesis's own candidates
Results::ThesisBest thesis_best_section(const pl::ProgramConfig& pc, const Results::Id& id) {
  const pl::Candidate& c = pc.thesis_best;
  Results::ThesisBest t;
  static_cast<Results::Id&>(t) = id;
  set_metrics(t, c);
  set_place(t, c);
  t.status = pl::status_name(c.status);
  t.singular = c.status == pl::CandidateStatus::kSingular;
  t.boundary_distance_m = c.boundary_distance;
  t.min_abs_sin_elbow = c.min_abs_sin;
  return t;
}

// energy over phi through the optimum's x_S
Results::Curve curve_section(const pl::ProgramConfig& pc, const Results::Id& id) {
  Results::Curve cv;
  static_cast<Results::Id&>(cv) = id;
  cv.x_s_m = pc.curve.x_s;
  for (size_t k = 0; k < pc.curve.phi.size(); ++k) {
    cv.phi_deg.push_back(pc.curve.phi[k] / kDeg);
    cv.energy_J.push_back(pc.curve.energy[k]);
    cv.status += pl::status_char(pc.curve.status[k]);
  }
  return cv;
}

// the Pareto front of (peak torque of `joint`, energy), thinned, and the excluded candidates
Results::Pareto pareto_section(const pl::ProgramConfig& pc, const Results::Id& id, int joint) {
  Results::Pareto pj;
  static_cast<Results::Id&>(pj) = id;
  pj.joint = joint + 1;
  const auto& front = pc.pareto[joint];
  double last = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < front.size(); ++k) {
    // thin: keep the first, the last, and steps of >= 0.2 % in energy
    if (k != 0 && k + 1 != front.size() && front[k].energy > last * (1 - 2e-3)) continue;
    last = front[k].energy;
    pj.peak_torque_Nm.push_back({front[k].peak_torque[0], front[k].peak_torque[1]});
    pj.energy_J.push_back(front[k].energy);
    pj.x_s_m.push_back(front[k].x_s);
    pj.phi_deg.push_back(front[k].phi / kDeg);
    pj.singular.push_back(front[k].singular);
  }
  // the inadmissible candidates inside the margin: drawn distinctly, never the front
  pj.excluded.what = "candidates inside the clearance margin (inadmissible), energy converged";
  last = std::numeric_limits<double>::infinity();
  const auto& ex = pc.pareto_excluded[joint];
  for (size_t k = 0; k < ex.size(); ++k) {
    if (k != 0 && k + 1 != ex.size() && ex[k].energy > last * (1 - 2e-3)) continue;
    last = ex[k].energy;
    pj.excluded.peak_torque_Nm.push_back({ex[k].peak_torque[0], ex[k].peak_torque[1]});
    pj.excluded.energy_J.push_back(ex[k].energy);
  }
  return pj;
}

// the energy map over root locations, as rows of text
Results::Map map_section(const pl::ProgramConfig& pc, const Results::Id& id) {
  const pl::EnergyMap& m = pc.map;
  Results::Map mj;
  static_cast<Results::Id&>(mj) = id;
  mj.x_m = m.x;
  mj.y_m = m.y;
  const size_t nx = m.x.size();
  for (size_t row = 0; row < m.y.size(); ++row) {
    std::string e, st;
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
      st += pl::status_char(m.status[row * nx + i]);
    }
    mj.energy_J_rows.push_back(std::move(e));
    mj.status_rows.push_back(std::move(st));
  }
  if (pc.found) mj.optimum_xy_m = pair(pc.refined.root);
  mj.encoding =
      "row j is y_m[j]; energy_J_rows: space-separated energies in J at 4 significant digits, "
      "'-' where unreachable or the sampled energy is not converged to 1e-4; status_rows: '.' "
      "unreachable, 's' singular, 'x' over a limit, "
      "'o' feasible; Y < 0 is the mirror image with the configurations swapped";
  return mj;
}

// one placement the case asked to evaluate
Results::Evaluation evaluation_section(const pl::Evaluation& e) {
  Results::Evaluation ej;
  static_cast<Results::Id&>(ej) = id_of(e.program, e.configuration);
  ej.label = e.label;
  const pl::Candidate& c = e.candidate;
  set_place(ej, c);
  const bool reachable = c.status != pl::CandidateStatus::kUnreachable;
  if (reachable) {
    set_metrics(ej, c);
  } else {
    ej.energy_J = NAN;  // peak_torque_Nm null
  }
  ej.status = pl::status_name(c.status);
  ej.singular = c.status == pl::CandidateStatus::kSingular;
  ej.boundary_distance_m = c.boundary_distance;
  ej.min_abs_sin_elbow = c.min_abs_sin;
  ej.saving_J = e.has_saving ? e.saving : NAN;
  ej.saving_percent = e.has_saving ? e.saving_percent : NAN;
  ej.line_start_m = pair(e.placement.start);
  ej.line_end_m = pair(e.placement.end);
  if (!e.series.t.empty()) ej.series = series_section(e.series);
  return ej;
}

// (over 60 lines, kept whole: a flat list of the typed results's fields, in their fields() order;
// each part has its own function)
Results PlacementRun::study_results() const {
  const pl::Result& r = result_;
  Results j;
  j.lmax_m = r.lmax;
  j.length_m = r.length;
  j.length_fraction = r.lmax > 0 ? r.length / r.lmax : 0.0;
  j.duration_s = spec_.duration;
  j.samples = spec_.samples;
  j.singularity_margin_m = spec_.singularity_margin;
  j.thesis_divisions = spec_.thesis_divisions;
  j.annulus_m = {r.inner, r.outer};
  if (spec_.torque_limit)
    j.torque_limits_Nm = Results::Pair{(*spec_.torque_limit)[0], (*spec_.torque_limit)[1]};
  if (spec_.power_limit)
    j.power_limits_W = Results::Pair{(*spec_.power_limit)[0], (*spec_.power_limit)[1]};
  j.thesis_intervals = {r.thesis_xs_case, r.xs_init, r.xs_fin};
  if (!r.cases.empty()) {
    const pl::Counts& c = r.cases.front().counts;
    j.geometry_counts = Results::GeometryCounts{c.total,
                                                c.unreachable,
                                                c.singular,
                                                c.feasible + c.over_limit,
                                                c.thesis_total,
                                                c.thesis_rejected,
                                                c.exact_outside_thesis};
  }
  for (const pl::ProgramConfig& pc : r.cases) {
    const Results::Id id = id_of(pc.program, pc.configuration);
    if (pc.found) {
      j.optima.push_back(optimum_section(spec_, pc, id));
    } else {
      Results::Unsolved u;
      static_cast<Results::Id&>(u) = id;
      u.reason = pc.reason;
      u.counts = counts_section(pc.counts);
      j.unsolved.push_back(std::move(u));
    }
    if (pc.thesis_found) {
      j.thesis_search.push_back(thesis_best_section(pc, id));
    }
    j.curves.push_back(curve_section(pc, id));
    for (int joint = 0; joint < 2; ++joint) {
      j.pareto.push_back(pareto_section(pc, id, joint));
    }
    j.maps.push_back(map_section(pc, id));
  }
  for (const pl::Evaluation& e : r.evaluations) {
    j.evaluations.push_back(evaluation_section(e));
  }
  for (const auto& pc : r.cases) {
    if (!pc.found) continue;
    Results::Convergence conv;
    static_cast<Results::Id&>(conv) = id_of(pc.program, pc.configuration);
    for (const auto& row : r.convergence) conv.rows.push_back({row.samples, row.energy});
    j.convergence = std::move(conv);
    break;
  }
  for (const scene::PlacementReplay& rp : replays_) {
    Results::Replay rj;
    static_cast<Results::Id&>(rj) = id_of(rp.program, rp.configuration);
    static_cast<studies::ReplayResults&>(rj) = replay_results(rp.replay);
    j.mujoco_replay.push_back(std::move(rj));
  }
  j.cycle_time = cycle_time_section(spec_, r);
  j.solve_seconds = r.seconds;
  j.samples_evaluated = r.samples_evaluated;
  // an arm read from a URDF or MJCF: its plane and where its limits came from (as the
  // time-optimal study's arm_model)
  if (spec_.arm_origin.from_model()) j.arm_model = spec_.arm_origin.lines();
  return j;
}

}  // namespace

StudyParts placement_parts() {
  return study_parts<PlacementRun>(
      "energy-optimal root location of a 2-link arm for a straight-line task",
      &report::placement_sections, &report::placement_answer,
      {"placement_root_loci.svg", "Optimal root locations across the placement cases",
       "optimal root locations of every placement case",
       "The optimal root location of each program and configuration in the frame fixed to the task "
       "line (every line starts at the origin and runs along X), one point per placement case, "
       "joined from the shortest line to the longest: Figure 9.30 of Kopmaz's thesis (2016; "
       "docs/sources.md), from this run's cases. Cases without an admissible optimum contribute no "
       "point. Triangles: the roots the thesis prints, by (4.14) from its printed x_S and φ "
       "(the bundled examples evaluate them as thesis-config-1, thesis-config-2 and "
       "thesis-only-line).",
       &report::placement_loci_across_cases});
}

}  // namespace armstudy::app
