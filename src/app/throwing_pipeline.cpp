// The throwing study in the pipeline: case -> studies::solve_throwing -> results.json.
//
// results.json "throwing" section (SI; keys ending in _deg are degrees):
//   parameters {gravity_m_s2, link1/link2 {length_m, mass_kg, com_m, inertia_kg_m2},
//               tray {circle_offset_m, mass_kg, com_m, com_lateral_m, inertia_kg_m2,
//               width_deg}, ball {mass_kg, circle_radius_m, radius_m, inertia_kg_m2},
//               motors {kt_Nm_per_A, kv_V_s_per_rad, resistance_ohm, viscous_Nm_s_per_rad,
//               coulomb_Nm, rotor_inertia_kg_m2, motor2, count_regeneration},
//               task {start_deg [4], release_deg [3], release_rate_rad_s [2], duration_s,
//               landing_height_m}, choices [sentences]},
//   assumptions [{name, value, unit, key}]: what the paper leaves open, with the values used,
//   limits {voltage_max_V, current_max_A, power_max_W, theta4_limit_rad [-lambda/2, lambda/2],
//           contact_margin_N, friction_coefficient, release_tolerance_rad, backoff},
//   energy_initial_J (raw eq. 8), energy_reference_J, energy_optimised_J (IDP), saving_percent
//   (against the reference),
//   reference {kind ("eq8" | "repaired" | "none"), initial_feasible, raw_breaks [{constraint,
//       worst_normalised, margin, unit}], repair {return_code, converged, iterations,
//       simulations, run_time_s, max_rate_change_rad_s}},
//   initial, reference_motion (when repaired), optimum, nlopt.motion: motions {energy_J,
//       max_abs_theta4_rad, max_voltage_V, max_current_A, max_power_W, min_normal_force_N,
//       max_friction_ratio, feasible, worst_normalised {constraint: g}, margins {..},
//       release_error {angle_rad [th1, th2, th3], rate_rad_s [th1', th2']},
//       energy_split {electrical_J, mechanical_J, copper_J, friction_J, rest_J},
//       profile {t_s, rate_rad_s [[j1, j2] per node]},
//       series {t_s, stage, q_rad [[th1..th4]], qd_rad_s, torque_Nm [[m1, m2]], voltage_V,
//       current_A, power_W, energy_J, ball_xy_m, normal_force_N, tangential_force_N,
//       friction_needed}} (two samples share each stage boundary; every RK4 step start),
//   idp {stages, steps_per_stage, iterations, max_passes, tolerance, candidates, shrink,
//        restore, region_rad_s, seed, seeds, backoff, threads, converged, best_seed,
//        run_time_s, evaluations, passes, last_gain,
//        seed_runs [{seed, energy_J, feasible, converged, passes, last_gain, evaluations,
//        run_time_s}], spread {best_J, median_J, worst_J},
//        convergence [{iteration, pass, energy_J, violation, region_rad_s, evaluations,
//        improvements}] (best seed)},
//   nlopt {ran, algorithm, return_code, converged, feasible, last_gain, iterations,
//          simulations, run_time_s, max_evaluations, max_time_s, ftol_rel, xtol_rel,
//          history_J, motion},
//   comparison [{optimiser, energy_J, mechanical_J, copper_J, friction_J, converged,
//       simulations, run_time_s, margins {contact_N, friction, tray_rad, release_rad,
//       voltage_V, current_A, power_W}, binding [names], binding_rating}] (margins from the
//       re-simulation with `refinement` x the steps; > 0 met),
//   verification {refinement, idp, nlopt: {feasible, margins, worst_normalised}},
//   release {time_s, ball_xy_m, ball_velocity_m_s},
//   flight {reaches, landing_height_m, duration_s, landing_xy_m, apex_m, t_s, path_xy_m},
//   replay {max_error_rad, tolerance_rad, integrator, t_s, q_rad},
//   integration {method, steps_per_stage, step_s, fine_steps_factor (16),
//                energy_error_vs_fine_steps, theta3_error_vs_fine_steps_rad},
//   run_time_s.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cases/throwing_case.hpp"
#include "app/json_numbers.hpp"
#include "app/pipeline.hpp"
#include "report/case_report.hpp"
#include "scene/throwing_frames.hpp"

namespace armstudy::app {
namespace {
using nlohmann::json;
namespace st = studies;
constexpr double kDeg = core::kPi / 180.0;

json num(double v) { return json_number(v); }
template <typename V>
json arr(const V& v) {
  json a = json::array();
  for (int i = 0; i < v.size(); ++i) a.push_back(num(v[i]));
  return a;
}

const char* kKeys[st::kConstraintKinds] = {"contact", "friction", "tray", "voltage",
                                           "current", "power", "release"};

// margins (> 0 met) in physical units of an evaluation
json margins_json(const st::ThrowingSpec& sp, const st::ProfileEvaluation& e) {
  return {{"contact_N", num(e.min_normal_force - sp.contact_margin)},
          {"friction", num(sp.friction_coefficient - e.max_friction_ratio)},
          {"tray_rad", num(sp.tray_width / 2 - e.max_abs_theta4)},
          {"release_rad", num(sp.release_tolerance - std::abs(e.theta3_final - sp.theta3_release))},
          {"voltage_V", num(sp.voltage_max - e.max_voltage)},
          {"current_A", num(sp.current_max - e.max_current)},
          {"power_W", num(sp.power_max - e.max_power)}};
}

json worst_json(const std::array<double, st::kConstraintKinds>& w) {
  json j;
  for (int c = 0; c < st::kConstraintKinds; ++c) j[kKeys[c]] = num(w[c]);
  return j;
}

// constraints within twice the back-off of their limit: the ones that bound the optimum
json binding_json(const std::array<double, st::kConstraintKinds>& w, double backoff) {
  json b = json::array();
  for (int c = 0; c < st::kConstraintKinds; ++c)
    if (w[c] >= -2 * backoff - 1e-9) b.push_back(st::constraint_name(static_cast<st::ConstraintKind>(c)));
  return b;
}

// the motor rating nearest its limit, "(not binding)" when it is not within twice the back-off
std::string binding_rating(const std::array<double, st::kConstraintKinds>& w, double backoff) {
  int best = static_cast<int>(st::ConstraintKind::kVoltage);
  for (int c : {static_cast<int>(st::ConstraintKind::kCurrent), static_cast<int>(st::ConstraintKind::kPower)})
    if (w[c] > w[best]) best = c;
  return std::string(st::constraint_name(static_cast<st::ConstraintKind>(best))) +
         (w[best] >= -2 * backoff - 1e-9 ? "" : " (nearest; not binding)");
}

json motion_json(const st::ThrowingSpec& sp, const st::ThrowMotion& m) {
  const auto& e = m.evaluation;
  json j;
  j["energy_J"] = num(e.energy);
  j["max_abs_theta4_rad"] = num(e.max_abs_theta4);
  j["max_voltage_V"] = num(e.max_voltage);
  j["max_current_A"] = num(e.max_current);
  j["max_power_W"] = num(e.max_power);
  j["min_normal_force_N"] = num(e.min_normal_force);
  j["max_friction_ratio"] = num(e.max_friction_ratio);
  j["feasible"] = e.feasible;
  j["worst_normalised"] = worst_json(m.worst);
  j["margins"] = margins_json(sp, e);
  j["release_error"] = {{"angle_rad", arr(m.angle_error)}, {"rate_rad_s", arr(m.rate_error)}};
  j["energy_split"] = {{"electrical_J", num(m.split.electrical)},
                       {"mechanical_J", num(m.split.mechanical)},
                       {"copper_J", num(m.split.copper)},
                       {"friction_J", num(m.split.friction)},
                       {"rest_J", num(m.split.rest)}};
  json pt = json::array(), pr = json::array();
  for (int k = 0; k <= m.profile.stages(); ++k) {
    pt.push_back(num(k * m.profile.stage_length()));
    pr.push_back(arr(Eigen::Vector2d(m.profile.v.col(k))));
  }
  j["profile"] = {{"t_s", pt}, {"rate_rad_s", pr}};
  const auto& s = m.series;
  json t = json::array(), stage = json::array(), q = json::array(), qd = json::array(),
       tau = json::array(), v = json::array(), i = json::array(), p = json::array(),
       en = json::array(), ball = json::array(), nf = json::array(), tf = json::array(),
       fr = json::array();
  for (size_t k = 0; k < s.t.size(); ++k) {
    t.push_back(num(s.t[k]));
    q.push_back(arr(s.q[k]));
    qd.push_back(arr(s.qd[k]));
    tau.push_back(arr(s.tau_m[k]));
    v.push_back(arr(s.voltage[k]));
    i.push_back(arr(s.current[k]));
    p.push_back(arr(s.power[k]));
    en.push_back(num(s.energy[k]));
    ball.push_back(arr(s.ball[k]));
    nf.push_back(num(s.normal_force[k]));
    tf.push_back(num(s.tangential_force[k]));
    // friction needed to roll, |F_t| / N (null where the tray does not push the ball)
    fr.push_back(s.normal_force[k] > 0 ? num(std::abs(s.tangential_force[k]) / s.normal_force[k])
                                       : json(nullptr));
  }
  // the stage of each sample: the end sample of a stage repeats its time
  int stg = 0;
  for (size_t k = 0; k < s.t.size(); ++k) {
    stage.push_back(stg);
    if (k + 1 < s.t.size() && s.t[k + 1] == s.t[k]) ++stg;
  }
  j["series"] = {{"t_s", t}, {"stage", stage}, {"q_rad", q}, {"qd_rad_s", qd},
                 {"torque_Nm", tau}, {"voltage_V", v}, {"current_A", i}, {"power_W", p},
                 {"energy_J", en}, {"ball_xy_m", ball}, {"normal_force_N", nf},
                 {"tangential_force_N", tf}, {"friction_needed", fr}};
  return j;
}

class ThrowingRun final : public StudyRun {
 public:
  explicit ThrowingRun(st::ThrowingSpec spec) : spec_(std::move(spec)) {}

  st::Status solve(const st::ProgressFn& progress) override {
    result_ = st::solve_throwing(spec_, progress);
    return result_.status;
  }
  std::string message() const override { return result_.message; }

  std::vector<st::Check> checks() const override {
    const auto& r = result_;
    const auto& sp = spec_;
    if (r.idp.series.t.empty()) return {};
    std::vector<st::Check> c;
    const std::string fine = std::to_string(sp.check_refinement) + "x the steps";
    // every reported optimum, re-simulated with finer steps, against every constraint
    auto verify = [&](const std::string& who, const std::string& label, const st::Verification& v) {
      const auto& e = v.evaluation;
      c.push_back(st::make_check(who + "_contact", label + " at " + fine + ": contact margin minus the "
                                 "smallest normal force of the tray on the ball (N)",
                                 sp.contact_margin - e.min_normal_force, 0.0));
      c.push_back(st::make_check(who + "_friction", label + " at " + fine + ": largest friction "
                                 "needed to roll, |F_t| / N, against the friction coefficient",
                                 e.max_friction_ratio, sp.friction_coefficient));
      c.push_back(st::make_check(who + "_ball_in_tray", label + " at " + fine + ": largest |theta4| "
                                 "(rad) against lambda/2", e.max_abs_theta4, sp.tray_width / 2));
      c.push_back(st::make_check(who + "_voltage", label + " at " + fine + ": largest |motor "
                                 "voltage| (V)", e.max_voltage, sp.voltage_max));
      c.push_back(st::make_check(who + "_current", label + " at " + fine + ": largest |motor "
                                 "current| (A)", e.max_current, sp.current_max));
      c.push_back(st::make_check(who + "_power", label + " at " + fine + ": largest |motor power "
                                 "e i| (W)", e.max_power, sp.power_max));
      c.push_back(st::make_check(who + "_release_theta3", label + " at " + fine + ": |theta3(tf) - "
                                 "release theta3| (rad)", v.release_error, sp.release_tolerance));
    };
    auto converged = [&](const std::string& who, const std::string& what, bool ok) {
      c.push_back(st::make_check(who + "_converged",
                                 what + (sp.allow_not_converged ? " (the case allows a run that "
                                         "is not converged: checks.allow_not_converged)" : "") +
                                     ": 0 converged, 1 not",
                                 ok ? 0.0 : 1.0, sp.allow_not_converged ? 1.0 : 0.0));
    };
    c.push_back(st::make_check("reference_feasible",
                               "the reference the saving is measured from (" + r.reference_kind +
                               ") meets every constraint: its total violation",
                               r.reference.evaluation.finite ? r.reference.evaluation.violation : INFINITY, 0.0));
    verify("idp", "IDP optimum", r.idp_check);
    converged("idp", "every IDP seed stopped on its tolerance (relative gain of a pass < " +
                         std::to_string(sp.idp.tolerance) + ", " + std::to_string(sp.idp.quiet_passes) +
                         " passes in a row) before its budget", r.idp_converged);
    c.push_back(st::make_check("idp_energy_below_reference",
                               "IDP optimum's energy (J) below the reference's",
                               r.idp.evaluation.energy, r.reference.evaluation.energy * (1 + 1e-12)));
    if (r.nlopt_ran) {
      verify("slsqp", "SLSQP optimum", r.nlopt_check);
      converged("slsqp", "SLSQP stopped on ftol_rel/xtol_rel at a feasible point before its budget",
                r.nlopt_run.converged);
    }
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

  std::vector<KeyFigure> key_figures() const override {
    const auto& r = result_;
    std::vector<KeyFigure> k = {
        {"energy_eq8_J", r.initial.evaluation.energy, "J", "energy of the eq. 8 start"},
        {"energy_reference_J", r.reference.evaluation.energy, "J", "energy of the feasible reference"},
        {"energy_idp_J", r.idp.evaluation.energy, "J", "energy of the IDP optimum"},
        {"saving_percent", r.saving_percent, "%", "IDP saving against the reference"},
        {"idp_run_time_s", r.idp_time, "s", "IDP run time"},
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
    if (r.nlopt_ran) k.push_back({"energy_slsqp_J", r.nlopt.evaluation.energy, "J", "energy of the SLSQP optimum"});
    if (r.flight.reaches) k.push_back({"landing_x_m", r.flight.landing.x(), "m", "landing point x"});
    return k;
  }

  // the study report: one call, everything else is src/report's
  void report(const std::filesystem::path& dir, const cases::CaseInfo& info,
              const nlohmann::json& results_json) override {
    report::write_case_report(dir, info, results_json);
  }
  json results() const override {
    const auto& a = spec_.arm;
    const auto& r = result_;
    json j;
    auto link = [](double l, double m, double c, double I) {
      return json{{"length_m", l}, {"mass_kg", m}, {"com_m", c}, {"inertia_kg_m2", I}};
    };
    j["parameters"] = {
        {"gravity_m_s2", a.gravity},
        {"link1", link(a.l1, a.m1, a.r1, a.I1)},
        {"link2", link(a.l2, a.m2, a.r2, a.I2)},
        {"tray", {{"circle_offset_m", a.circle_offset}, {"mass_kg", a.m3}, {"com_m", a.r3},
                  {"com_lateral_m", a.r3_lateral}, {"inertia_kg_m2", a.I3},
                  {"width_deg", spec_.tray_width / kDeg}}},
        {"ball", {{"mass_kg", a.m4}, {"circle_radius_m", a.r4}, {"radius_m", a.rb},
                  {"inertia_kg_m2", a.Ib}}},
        {"motors", {{"kt_Nm_per_A", spec_.motor.kt}, {"kv_V_s_per_rad", spec_.motor.kv},
                    {"resistance_ohm", spec_.motor.Ra}, {"viscous_Nm_s_per_rad", spec_.motor.Dm},
                    {"coulomb_Nm", spec_.motor.tau_f}, {"rotor_inertia_kg_m2", a.rotor_inertia},
                    {"motor2", a.motor2 == st::Motor2Mount::kOnBase ? "on_base" : "on_link1"},
                    {"count_regeneration", spec_.count_regeneration}}},
        {"task", {{"start_deg", {spec_.start[0] / kDeg, spec_.start[1] / kDeg,
                                 spec_.theta3_start / kDeg, spec_.theta4_start / kDeg}},
                  {"release_deg", {spec_.release[0] / kDeg, spec_.release[1] / kDeg,
                                   spec_.theta3_release / kDeg}},
                  {"release_rate_rad_s", {spec_.release_rate[0], spec_.release_rate[1]}},
                  {"duration_s", spec_.tf},
                  {"landing_height_m", spec_.landing_height}}},
        {"choices",
         {"model derived from first principles (docs/derivations/throwing.md): ball spin = "
          "tray rate - (r4/r_b) "
          "theta4'; eq. 3's spin term and a5 as printed are wrong",
          "the centre of the ball's circle lies at the tray's circle offset from its hinge (Table 1's l3 "
          "by default)",
          "ball inertia 2/5 m r_b^2 unless given (equals Table 1's 4.8e-7 kg m^2)",
          "motor 2 drives theta2 (on_link1, eq. 5 as printed) unless motor2: on_base",
          "rotor inertia (missing from Table 1) as the case's motors give it",
          "tray width lambda (eq. 9) and the current limit as the case gives them",
          "energy = eq. 7 (signed e i: regeneration counted) unless the case counts only e i > 0",
          "theta3 at release is a constraint (within the release tolerance), reached through the "
          "passive dynamics"}}};
    j["assumptions"] = json::array({
        {{"name", "tray's angular width lambda (eq. 9): the ball stays within +-lambda/2"},
         {"value", spec_.tray_width / kDeg}, {"unit", "deg"}, {"key", "tray.width_deg"}},
        {{"name", "friction coefficient between ball and tray (rolling needs |F_t| <= mu N)"},
         {"value", spec_.friction_coefficient}, {"unit", ""}, {"key", "constraints.friction_coefficient"}},
        {{"name", "contact margin: the tray's normal force on the ball stays above it"},
         {"value", spec_.contact_margin}, {"unit", "N"}, {"key", "constraints.contact_margin_N"}},
        {{"name", "current limit of each motor (not in Table 1)"},
         {"value", spec_.current_max}, {"unit", "A"}, {"key", "motors.current_max_A"}},
        {{"name", "Table 1's 60 W rating read as a limit on |e i| of each motor"},
         {"value", spec_.power_max}, {"unit", "W"}, {"key", "motors.power_max_W"}},
        {{"name", "Table 1's 24 V rating read as a limit on |e|"},
         {"value", spec_.voltage_max}, {"unit", "V"}, {"key", "motors.voltage_max_V"}},
        {{"name", "release tolerance of the passive tray angle theta3"},
         {"value", spec_.release_tolerance / kDeg}, {"unit", "deg"}, {"key", "constraints.release_tolerance_deg"}},
        {{"name", "constraint back-off of both optimisers (normalised)"},
         {"value", spec_.backoff}, {"unit", ""}, {"key", "constraints.backoff"}},
        {{"name", "rotor inertia of each motor (not in Table 1)"},
         {"value", a.rotor_inertia}, {"unit", "kg m^2"}, {"key", "motors.rotor_inertia_kg_m2"}},
        {{"name", "centre of the ball's circle from the tray hinge"},
         {"value", a.circle_offset}, {"unit", "m"}, {"key", "tray.circle_offset_m"}}});
    j["limits"] = {{"voltage_max_V", spec_.voltage_max}, {"current_max_A", spec_.current_max},
                   {"power_max_W", spec_.power_max},
                   {"theta4_limit_rad", {-spec_.tray_width / 2, spec_.tray_width / 2}},
                   {"contact_margin_N", spec_.contact_margin},
                   {"friction_coefficient", spec_.friction_coefficient},
                   {"release_tolerance_rad", spec_.release_tolerance},
                   {"backoff", spec_.backoff}};
    j["energy_initial_J"] = num(r.initial.evaluation.energy);
    j["energy_reference_J"] = num(r.reference.evaluation.energy);
    j["energy_optimised_J"] = num(r.idp.evaluation.energy);
    j["saving_percent"] = num(r.saving_percent);
    if (r.idp.series.t.empty()) return j;
    {
      json breaks = json::array();
      const json mg = margins_json(spec_, r.initial.evaluation);
      const char* units[st::kConstraintKinds] = {"N", "", "rad", "V", "A", "W", "rad"};
      const char* mkeys[st::kConstraintKinds] = {"contact_N", "friction", "tray_rad", "voltage_V",
                                                 "current_A", "power_W", "release_rad"};
      for (int c = 0; c < st::kConstraintKinds; ++c)
        if (r.initial.worst[c] > 0)
          breaks.push_back({{"constraint", st::constraint_name(static_cast<st::ConstraintKind>(c))},
                            {"worst_normalised", num(r.initial.worst[c])},
                            {"margin", mg[mkeys[c]]}, {"unit", units[c]}});
      json ref = {{"kind", r.reference_kind}, {"initial_feasible", r.initial_feasible},
                  {"raw_breaks", breaks}};
      if (r.reference_kind != "eq8")
        ref["repair"] = {{"method", "SLSQP from eq. 8 descending the squared constraint violation "
                                    "(aimed at twice the back-off inside every limit) until it is 0 "
                                    "or stops on its tolerance; the reference must then meet every "
                                    "constraint with the back-off"},
                         {"return_code", r.repair_run.return_code},
                         {"converged", r.repair_run.converged},
                         {"feasible", r.repair_run.feasible},
                         {"iterations", r.repair_run.iterations},
                         {"simulations", r.repair_run.simulations},
                         {"run_time_s", num(r.repair_run.run_time)},
                         {"max_rate_change_rad_s", num(r.repair_run.rate_change)}};
      j["reference"] = ref;
    }
    j["initial"] = motion_json(spec_, r.initial);
    if (r.reference_kind == "repaired") j["reference_motion"] = motion_json(spec_, r.reference);
    j["optimum"] = motion_json(spec_, r.idp);
    json conv = json::array();
    for (const auto& h : r.idp_run.history)
      conv.push_back({{"iteration", h.iteration}, {"pass", h.pass}, {"energy_J", num(h.energy)},
                      {"violation", num(h.violation)}, {"region_rad_s", arr(h.region)},
                      {"evaluations", h.evaluations}, {"improvements", h.improvements}});
    const auto& is = spec_.idp;
    json seeds = json::array();
    std::vector<double> es;
    long evaluations = 0;
    for (const auto& sd : r.idp_seeds) {
      seeds.push_back({{"seed", sd.seed}, {"energy_J", num(sd.evaluation.energy)},
                       {"feasible", sd.evaluation.feasible}, {"converged", sd.converged},
                       {"passes", sd.passes}, {"last_gain", num(sd.last_gain)},
                       {"evaluations", sd.evaluations}, {"run_time_s", num(sd.run_time)}});
      es.push_back(sd.evaluation.energy);
      evaluations += sd.evaluations;
    }
    std::sort(es.begin(), es.end());
    const double median = es.empty() ? NAN
                          : es.size() % 2 ? es[es.size() / 2]
                                          : 0.5 * (es[es.size() / 2 - 1] + es[es.size() / 2]);
    j["idp"] = {{"stages", spec_.stages}, {"steps_per_stage", spec_.steps_per_stage},
                {"iterations", is.iterations}, {"max_passes", is.max_passes},
                {"tolerance", is.tolerance}, {"quiet_passes", is.quiet_passes},
                {"candidates", is.candidates},
                {"shrink", is.shrink}, {"restore", is.restore}, {"region_rad_s", arr(is.region)},
                {"seed", is.seed}, {"seeds", is.seeds}, {"backoff", spec_.backoff},
                {"threads", r.idp_run.threads}, {"converged", r.idp_converged},
                {"best_seed", r.idp_run.seed}, {"passes", r.idp_run.passes},
                {"last_gain", num(r.idp_run.last_gain)},
                {"evaluations", evaluations}, {"run_time_s", num(r.idp_time)},
                {"seed_runs", seeds},
                {"spread", {{"best_J", num(es.empty() ? NAN : es.front())}, {"median_J", num(median)},
                            {"worst_J", num(es.empty() ? NAN : es.back())}}},
                {"convergence", conv}};
    json nl = {{"ran", r.nlopt_ran}};
    if (r.nlopt_ran) {
      json hist = json::array();
      for (double h : r.nlopt_run.history) hist.push_back(num(h));
      nl["algorithm"] = "NLopt LD_SLSQP, central-difference gradients, same parameterisation and constraints";
      nl["return_code"] = r.nlopt_run.return_code;
      nl["converged"] = r.nlopt_run.converged;
      nl["feasible"] = r.nlopt_run.feasible;
      nl["last_gain"] = num(r.nlopt_run.last_gain);
      nl["iterations"] = r.nlopt_run.iterations;
      nl["simulations"] = r.nlopt_run.simulations;
      nl["run_time_s"] = num(r.nlopt_run.run_time);
      nl["max_evaluations"] = spec_.nlopt.max_evaluations;
      nl["max_time_s"] = spec_.nlopt.max_time;
      nl["ftol_rel"] = spec_.nlopt.ftol_rel;
      nl["xtol_rel"] = spec_.nlopt.xtol_rel;
      nl["history_J"] = hist;
      nl["motion"] = motion_json(spec_, r.nlopt);
    }
    j["nlopt"] = nl;
    // one table of the optimisers on equal terms (margins from the finer re-simulation)
    auto row = [&](const std::string& name, const st::ThrowMotion& m, const st::Verification& v,
                   bool conv, long sims, double time) {
      return json{{"optimiser", name}, {"energy_J", num(m.evaluation.energy)},
                  {"mechanical_J", num(m.split.mechanical)}, {"copper_J", num(m.split.copper)},
                  {"friction_J", num(m.split.friction)}, {"converged", conv},
                  {"simulations", sims}, {"run_time_s", num(time)},
                  {"feasible", v.feasible}, {"margins", margins_json(spec_, v.evaluation)},
                  {"binding", binding_json(v.worst, spec_.backoff)},
                  {"binding_rating", binding_rating(v.worst, spec_.backoff)}};
    };
    json cmp = json::array();
    cmp.push_back(row("IDP (best of " + std::to_string(r.idp_seeds.size()) + " seeds)", r.idp,
                      r.idp_check, r.idp_converged, evaluations, r.idp_time));
    if (r.nlopt_ran)
      cmp.push_back(row("SLSQP", r.nlopt, r.nlopt_check, r.nlopt_run.converged,
                        r.nlopt_run.simulations, r.nlopt_run.run_time));
    j["comparison"] = cmp;
    json ver = {{"refinement", spec_.check_refinement},
                {"idp", {{"feasible", r.idp_check.feasible},
                         {"margins", margins_json(spec_, r.idp_check.evaluation)},
                         {"worst_normalised", worst_json(r.idp_check.worst)}}}};
    if (r.nlopt_ran)
      ver["nlopt"] = {{"feasible", r.nlopt_check.feasible},
                      {"margins", margins_json(spec_, r.nlopt_check.evaluation)},
                      {"worst_normalised", worst_json(r.nlopt_check.worst)}};
    j["verification"] = ver;
    j["release"] = {{"time_s", spec_.tf}, {"ball_xy_m", arr(r.flight.release_position)},
                    {"ball_velocity_m_s", arr(r.flight.release_velocity)}};
    json path = json::array(), pt = json::array();
    for (size_t k = 0; k < r.flight.path.size(); ++k) {
      path.push_back(arr(r.flight.path[k]));
      pt.push_back(num(r.flight.path_t[k]));
    }
    j["flight"] = {{"reaches", r.flight.reaches}, {"landing_height_m", spec_.landing_height},
                   {"duration_s", num(r.flight.duration)}, {"landing_xy_m", arr(r.flight.landing)},
                   {"apex_m", num(r.flight.apex)}, {"t_s", pt}, {"path_xy_m", path}};
    json rt = json::array(), rq = json::array();
    for (size_t k = 0; k < r.replay_t.size(); ++k) {
      rt.push_back(num(r.replay_t[k]));
      rq.push_back(arr(r.replay_q[k]));
    }
    j["replay"] = {{"max_error_rad", num(r.replay_error)},
                   {"tolerance_rad", spec_.replay_tolerance},
                   {"integrator", "DOPRI5 rtol 1e-10 atol 1e-12, all joints free; voltages of the plan simulated "
                                  "with 16x the RK4 steps, linear between its samples within a stage; "
                                  "error against that plan; coulomb sign smoothed by tanh(qd / 1e-4 rad/s)"},
                   {"t_s", rt}, {"q_rad", rq}};
    j["integration"] = {{"method", "classical RK4, fixed step, steps aligned with the stages"},
                        {"steps_per_stage", spec_.steps_per_stage},
                        {"step_s", spec_.tf / spec_.stages / spec_.steps_per_stage},
                        {"fine_steps_factor", 16},
                        {"energy_error_vs_fine_steps", num(r.rk4_energy_error)},
                        {"theta3_error_vs_fine_steps_rad", num(r.rk4_theta3_error)}};
    j["run_time_s"] = num(r.run_time);
    return j;
  }

  // frames: the IDP optimum's strip and locus (Fig. 7) and the flight (src/scene)
  std::vector<std::string> render(const std::filesystem::path& dir,
                                  const cases::CaseInfo& info) override {
    return scene::render_throwing_frames(spec_, result_, info.render, dir);
  }

 private:
  st::ThrowingSpec spec_;
  st::ThrowingResult result_;
};

std::unique_ptr<StudyRun> load(cases::Map& root, const cases::CaseInfo&) {
  return std::make_unique<ThrowingRun>(cases::load_throwing_spec(root));
}

}  // namespace

StudyEntry throwing_entry() {
  return {"throwing",
          "tray arm with a passive joint: energy-saving throw by IDP and SLSQP (Sato et al. Sec. 4)",
          &load};
}

}  // namespace armstudy::app
