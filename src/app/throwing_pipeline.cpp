// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The throwing study in the pipeline: case -> studies::solve_throwing -> results.json.
//
// results.json "throwing" section: studies/throwing/study_results.hpp (every key, typed;
// written from it here, read back from it by the report and merge).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <locale>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/export_records.hpp"
#include "app/json_numbers.hpp"
#include "app/pipeline.hpp"
#include "app/study_checks.hpp"
#include "app/study_entry.hpp"
#include "cases/throwing_case.hpp"
#include "report/motion_csv.hpp"
#include "report/results_fields.hpp"
#include "report/study_sections.hpp"
#include "scene/model_export.hpp"
#include "scene/throwing_frames.hpp"
#include "studies/throwing/study_results.hpp"
#include "studies/throwing/warm_solve.hpp"

namespace armstudy::app {
namespace {
using nlohmann::json;
namespace st = studies;
using core::kDeg;

using Results = st::ThrowingStudyResults;

template <typename V>
std::vector<double> arr(const V& v) {
  std::vector<double> a;
  for (int i = 0; i < v.size(); ++i) a.push_back(v[i]);
  return a;
}

// margins (> 0 met) in physical units of an evaluation
Results::Margins margins_of(const st::ThrowingSpec& sp, const st::ProfileEvaluation& e) {
  Results::Margins m;
  m.contact_N = e.min_normal_force - sp.contact_margin;
  m.friction = sp.friction_coefficient - e.max_friction_ratio;
  m.tray_rad = sp.tray_width / 2 - e.max_abs_theta4;
  m.release_rad = sp.release_tolerance - std::abs(e.theta3_final - sp.theta3_release);
  m.voltage_V = sp.voltage_max - e.max_voltage;
  m.current_A = sp.current_max - e.max_current;
  m.power_W = sp.power_max - e.max_power;
  return m;
}

// in the order of st::ConstraintKind
Results::Worst worst_of(const std::array<double, st::kConstraintKinds>& w) {
  return {w[0], w[1], w[2], w[3], w[4], w[5], w[6]};
}

// the motor rating nearest its limit, "(not binding)" when it is not within twice the back-off
std::string binding_rating(const std::array<double, st::kConstraintKinds>& w, double backoff) {
  int best = static_cast<int>(st::ConstraintKind::kVoltage);
  for (int c : {static_cast<int>(st::ConstraintKind::kCurrent),
                static_cast<int>(st::ConstraintKind::kPower)})
    if (w[c] > w[best]) best = c;
  return std::string(st::constraint_name(static_cast<st::ConstraintKind>(best))) +
         (w[best] >= -2 * backoff - 1e-9 ? "" : " (nearest; not binding)");
}

Results::Motion motion_of(const st::ThrowingSpec& sp, const st::ThrowMotion& m) {
  const auto& e = m.evaluation;
  Results::Motion j;
  j.energy_J = e.energy;
  j.max_abs_theta4_rad = e.max_abs_theta4;
  j.max_voltage_V = e.max_voltage;
  j.max_current_A = e.max_current;
  j.max_power_W = e.max_power;
  j.min_normal_force_N = e.min_normal_force;
  j.max_friction_ratio = e.max_friction_ratio;
  j.feasible = e.feasible;
  j.worst_normalised = worst_of(m.worst);
  j.margins = margins_of(sp, e);
  j.release_error = {arr(m.angle_error), arr(m.rate_error)};
  j.energy_split = {m.split.electrical, m.split.mechanical, m.split.copper, m.split.friction,
                    m.split.rest};
  for (int k = 0; k <= m.profile.stages(); ++k) {
    j.profile.t_s.push_back(k * m.profile.stage_length());
    j.profile.rate_rad_s.push_back(arr(Eigen::Vector2d(m.profile.v.col(k))));
  }
  const auto& s = m.series;
  Results::Series& o = j.series;
  for (size_t k = 0; k < s.t.size(); ++k) {
    o.t_s.push_back(s.t[k]);
    o.q_rad.push_back(arr(s.q[k]));
    o.qd_rad_s.push_back(arr(s.qd[k]));
    o.torque_Nm.push_back(arr(s.tau_m[k]));
    o.voltage_V.push_back(arr(s.voltage[k]));
    o.current_A.push_back(arr(s.current[k]));
    o.power_W.push_back(arr(s.power[k]));
    o.energy_J.push_back(s.energy[k]);
    o.ball_xy_m.push_back(arr(s.ball[k]));
    o.normal_force_N.push_back(s.normal_force[k]);
    o.tangential_force_N.push_back(s.tangential_force[k]);
    // friction needed to roll, |F_t| / N (null where the tray does not push the ball)
    o.friction_needed.push_back(
        s.normal_force[k] > 0 ? std::abs(s.tangential_force[k]) / s.normal_force[k] : NAN);
  }
  // the stage of each sample: the end sample of a stage repeats its time
  int stg = 0;
  for (size_t k = 0; k < s.t.size(); ++k) {
    o.stage.push_back(stg);
    if (k + 1 < s.t.size() && s.t[k + 1] == s.t[k]) ++stg;
  }
  return j;
}

// every SLSQP start's simulations
long slsqp_simulations(const st::ThrowingResult& r) {
  long n = 0;
  for (const auto& s : r.slsqp_starts) n += s.run.simulations;
  return n;
}

// 0.01, 1e-05: a setting as a reader wrote it
std::string short_number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

// the arm, motors and task of the case, and the modelling choices
void set_parameters(const st::ThrowingSpec& spec, Results& j) {
  const auto& a = spec.arm;
  auto& p = j.parameters;
  p.gravity_m_s2 = a.gravity;
  p.link1 = {a.l1, a.m1, a.r1, a.I1};
  p.link2 = {a.l2, a.m2, a.r2, a.I2};
  p.tray = {a.circle_offset, a.m3, a.r3, a.r3_lateral, a.I3, spec.tray_width / kDeg};
  p.ball = {a.m4, a.r4, a.rb, a.Ib};
  p.motors = {spec.motor.kt,
              spec.motor.kv,
              spec.motor.Ra,
              spec.motor.Dm,
              spec.motor.tau_f,
              a.rotor_inertia,
              a.motor2 == st::Motor2Mount::kOnBase ? "on_base" : "on_link1",
              spec.count_regeneration};
  p.task = {{spec.start[0] / kDeg, spec.start[1] / kDeg, spec.theta3_start / kDeg,
             spec.theta4_start / kDeg},
            {spec.release[0] / kDeg, spec.release[1] / kDeg, spec.theta3_release / kDeg},
            {spec.release_rate[0], spec.release_rate[1]},
            spec.tf,
            spec.landing_height};
  p.choices = {
      "model derived from first principles (docs/derivations/throwing.md): ball spin = "
      "tray rate - (r4/r_b) "
      "theta4'; eq. 3's spin term and a5 as printed are wrong",
      "the centre of the ball's circle lies at the tray's circle offset from its hinge (Table "
      "1's l3 "
      "by default)",
      "ball inertia 2/5 m r_b^2 unless given (equals Table 1's 4.8e-7 kg m^2)",
      "motor 2 drives theta2 (on_link1, eq. 5 as printed) unless motor2: on_base",
      "rotor inertia (missing from Table 1) as the case's motors give it",
      "tray width lambda (eq. 9) and the current limit as the case gives them",
      "energy = eq. 7 (signed e i: regeneration counted) unless the case counts only e i > 0",
      "theta3 at release is a constraint (within the release tolerance), reached through the "
      "passive dynamics"};
}

// what the case assumes where the paper is silent, and the limits
void set_assumptions(const st::ThrowingSpec& spec, Results& j) {
  const auto& a = spec.arm;
  j.assumptions = {{"tray's angular width lambda (eq. 9): the ball stays within +-lambda/2",
                    spec.tray_width / kDeg, "deg", "tray.width_deg"},
                   {"friction coefficient between ball and tray (rolling needs |F_t| <= mu N)",
                    spec.friction_coefficient, "", "constraints.friction_coefficient"},
                   {"contact margin: the tray's normal force on the ball stays above it",
                    spec.contact_margin, "N", "constraints.contact_margin_N"},
                   {"current limit of each motor (not in Table 1)", spec.current_max, "A",
                    "motors.current_max_A"},
                   {"Table 1's 60 W rating read as a limit on |e i| of each motor", spec.power_max,
                    "W", "motors.power_max_W"},
                   {"Table 1's 24 V rating read as a limit on |e|", spec.voltage_max, "V",
                    "motors.voltage_max_V"},
                   {"release tolerance of the passive tray angle theta3",
                    spec.release_tolerance / kDeg, "deg", "constraints.release_tolerance_deg"},
                   {"constraint back-off of both optimisers (normalised)", spec.backoff, "",
                    "constraints.backoff"},
                   {"rotor inertia of each motor (not in Table 1)", a.rotor_inertia, "kg m^2",
                    "motors.rotor_inertia_kg_m2"},
                   {"sign(qd) of the motors' Coulomb term taken as a smooth step within +-this "
                    "rate (a numerical regularisation; 0: the exact sign)",
                    spec.motor.coulomb_band, "rad/s", "motors.coulomb_band_rad_s"},
                   {"centre of the ball's circle from the tray hinge", a.circle_offset, "m",
                    "tray.circle_offset_m"}};
  j.limits = {spec.voltage_max,       spec.current_max,
              spec.power_max,         {-spec.tray_width / 2, spec.tray_width / 2},
              spec.contact_margin,    spec.friction_coefficient,
              spec.release_tolerance, spec.backoff};
}

// the eq. 8 reference: the constraints it breaks and how it was repaired
void set_reference(const st::ThrowingSpec& spec, const st::ThrowingResult& r,
                   Results::Optimised& o) {
  {
    const Results::Margins mg = margins_of(spec, r.initial.evaluation);
    const char* units[st::kConstraintKinds] = {"N", "", "rad", "V", "A", "W", "rad"};
    const double margins[st::kConstraintKinds] = {mg.contact_N,  mg.friction,  mg.tray_rad,
                                                  mg.voltage_V,  mg.current_A, mg.power_W,
                                                  mg.release_rad};
    for (int c = 0; c < st::kConstraintKinds; ++c)
      if (r.initial.worst[c] > 0)
        o.reference.raw_breaks.push_back({st::constraint_name(static_cast<st::ConstraintKind>(c)),
                                          r.initial.worst[c], margins[c], units[c]});
    o.reference.kind = r.reference_kind;
    o.reference.initial_feasible = r.initial_feasible;
    if (r.reference_kind != "eq8")
      o.reference.repair = Results::Repair{
          "SLSQP from eq. 8 descending the squared constraint violation "
          "(aimed at twice the back-off inside every limit) until it is 0 "
          "or stops on its tolerance; the reference must then meet every "
          "constraint with the back-off",
          r.repair_run.return_code,
          r.repair_run.converged,
          r.repair_run.feasible,
          r.repair_run.iterations,
          r.repair_run.simulations,
          r.repair_run.run_time,
          r.repair_run.rate_change};
  }
}

// the IDP run (the paper's method): its seeds, settings and first-order residual; returns
// the simulations of all seeds
long set_idp(const st::ThrowingSpec& spec, const st::ThrowingResult& r, Results::Optimised& o) {
  Results::Idp& idp = o.idp;
  for (const auto& h : r.idp_run.history)
    idp.convergence.push_back(
        {h.iteration, h.pass, h.energy, h.violation, arr(h.region), h.evaluations, h.improvements});
  const auto& is = spec.idp;
  std::vector<double> es;
  long evaluations = 0;
  for (const auto& sd : r.idp_seeds) {
    idp.seed_runs.push_back({sd.seed, sd.evaluation.energy, sd.evaluation.feasible, sd.converged,
                             sd.passes, sd.last_gain, sd.evaluations, sd.run_time});
    es.push_back(sd.evaluation.energy);
    evaluations += sd.evaluations;
  }
  std::sort(es.begin(), es.end());
  const double median = es.empty()      ? NAN
                        : es.size() % 2 ? es[es.size() / 2]
                                        : 0.5 * (es[es.size() / 2 - 1] + es[es.size() / 2]);
  idp.stages = spec.stages;
  idp.steps_per_stage = spec.steps_per_stage;
  idp.iterations = is.iterations;
  idp.max_passes = is.max_passes;
  idp.tolerance = is.tolerance;
  idp.quiet_passes = is.quiet_passes;
  idp.candidates = is.candidates;
  idp.shrink = is.shrink;
  idp.restore = is.restore;
  idp.region_rad_s = arr(is.region);
  idp.seed = is.seed;
  idp.seeds = is.seeds;
  idp.backoff = spec.backoff;
  idp.threads = r.idp_run.threads;
  idp.converged = r.idp_converged;
  idp.best_seed = r.idp_run.seed;
  idp.passes = r.idp_run.passes;
  idp.last_gain = r.idp_run.last_gain;
  idp.evaluations = evaluations;
  idp.run_time_s = r.idp_time;
  idp.spread = {es.empty() ? NAN : es.front(), median, es.empty() ? NAN : es.back()};
  idp.first_order =
      Results::FirstOrder{r.idp_optimality.kkt_residual, spec.nlopt.kkt_tolerance,
                          r.idp_optimality.active_constraints, r.idp_optimality.binding};
  return evaluations;
}

// the SLSQP run from several starts
void set_nlopt(const st::ThrowingSpec& spec, const st::ThrowingResult& r, Results::Optimised& o) {
  o.nlopt.ran = r.nlopt_ran;
  if (r.nlopt_ran) {
    // assigned, not emplace()d: clang 14 (the sanitizer build) takes std::optional's
    // emplace() of a nested struct with member initialisers as not default-constructible
    o.nlopt.run = Results::NloptRun{};
    Results::NloptRun& nl = *o.nlopt.run;
    nl.history_J = r.nlopt_run.history;
    nl.algorithm =
        "NLopt LD_SLSQP, central-difference gradients, same parameterisation and constraints";
    nl.return_code = r.nlopt_run.return_code;
    nl.converged = r.nlopt_run.converged;
    nl.feasible = r.nlopt_run.feasible;
    nl.last_gain = r.nlopt_run.last_gain;
    nl.iterations = r.nlopt_run.iterations;
    nl.simulations = r.nlopt_run.simulations;
    nl.run_time_s = r.nlopt_run.run_time;
    nl.max_evaluations = spec.nlopt.max_evaluations;
    nl.max_time_s = spec.nlopt.max_time;
    nl.ftol_rel = spec.nlopt.ftol_rel;
    nl.xtol_rel = spec.nlopt.xtol_rel;
    nl.motion = motion_of(spec, r.nlopt);
    nl.first_order = Results::FirstOrder{r.nlopt_run.kkt_residual, spec.nlopt.kkt_tolerance,
                                         r.nlopt_run.active_constraints, r.nlopt_run.binding};
    auto& starts = nl.starts.emplace();
    for (const auto& sr : r.slsqp_starts)
      starts.push_back({sr.name, sr.run.evaluation.energy, sr.run.feasible && sr.check.feasible,
                        sr.run.converged && sr.check.feasible, sr.run.kkt_residual,
                        sr.run.iterations, sr.run.restarts, sr.run.return_code});
    nl.best_start = r.slsqp_starts[r.slsqp_best_start].name;
  }
}

// the answer's control grids: every grid and the verdict
void set_control_grids(const st::ThrowingSpec& spec, const st::ThrowingResult& r,
                       Results::Optimised& o) {
  if (!r.nlopt_ran || r.grids.empty()) return;
  o.control_grids = Results::ControlGrids{};  // not emplace(): clang 14, as above
  Results::ControlGrids& cg = *o.control_grids;
  cg.status = r.grids.size() < 2 ? "not_refined" : r.grid_converged ? "converged" : "not_converged";
  cg.tolerance = spec.grid.tolerance;
  cg.refinements = spec.grid.refinements;
  for (const auto& g : r.grids)
    cg.grids.push_back({g.stages, g.steps_per_stage, g.energy, g.feasible, g.converged,
                        g.kkt_residual, g.from, g.run_time, g.simulations});
  cg.change_per_doubling_J = r.grid_change;
  cg.error_J = r.grid_error;
  cg.extrapolated_J = r.grid_extrapolated;
  cg.energy_first_grid_J = r.first_grid.evaluation.energy;
}

// one table of the optimisers on equal terms, and the finer re-simulation's verdicts
void set_comparison(const st::ThrowingSpec& spec, const st::ThrowingResult& r, long evaluations,
                    Results::Optimised& o) {
  // one table of the optimisers on equal terms (margins from the finer re-simulation)
  auto row = [&](const std::string& name, const st::ThrowMotion& m, const st::Verification& v,
                 bool conv, long sims, double time, std::vector<std::string> binding) {
    std::sort(binding.begin(), binding.end());
    return Results::Comparison{name,
                               m.evaluation.energy,
                               m.split.mechanical,
                               m.split.copper,
                               m.split.friction,
                               conv,
                               sims,
                               time,
                               v.feasible,
                               margins_of(spec, v.evaluation),
                               binding,
                               binding_rating(v.worst, spec.backoff)};
  };
  o.comparison.push_back(row("IDP (best of " + std::to_string(r.idp_seeds.size()) + " seeds)" +
                                 (r.idp_converged ? "" : ", a stall"),
                             r.idp, r.idp_check, r.idp_converged, evaluations, r.idp_time,
                             r.idp_optimality.binding));
  const bool grids = r.nlopt_ran && r.grids.size() >= 2;
  if (r.nlopt_ran) {
    long sims = slsqp_simulations(r);
    double time = r.nlopt_run.run_time;
    if (grids) {
      time = 0;
      for (const auto& g : r.grids) time += g.run_time;
      for (size_t k = 1; k < r.grids.size(); ++k) sims += r.grids[k].simulations;
    }
    o.comparison.push_back(
        row("SLSQP" +
                (grids ? " on " + std::to_string(r.nlopt.profile.stages()) + " stages (the answer)"
                       : std::string()) +
                " (best of " + std::to_string(r.slsqp_starts.size()) + " starts)",
            r.nlopt, r.nlopt_check, r.nlopt_run.converged, sims, time, r.nlopt_run.binding));
  }
  // SLSQP's answer on the first grid, IDP's stages: IDP's gap on its own grid
  if (grids) {
    const auto& b = r.slsqp_starts[r.slsqp_best_start];
    o.comparison.push_back(
        row("SLSQP on " + std::to_string(r.grids.front().stages) + " stages (IDP's grid)",
            r.first_grid, r.first_grid_check, b.run.converged, slsqp_simulations(r),
            r.grids.front().run_time, b.run.binding));
  }
  o.verification.refinement = spec.check_refinement;
  o.verification.idp = {r.idp_check.feasible, margins_of(spec, r.idp_check.evaluation),
                        worst_of(r.idp_check.worst)};
  if (r.nlopt_ran)
    o.verification.nlopt =
        Results::Verified{r.nlopt_check.feasible, margins_of(spec, r.nlopt_check.evaluation),
                          worst_of(r.nlopt_check.worst)};
}

// the release, the ball's flight, the open-loop replay and the integration
void set_flight_and_replay(const st::ThrowingSpec& spec, const st::ThrowingResult& r,
                           Results::Optimised& o) {
  o.release = {spec.tf, arr(r.flight.release_position), arr(r.flight.release_velocity)};
  Results::Flight& fl = o.flight;
  for (size_t k = 0; k < r.flight.path.size(); ++k) {
    fl.path_xy_m.push_back(arr(r.flight.path[k]));
    fl.t_s.push_back(r.flight.path_t[k]);
  }
  fl.reaches = r.flight.reaches;
  fl.landing_height_m = spec.landing_height;
  fl.duration_s = r.flight.duration;
  fl.landing_xy_m = arr(r.flight.landing);
  fl.apex_m = r.flight.apex;
  for (size_t k = 0; k < r.replay_t.size(); ++k) {
    o.replay.t_s.push_back(r.replay_t[k]);
    o.replay.q_rad.push_back(arr(r.replay_q[k]));
  }
  o.replay.max_error_rad = r.replay_error;
  o.replay.tolerance_rad = spec.replay_tolerance;
  o.replay.integrator =
      "DOPRI5 rtol 1e-10 atol 1e-12, all joints free; voltages of the plan simulated "
      "with 16x the RK4 steps, linear between its samples within a stage; "
      "error against that plan; coulomb sign smoothed by tanh(qd / 1e-4 rad/s)";
  // the answer's grid (the finest of the control grids when SLSQP answers)
  const bool fine = r.answer == "slsqp" && r.answer_steps_per_stage > 0;
  const int steps = fine ? r.answer_steps_per_stage : spec.steps_per_stage;
  const int stages = fine ? r.nlopt.profile.stages() : spec.stages;
  o.integration = {"classical RK4, fixed step, steps aligned with the stages",
                   steps,
                   spec.tf / stages / steps,
                   16,
                   r.rk4_energy_error,
                   r.rk4_theta3_error};
}

class ThrowingRun final : public TypedStudyRun<st::ThrowingSpec, st::ThrowingResult, Results> {
 public:
  using TypedStudyRun::TypedStudyRun;

  st::Status solve(const st::ProgressFn& progress) override {
    result_ = warm_ ? st::solve_throwing_warm(spec_, *warm_) : st::solve_throwing(spec_, progress);
    offered_before_ = spec_.offered_starts.size();
    return result_.status;
  }

  // a step's answer that meets this case's limits for less: SLSQP starts from it next solve()
  bool offer_start(const StudyRun& step, const std::string& from) override {
    const auto* s = dynamic_cast<const ThrowingRun*>(&step);
    const auto& r = result_;
    if (!s || warm_ || r.status != st::Status::kSolved || r.answer != "slsqp" ||
        s->result_.status != st::Status::kSolved || s->result_.answer != "slsqp")
      return false;
    const st::JudgedThrow j = st::judge_throw(spec_, s->result_.nlopt.profile);
    const double answer = r.nlopt.evaluation.energy;
    // within the limits as the optimisers' answers are: the back-off kept (a throw that spends
    // it is cheaper for that alone) and feasible in the re-check
    if (!j.finite || !j.feasible || !j.keeps_backoff ||
        !(j.energy < answer - kOfferMargin * std::abs(answer)))
      return false;
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os << from << ": " << std::fixed << std::setprecision(6) << j.energy
       << " J within this case's limits";
    spec_.offered_starts.push_back({os.str(), s->result_.nlopt.profile});
    return true;
  }
  // the starts kept since the last solve() (those before it were its starts)
  std::string offered() const override {
    std::string t;
    for (size_t i = offered_before_; i < spec_.offered_starts.size(); ++i)
      t += (t.empty() ? "" : "; ") + spec_.offered_starts[i].name;
    return t;
  }

  // a sensitivity step: SLSQP from the nominal answer alone (studies/throwing/warm_solve.hpp)
  bool warm_start(const StudyRun& nominal) override {
    const auto* n = dynamic_cast<const ThrowingRun*>(&nominal);
    if (!n || n->result_.status != st::Status::kSolved) return false;
    const auto& r = n->result_;
    const st::VelocityProfile& p = r.answer == "slsqp" ? r.nlopt.profile : r.idp.profile;
    warm_ = p;
    return true;
  }
  bool warm_started() const override { return warm_.has_value(); }
  // the kinds of the answer's active constraints with a positive multiplier
  std::vector<std::string> binding() const override {
    const auto& r = result_;
    std::vector<std::string> b =
        r.answer == "slsqp" ? r.nlopt_run.binding : r.idp_optimality.binding;
    std::sort(b.begin(), b.end());
    b.erase(std::unique(b.begin(), b.end()), b.end());
    return b;
  }

  std::vector<st::Check> checks() const override { return throwing_checks(spec_, result_); }

  std::vector<KeyFigure> key_figures() const override {
    const auto& r = result_;
    const bool slsqp = r.answer == "slsqp";
    std::vector<KeyFigure> k = {
        {"energy_J", slsqp ? r.nlopt.evaluation.energy : r.idp.evaluation.energy, "J",
         "energy of the answer (the lowest converged, re-checked throw)"},
        {"saving_percent", r.saving_percent, "%", "the answer's saving against the eq. 8 start"},
        {"energy_eq8_J", r.initial.evaluation.energy, "J", "energy of the eq. 8 start"},
        {"energy_idp_J", r.idp.evaluation.energy, "J", "energy of the IDP optimum"},
        {"replay_error_rad", r.replay_error, "rad", "largest open-loop replay error"},
    };
    if (!r.idp_seeds.empty()) {
      double lo = INFINITY, hi = -INFINITY;
      for (const auto& sd : r.idp_seeds) {
        lo = std::min(lo, sd.evaluation.energy);
        hi = std::max(hi, sd.evaluation.energy);
      }
      k.push_back({"idp_seed_spread_J", hi - lo, "J", "spread of the IDP seeds"});
    }
    if (r.nlopt_ran)
      k.push_back(
          {"energy_slsqp_J", r.nlopt.evaluation.energy, "J", "energy of the SLSQP optimum"});
    if (r.nlopt_ran && r.grids.size() >= 2) {
      k.push_back({"energy_first_grid_J", r.first_grid.evaluation.energy, "J",
                   "SLSQP's answer on the first control grid (IDP's stages)"});
      if (r.grid_converged)  // not estimated while the energy still falls (NaN)
        k.push_back({"grid_error_J", r.grid_error, "J",
                     "estimated error of the answer's energy from the control grids"});
    }
    if (r.flight.reaches)
      k.push_back({"landing_x_m", r.flight.landing.x(), "m", "landing point x of the answer"});
    return k;
  }

  Results study_results() const override {
    const auto& r = result_;
    Results j;
    set_parameters(spec_, j);
    set_assumptions(spec_, j);
    j.energy_initial_J = r.initial.evaluation.energy;
    j.energy_reference_J = r.reference.evaluation.energy;
    j.energy_optimised_J =
        r.answer == "slsqp" ? r.nlopt.evaluation.energy : r.idp.evaluation.energy;
    j.saving_percent = r.saving_percent;
    if (r.idp.series.t.empty()) return j;
    j.run = Results::Optimised{};  // not emplace(): clang 14, as above
    Results::Optimised& o = *j.run;
    o.answer = r.answer;
    set_reference(spec_, r, o);
    o.initial = motion_of(spec_, r.initial);
    if (r.reference_kind == "repaired") o.reference_motion = motion_of(spec_, r.reference);
    o.optimum = motion_of(spec_, r.idp);
    const long evaluations = set_idp(spec_, r, o);
    set_nlopt(spec_, r, o);
    set_control_grids(spec_, r, o);
    set_comparison(spec_, r, evaluations, o);
    set_flight_and_replay(spec_, r, o);
    o.run_time_s = r.run_time;
    return j;
  }

  // model.xml (the IDP motion's scene, keyframes at its strip's times) and one CSV per motion
  std::vector<report::ExportRecord> write_exports(const std::filesystem::path& dir,
                                                  const cases::CaseInfo& info) override {
    std::vector<report::ExportRecord> out;
    if (result_.status != st::Status::kSolved || result_.idp.series.t.size() < 2) return out;
    const scene::ArmScene sc = scene::throwing_scene(spec_, result_, info.render);
    const auto keys =
        scene::strip_keyframes(scene::throwing_motion(result_.idp.series), info.render.frames);
    const std::string motion = "the IDP optimum (throwing_idp_strip.png)";
    out.push_back(model_export_entry(
        scene::write_model_xml(dir, sc.chain, sc.mjcf, keys, motion, info.path), motion, keys));
    const auto csv = [&](const st::ThrowMotion& tm, const std::string& name,
                         const std::string& what) {
      const st::ThrowSeries& s = tm.series;
      if (s.t.size() < 2) return;
      const size_t n = s.t.size();
      report::MotionCsv t;
      t.file = "motion_" + name + ".csv";
      t.what =
          what +
          ": time, the four joint angles, rates and accelerations, the two motors' torques, "
          "voltages, currents and electrical powers, the energy consumed so far, the ball's centre "
          "and the tray's normal and tangential force on it (a stage boundary appears twice, once "
          "per stage)";
      t.add("t", "s", s.t);
      t.add_joints("q", "rad", s.q);
      t.add_joints("qd", "rad/s", s.qd);
      if (s.qdd.size() == n) t.add_joints("qdd", "rad/s^2", s.qdd);
      const auto motors = [&](const std::vector<Eigen::Vector2d>& v, const std::string& col,
                              const std::string& unit) {
        if (v.size() == n) t.add_joints(col, unit, v);
      };
      motors(s.tau_m, "motor_torque", "N m");
      motors(s.voltage, "voltage", "V");
      motors(s.current, "current", "A");
      motors(s.power, "power", "W");
      if (s.energy.size() == n) t.add("energy", "J", s.energy);
      if (s.ball.size() == n) {
        t.add_joints("ball_", "m", s.ball);
        t.columns[t.columns.size() - 2].name = "ball_x";
        t.columns[t.columns.size() - 1].name = "ball_y";
      }
      if (s.normal_force.size() == n) t.add("normal_force", "N", s.normal_force);
      if (s.tangential_force.size() == n) t.add("tangential_force", "N", s.tangential_force);
      report::write_motion_csv(dir, t);
      out.push_back(csv_export_entry(t, name));
    };
    csv(result_.idp, "idp", "the IDP optimum (iterative dynamic programming, the best seed)");
    csv(result_.reference, "reference",
        "the feasible reference motion the saving is measured from");
    csv(result_.initial, "initial", "the initial motion (eq. 8 profile, raw)");
    if (result_.nlopt_ran) csv(result_.nlopt, "nlopt", "SLSQP's answer (its final point)");
    return out;
  }

  // frames: the IDP optimum's strip and locus (Fig. 7) and the flight (src/scene)
  scene::Rendered render(const std::filesystem::path& dir, const cases::CaseInfo& info) override {
    return scene::render_throwing_frames(spec_, result_, info.render, dir);
  }

 private:
  std::optional<st::VelocityProfile> warm_;  ///< a sensitivity step's start (warm_start)
  size_t offered_before_ = 0;                ///< spec_.offered_starts at the last solve()
};

}  // namespace

// (over 60 lines, kept whole: one check a block, in the order the report lists them)
std::vector<st::Check> throwing_checks(const st::ThrowingSpec& sp, const st::ThrowingResult& r) {
  if (r.idp.series.t.empty()) return {};
  std::vector<st::Check> c;
  const std::string fine = std::to_string(sp.check_refinement) + "x the steps";
  // every reported optimum, re-simulated with finer steps, against every constraint
  auto verify = [&](const std::string& who, const std::string& label, const st::Verification& v) {
    const auto& e = v.evaluation;
    c.push_back(st::make_check(who + "_contact",
                               label + " at " + fine +
                                   ": contact margin minus the "
                                   "smallest normal force of the tray on the ball (N)",
                               sp.contact_margin - e.min_normal_force, 0.0));
    c.push_back(st::make_check(who + "_friction",
                               label + " at " + fine +
                                   ": largest friction "
                                   "needed to roll, |F_t| / N, against the friction coefficient",
                               e.max_friction_ratio, sp.friction_coefficient));
    c.push_back(st::make_check(who + "_ball_in_tray",
                               label + " at " + fine +
                                   ": largest |theta4| "
                                   "(rad) against lambda/2",
                               e.max_abs_theta4, sp.tray_width / 2));
    c.push_back(st::make_check(who + "_voltage",
                               label + " at " + fine +
                                   ": largest |motor "
                                   "voltage| (V)",
                               e.max_voltage, sp.voltage_max));
    c.push_back(st::make_check(who + "_current",
                               label + " at " + fine +
                                   ": largest |motor "
                                   "current| (A)",
                               e.max_current, sp.current_max));
    c.push_back(st::make_check(who + "_power",
                               label + " at " + fine +
                                   ": largest |motor power "
                                   "e i| (W)",
                               e.max_power, sp.power_max));
    c.push_back(st::make_check(who + "_release_theta3",
                               label + " at " + fine +
                                   ": |theta3(tf) - "
                                   "release theta3| (rad)",
                               v.release_error, sp.release_tolerance));
  };
  auto converged = [&](const std::string& who, const std::string& what, bool ok) {
    c.push_back(
        st::make_check(who + "_converged",
                       what +
                           (sp.allow_not_converged ? " (the case allows a run that "
                                                     "is not converged: checks.allow_not_converged)"
                                                   : "") +
                           ": 0 converged, 1 not",
                       ok ? 0.0 : 1.0, sp.allow_not_converged ? 1.0 : 0.0));
  };
  // the answer's checks decide the case; IDP, when it is only the comparison, is not
  // checked here: its re-check margins are in the comparison table and the answer's
  // sentence says when its throw breaks a limit or stalls
  const bool idp_answer = r.answer == "idp";
  const std::string kkt_words =
      "first-order residual |grad E + sum lambda grad g| / E per rad/s "
      "at most " +
      short_number(sp.nlopt.kkt_tolerance) + " (KKT, active constraints)";
  if (idp_answer) verify("idp", "IDP optimum (the answer)", r.idp_check);
  if (idp_answer)
    converged("idp",
              "IDP stopped on its tolerance (relative gain of a pass < " +
                  std::to_string(sp.idp.tolerance) + ", " + std::to_string(sp.idp.quiet_passes) +
                  " passes in a row) before its budget and its optimum's " + kkt_words,
              r.idp_converged);
  if (r.nlopt_ran) {
    verify("slsqp", "SLSQP optimum (the answer)", r.nlopt_check);
    converged("slsqp", "SLSQP's answer is feasible and its " + kkt_words, r.nlopt_run.converged);
  }
  // the control grid: 0 converged, 1 still falling (a failure only when the case
  // requires a converged sequence; the answer's sentence says "not converged" either way)
  if (r.nlopt_ran && r.answer == "slsqp" && r.grids.size() >= 2)
    c.push_back(st::make_check(
        "control_grid_converged",
        "the control grid: the last doubling of the stages (" +
            std::to_string(r.grids[r.grids.size() - 2].stages) + " -> " +
            std::to_string(r.grids.back().stages) + ") changed the energy by " +
            short_number(std::abs(r.grid_change)) + " J, at most " +
            short_number(sp.grid.tolerance) + " of it (throwing.grid.tolerance)" +
            (sp.grid.require_converged ? ""
                                       : " (the case allows a sequence still falling: "
                                         "throwing.grid.require_converged false)") +
            ": 0 converged, 1 not",
        r.grid_converged ? 0.0 : 1.0, sp.grid.require_converged ? 0.0 : 1.0));
  c.push_back(st::make_check("open_loop_replay",
                             "the optimum's voltages applied open loop to the core model (all "
                             "joints free, DOPRI5) reproduce the planned angles (16x-step plan): "
                             "max error (rad)",
                             r.replay_error, sp.replay_tolerance));
  c.push_back(st::make_check("rk4_accuracy",
                             "relative energy change of the optimum with 16x the RK4 steps",
                             r.rk4_energy_error, 1e-3));
  return c;
}

StudyParts throwing_parts() {
  return study_parts<ThrowingRun>(
      "tray arm with a passive joint: energy-saving throw by IDP and SLSQP (Sato et al. Sec. 4)",
      &report::throwing_sections, &report::throwing_answer);
}

}  // namespace armstudy::app
