// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The pendulum study in the pipeline: case -> studies::solve_pendulum -> results.json.
//
// results.json "pendulum" section: studies/pendulum/study_results.hpp (every key, typed;
// written from it here, read back from it by the report and merge).
#include <cmath>
#include <cstdio>

#include "app/export_records.hpp"
#include "app/json_numbers.hpp"
#include "app/pipeline.hpp"
#include "app/stored_series.hpp"
#include "app/study_checks.hpp"
#include "app/study_entry.hpp"
#include "cases/pendulum_case.hpp"
#include "report/motion_csv.hpp"
#include "report/results_fields.hpp"
#include "report/study_sections.hpp"
#include "scene/model_export.hpp"
#include "scene/pendulum_frames.hpp"
#include "studies/pendulum/study_results.hpp"

namespace armstudy::app {
namespace {
using core::kDeg;
using nlohmann::json;

std::array<double, 2> xy(const Eigen::Vector2d& v) { return {v.x(), v.y()}; }
std::vector<double> vec(const core::JointVector& v) { return {v.data(), v.data() + v.size()}; }

class PendulumRun final : public TypedStudyRun<studies::PendulumSpec, studies::PendulumResult,
                                               studies::PendulumStudyResults> {
 public:
  using TypedStudyRun::TypedStudyRun;

  studies::Status solve(const studies::ProgressFn& progress) override {
    result_ = studies::solve_pendulum(spec_, progress);
    return result_.status;
  }

  std::vector<studies::Check> checks() const override { return pendulum_checks(spec_, result_); }

  // the figure the pendulum's parameters move (the drift is the integrator's, not theirs)
  std::string headline() const override { return "energy_exchanged_J"; }

  std::vector<KeyFigure> key_figures() const override {
    return {
        {"energy_drift_relative", result_.energy_drift_rel, "",
         "energy drift (share of the energy exchanged)"},
        {"energy_exchanged_J", result_.energy_scale, "J", "largest kinetic energy"},
        {"integrator_steps", static_cast<double>(result_.steps_accepted), "", "integrator steps"}};
  }

  studies::PendulumStudyResults study_results() const override {
    const auto& a = spec_.arm;
    const auto& r = result_;
    studies::PendulumStudyResults s;
    auto& p = s.parameters;
    p.gravity_m_s2 = a.gravity;
    p.locked_deg = {spec_.theta1 / kDeg, spec_.theta2 / kDeg};
    p.start_deg = {spec_.theta3 / kDeg, spec_.theta4 / kDeg};
    p.start_rate_deg_s = {spec_.theta3_rate / kDeg, spec_.theta4_rate / kDeg};
    p.duration_s = spec_.duration;
    p.tray = {a.circle_offset, a.m3, a.r3, a.r3_lateral, a.I3};
    p.ball = {a.m4, a.r4, a.rb, a.Ib};
    p.choices = {
        "joints 1 and 2 locked at the case's locked angles (0, 0 deg by default: at -45, -45 deg "
        "the ball would sit above the hinge)",
        "ball spin = tray rate - (r4/r_b) theta4' (eq. 3 drops the tray rate; a5 is printed "
        "inverted)",
        "tray centre of mass, inertia and circle offset are not given for the test rig; "
        "the values used are in the parameters' tray entries"};
    s.integrator = {r.integrator,     r.rtol,           r.atol,
                    r.steps_accepted, r.steps_rejected, r.evaluations};
    // a long integration as a subsample (app/stored_series.hpp, as the time-optimal
    // study's nodes); the energy check and the snapshots read every step
    auto& se = s.series;
    const int stride = stored_stride(r.t.size());
    se.stride = stride;
    for (const size_t k : stored_indices(r.t.size(), stride)) {
      se.t_s.push_back(r.t[k]);
      se.q_rad.push_back(vec(r.q[k]));
      se.qd_rad_s.push_back(vec(r.qd[k]));
      se.kinetic_J.push_back(r.kinetic[k]);
      se.potential_J.push_back(r.potential[k]);
      se.total_J.push_back(r.total[k]);
      se.ball_xy_m.push_back(xy(r.ball[k]));
      se.circle_centre_xy_m.push_back(xy(r.circle_centre[k]));
    }
    // a failed integration has the snapshot times it asked for, but no states to index
    for (size_t i = 0; i < r.snapshot_index.size(); ++i) {
      const int k = r.snapshot_index[i];
      s.snapshots.push_back({r.snapshot_t[i], k, vec(r.q[k]), xy(r.ball[k])});
    }
    s.energy = {r.energy_initial, r.energy_scale, r.energy_drift, r.energy_drift_rel,
                spec_.drift_tolerance};
    s.run_time_s = r.run_time;
    return s;
  }

  // model.xml (the frames' scene, keyframes at the snapshots) and the motion as CSV
  std::vector<report::ExportRecord> write_exports(const std::filesystem::path& dir,
                                                  const cases::CaseInfo& info) override {
    std::vector<report::ExportRecord> out;
    if (result_.status != studies::Status::kSolved || result_.t.empty()) return out;
    const core::PlanarChain chain = studies::make_tray_arm(spec_.arm);
    const scene::ArmScene sc = scene::pendulum_scene(spec_, result_, info.render);
    const auto keys = scene::pendulum_snapshots(result_);
    const std::string motion = "the pendulum's snapshots (pendulum_snapshots_strip.png)";
    out.push_back(model_export_entry(
        scene::write_model_xml(dir, chain, sc.mjcf, keys, motion, info.path), motion, keys));
    report::MotionCsv t;
    t.file = "motion_pendulum.csv";
    t.what =
        "the simulated pendulum (joints 1 and 2 locked, the tray and the ball free; the "
        "integrator's accepted steps): time, the four joint angles and rates, kinetic, potential "
        "and total energy, the ball's centre; no joint torques (the locked joints hold still, the "
        "others are passive) and no motors";
    t.add("t", "s", result_.t);
    t.add_joints("q", "rad", result_.q);
    t.add_joints("qd", "rad/s", result_.qd);
    if (result_.kinetic.size() == result_.t.size()) {
      t.add("kinetic_energy", "J", result_.kinetic);
      t.add("potential_energy", "J", result_.potential);
      t.add("total_energy", "J", result_.total);
    }
    if (result_.ball.size() == result_.t.size()) {
      t.add_joints("ball_", "m", result_.ball);
      t.columns[t.columns.size() - 2].name = "ball_x";
      t.columns[t.columns.size() - 1].name = "ball_y";
    }
    report::write_motion_csv(dir, t);
    out.push_back(csv_export_entry(t, "pendulum"));
    return out;
  }

  // frames: snapshots every snapshot_step, strip and locus (src/scene)
  scene::Rendered render(const std::filesystem::path& dir, const cases::CaseInfo& info) override {
    return scene::render_pendulum_frames(spec_, result_, info.render, dir);
  }
};

}  // namespace

std::vector<studies::Check> pendulum_checks(const studies::PendulumSpec& spec,
                                            const studies::PendulumResult& result) {
  if (result.status != studies::Status::kSolved) return {};
  return {studies::make_check(
      "pendulum_energy_drift",
      "mechanical energy of the passive tray and ball (joints 1, 2 locked) stays constant: "
      "max |E(t) - E(0)| over the largest kinetic energy",
      result.energy_drift_rel, spec.drift_tolerance)};
}

StudyParts pendulum_parts() {
  return study_parts<PendulumRun>(
      "tray and rolling ball swinging freely (Sato et al. Sec. 3): energy conservation",
      &report::pendulum_sections, &report::pendulum_answer);
}

}  // namespace armstudy::app
