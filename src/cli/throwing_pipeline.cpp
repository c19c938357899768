// The throwing study in the pipeline: case -> studies::solve_throwing -> results.json.
//
// results.json "throwing" section (SI; keys ending in _deg are degrees):
//   parameters {gravity_m_s2, link1/link2 {length_m, mass_kg, com_m, inertia_kg_m2},
//               tray {circle_offset_m, mass_kg, com_m, com_lateral_m, inertia_kg_m2,
//               width_deg}, ball {mass_kg, circle_radius_m, radius_m, inertia_kg_m2},
//               motors {kt_Nm_per_A, kv_V_s_per_rad, resistance_ohm, viscous_Nm_s_per_rad,
//               coulomb_Nm, rotor_inertia_kg_m2, motor2, count_regeneration},
//               task {start_deg [4], release_deg [3], release_rate_rad_s [2], duration_s,
//               landing_height_m}, criterion {k_*}, choices [sentences]},
//   limits {voltage_max_V, current_max_A, theta4_limit_rad [-lambda/2, lambda/2]},
//   energy_initial_J (eq. 8), energy_optimised_J (IDP), saving_percent,
//   initial, optimum, nlopt.motion: motions {energy_J, criterion_J, max_abs_theta4_rad,
//       max_voltage_V, max_current_A, release_error {angle_rad [th1, th2, th3],
//       rate_rad_s [th1', th2']}, energy_split {electrical_J, mechanical_J, copper_J,
//       friction_J, rest_J}, profile {t_s, rate_rad_s [[j1, j2] per node]},
//       series {t_s, stage, q_rad [[th1..th4]], qd_rad_s, torque_Nm [[m1, m2]], voltage_V,
//       current_A, power_W, energy_J, ball_xy_m}} (two samples share each stage boundary),
//   idp {stages, steps_per_stage, iterations, passes, candidates, shrink, restore,
//        region_rad_s, seed, threads, evaluations, run_time_s,
//        convergence [{iteration, pass, criterion_J, energy_J, region_rad_s, evaluations,
//        improvements}]},
//   nlopt {ran, algorithm, return_code, feasible, simulations, run_time_s, history_J, motion},
//   release {time_s, ball_xy_m, ball_velocity_m_s},
//   flight {reaches, landing_height_m, duration_s, landing_xy_m, apex_m, t_s, path_xy_m},
//   replay {max_error_rad, tolerance_rad, integrator, t_s, q_rad},
//   integration {method, steps_per_stage, step_s, fine_steps_factor (16),
//                energy_error_vs_fine_steps, theta3_error_vs_fine_steps_rad},
//   run_time_s.
#include <cmath>
#include <cstdio>

#include "cases/throwing_case.hpp"
#include "cli/json_numbers.hpp"
#include "cli/pipeline.hpp"
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

json motion_json(const st::ThrowMotion& m) {
  const auto& e = m.evaluation;
  json j;
  j["energy_J"] = num(e.energy);
  j["criterion_J"] = num(e.criterion);
  j["max_abs_theta4_rad"] = num(e.max_abs_theta4);
  j["max_voltage_V"] = num(e.max_voltage);
  j["max_current_A"] = num(e.max_current);
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
       en = json::array(), ball = json::array();
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
  }
  // the stage of each sample: the end sample of a stage repeats its time
  int stg = 0;
  for (size_t k = 0; k < s.t.size(); ++k) {
    stage.push_back(stg);
    if (k + 1 < s.t.size() && s.t[k + 1] == s.t[k]) ++stg;
  }
  j["series"] = {{"t_s", t}, {"stage", stage}, {"q_rad", q}, {"qd_rad_s", qd},
                 {"torque_Nm", tau}, {"voltage_V", v}, {"current_A", i}, {"power_W", p},
                 {"energy_J", en}, {"ball_xy_m", ball}};
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
    if (r.idp.series.t.empty()) return {};
    const auto& e = r.idp.evaluation;
    return {
        st::make_check("voltage_limit", "largest |motor voltage| along the optimum (V)",
                       e.max_voltage, spec_.voltage_max),
        st::make_check("current_limit", "largest |motor current| along the optimum (A)",
                       e.max_current, spec_.current_max),
        st::make_check("ball_in_tray", "largest |theta4| along the optimum (rad) <= lambda/2",
                       e.max_abs_theta4, spec_.tray_width / 2),
        st::make_check("energy_below_eq8",
                       "optimised energy (J) below the eq. 8 trajectory's energy",
                       e.energy, r.initial.evaluation.energy * (1 - 1e-9)),
        st::make_check("release_theta3", "|theta3(tf) - release theta3| of the optimum (rad)",
                       std::abs(r.idp.angle_error[2]), spec_.release_tolerance),
        st::make_check("open_loop_replay",
                       "the optimum's voltages applied open loop to the core model (all joints "
                       "free, DOPRI5) reproduce the planned angles (16x-step plan): max error (rad)",
                       r.replay_error, spec_.replay_tolerance),
        st::make_check("rk4_accuracy",
                       "relative energy change of the optimum with 16x the RK4 steps",
                       r.rk4_energy_error, 1e-3),
    };
  }

  std::vector<KeyFigure> key_figures() const override {
    const auto& r = result_;
    std::vector<KeyFigure> k = {
        {"energy_eq8_J", r.initial.evaluation.energy, "J"},
        {"energy_idp_J", r.idp.evaluation.energy, "J"},
        {"saving_percent", r.saving_percent, "%"},
        {"idp_run_time_s", r.idp_run.run_time, "s"},
        {"replay_error_rad", r.replay_error, "rad"},
    };
    if (r.nlopt_ran) k.push_back({"energy_slsqp_J", r.nlopt.evaluation.energy, "J"});
    if (r.flight.reaches) k.push_back({"landing_x_m", r.flight.landing.x(), "m"});
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
        {"criterion", {{"k_tray_J_per_rad", spec_.k_tray}, {"k_release_J_per_rad", spec_.k_release},
                       {"k_voltage_J_per_V", spec_.k_voltage}, {"k_current_J_per_A", spec_.k_current}}},
        {"choices",
         {"model derived from first principles (docs/derivations/throwing.md): ball spin = "
          "tray rate - (r4/r_b) "
          "theta4'; eq. 3's spin term and a5 as printed are wrong",
          "the centre of the ball's circle lies circle_offset_m from the tray hinge (Table 1's l3 "
          "by default)",
          "ball inertia 2/5 m r_b^2 unless given (equals Table 1's 4.8e-7 kg m^2)",
          "motor 2 drives theta2 (on_link1, eq. 5 as printed) unless motor2: on_base",
          "rotor inertia (missing from Table 1) as given in motors.rotor_inertia_kg_m2",
          "tray width lambda (eq. 9) as tray.width_deg; current limit as motors.current_max_A",
          "energy = eq. 7 (signed e i: regeneration counted) unless count_regeneration: false",
          "theta3 at release is penalised (k_release), reached through the passive dynamics"}}};
    j["limits"] = {{"voltage_max_V", spec_.voltage_max}, {"current_max_A", spec_.current_max},
                   {"theta4_limit_rad", {-spec_.tray_width / 2, spec_.tray_width / 2}}};
    j["energy_initial_J"] = num(r.initial.evaluation.energy);
    j["energy_optimised_J"] = num(r.idp.evaluation.energy);
    j["saving_percent"] = num(r.saving_percent);
    if (r.idp.series.t.empty()) return j;
    j["initial"] = motion_json(r.initial);
    j["optimum"] = motion_json(r.idp);
    json conv = json::array();
    for (const auto& h : r.idp_run.history)
      conv.push_back({{"iteration", h.iteration}, {"pass", h.pass}, {"criterion_J", num(h.criterion)},
                      {"energy_J", num(h.energy)}, {"region_rad_s", arr(h.region)},
                      {"evaluations", h.evaluations}, {"improvements", h.improvements}});
    const auto& is = spec_.idp;
    j["idp"] = {{"stages", spec_.stages}, {"steps_per_stage", spec_.steps_per_stage},
                {"iterations", is.iterations}, {"passes", is.passes}, {"candidates", is.candidates},
                {"shrink", is.shrink}, {"restore", is.restore}, {"region_rad_s", arr(is.region)},
                {"seed", is.seed}, {"threads", r.idp_run.threads},
                {"evaluations", r.idp_run.evaluations}, {"run_time_s", num(r.idp_run.run_time)},
                {"convergence", conv}};
    json nl = {{"ran", r.nlopt_ran}};
    if (r.nlopt_ran) {
      json hist = json::array();
      for (double h : r.nlopt_run.history) hist.push_back(num(h));
      nl["algorithm"] = "NLopt LD_SLSQP, central-difference gradients, same parameterisation";
      nl["return_code"] = r.nlopt_run.return_code;
      nl["feasible"] = r.nlopt_run.feasible;
      nl["simulations"] = r.nlopt_run.simulations;
      nl["run_time_s"] = num(r.nlopt_run.run_time);
      nl["max_evaluations"] = spec_.nlopt.max_evaluations;
      nl["history_J"] = hist;
      nl["motion"] = motion_json(r.nlopt);
    }
    j["nlopt"] = nl;
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
