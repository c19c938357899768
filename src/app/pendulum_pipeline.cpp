// The pendulum study in the pipeline: case -> studies::solve_pendulum -> results.json.
//
// results.json "pendulum" section (SI; keys ending in _deg are degrees):
//   parameters {gravity_m_s2, locked_deg [th1, th2], start_deg [th3, th4],
//               start_rate_deg_s, duration_s, tray {circle_offset_m, mass_kg, com_m,
//               com_lateral_m, inertia_kg_m2}, ball {mass_kg, circle_radius_m, radius_m,
//               inertia_kg_m2}, choices [sentences: what 003 leaves open and the value used]},
//   integrator {name, rtol, atol, steps_accepted, steps_rejected, evaluations},
//   series {t_s, q_rad [[th1..th4] per sample], qd_rad_s [[...]], kinetic_J, potential_J,
//           total_J, ball_xy_m [[x, y]], circle_centre_xy_m [[x, y]]},
//   snapshots [{t_s, index, q_rad, ball_xy_m}] every snapshot_s (Fig. 2),
//   energy {initial_J, scale_J (largest kinetic energy), drift_J, drift_relative,
//           tolerance_relative}, run_time_s.
#include <cmath>
#include <cstdio>

#include "cases/pendulum_case.hpp"
#include "app/json_numbers.hpp"
#include "app/pipeline.hpp"
#include "report/case_report.hpp"
#include "scene/pendulum_frames.hpp"

namespace armstudy::app {
namespace {
using nlohmann::json;
constexpr double kDeg = core::kPi / 180.0;

json num(double v) { return json_number(v); }
json xy(const Eigen::Vector2d& v) { return json::array({num(v.x()), num(v.y())}); }
json vec(const core::JointVector& v) {
  json a = json::array();
  for (int i = 0; i < v.size(); ++i) a.push_back(num(v[i]));
  return a;
}

class PendulumRun final : public StudyRun {
 public:
  explicit PendulumRun(studies::PendulumSpec spec) : spec_(std::move(spec)) {}

  studies::Status solve(const studies::ProgressFn& progress) override {
    result_ = studies::solve_pendulum(spec_, progress);
    return result_.status;
  }
  std::string message() const override { return result_.message; }

  std::vector<studies::Check> checks() const override {
    if (result_.status != studies::Status::kSolved) return {};
    return {studies::make_check(
        "pendulum_energy_drift",
        "mechanical energy of the passive tray and ball (joints 1, 2 locked) stays constant: "
        "max |E(t) - E(0)| over the largest kinetic energy",
        result_.energy_drift_rel, spec_.drift_tolerance)};
  }

  std::vector<KeyFigure> key_figures() const override {
    return {{"energy_drift_relative", result_.energy_drift_rel, "", "energy drift (share of the energy exchanged)"},
            {"energy_exchanged_J", result_.energy_scale, "J", "largest kinetic energy"},
            {"integrator_steps", static_cast<double>(result_.steps_accepted), "", "integrator steps"}};
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
    j["parameters"] = {
        {"gravity_m_s2", a.gravity},
        {"locked_deg", {spec_.theta1 / kDeg, spec_.theta2 / kDeg}},
        {"start_deg", {spec_.theta3 / kDeg, spec_.theta4 / kDeg}},
        {"start_rate_deg_s", {spec_.theta3_rate / kDeg, spec_.theta4_rate / kDeg}},
        {"duration_s", spec_.duration},
        {"tray", {{"circle_offset_m", a.circle_offset}, {"mass_kg", a.m3}, {"com_m", a.r3},
                  {"com_lateral_m", a.r3_lateral}, {"inertia_kg_m2", a.I3}}},
        {"ball", {{"mass_kg", a.m4}, {"circle_radius_m", a.r4}, {"radius_m", a.rb},
                  {"inertia_kg_m2", a.Ib}}},
        {"choices",
         {"joints 1 and 2 locked at the case's locked angles (0, 0 deg by default: at -45, -45 deg "
          "the ball would sit above the hinge)",
          "ball spin = tray rate - (r4/r_b) theta4' (eq. 3 drops the tray rate; a5 is printed "
          "inverted)",
          "tray centre of mass, inertia and circle offset are not given for the test rig; "
          "the values used are in the parameters' tray entries"}}};
    j["integrator"] = {{"name", r.integrator}, {"rtol", r.rtol}, {"atol", r.atol},
                       {"steps_accepted", r.steps_accepted}, {"steps_rejected", r.steps_rejected},
                       {"evaluations", r.evaluations}};
    json t = json::array(), q = json::array(), qd = json::array(), K = json::array(),
         U = json::array(), E = json::array(), ball = json::array(), cc = json::array();
    for (size_t k = 0; k < r.t.size(); ++k) {
      t.push_back(num(r.t[k]));
      q.push_back(vec(r.q[k]));
      qd.push_back(vec(r.qd[k]));
      K.push_back(num(r.kinetic[k]));
      U.push_back(num(r.potential[k]));
      E.push_back(num(r.total[k]));
      ball.push_back(xy(r.ball[k]));
      cc.push_back(xy(r.circle_centre[k]));
    }
    j["series"] = {{"t_s", t}, {"q_rad", q}, {"qd_rad_s", qd}, {"kinetic_J", K},
                   {"potential_J", U}, {"total_J", E}, {"ball_xy_m", ball},
                   {"circle_centre_xy_m", cc}};
    json snaps = json::array();
    for (size_t i = 0; i < r.snapshot_t.size(); ++i) {
      const int k = r.snapshot_index[i];
      snaps.push_back({{"t_s", num(r.snapshot_t[i])}, {"index", k}, {"q_rad", vec(r.q[k])},
                       {"ball_xy_m", xy(r.ball[k])}});
    }
    j["snapshots"] = snaps;
    j["energy"] = {{"initial_J", num(r.energy_initial)}, {"scale_J", num(r.energy_scale)},
                   {"drift_J", num(r.energy_drift)}, {"drift_relative", num(r.energy_drift_rel)},
                   {"tolerance_relative", spec_.drift_tolerance}};
    j["run_time_s"] = num(r.run_time);
    return j;
  }

  // frames: snapshots every snapshot_step, strip and locus (src/scene)
  std::vector<std::string> render(const std::filesystem::path& dir,
                                  const cases::CaseInfo& info) override {
    return scene::render_pendulum_frames(spec_, result_, info.render, dir);
  }

 private:
  studies::PendulumSpec spec_;
  studies::PendulumResult result_;
};

std::unique_ptr<StudyRun> load(cases::Map& root, const cases::CaseInfo&) {
  return std::make_unique<PendulumRun>(cases::load_pendulum_spec(root));
}

}  // namespace

StudyEntry pendulum_entry() {
  return {"pendulum",
          "tray and rolling ball swinging freely (Sato et al. Sec. 3): energy conservation",
          &load};
}

}  // namespace armstudy::app
