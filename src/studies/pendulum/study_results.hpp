// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The pendulum study's part of results.json as a typed value: what the pipeline writes
/// (app/pendulum_pipeline.cpp fills it from the PendulumResult) and what the report and
/// `armstudy merge` read back. `fields` names every key once: report/results_fields.hpp
/// turns it into the writer, the strict reader and the schema (results.schema.json). SI;
/// keys ending in _deg are degrees.

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace armstudy::studies {

struct PendulumStudyResults {
  struct Tray {
    double circle_offset_m = 0, mass_kg = 0, com_m = 0, com_lateral_m = 0, inertia_kg_m2 = 0;
  };
  struct Ball {
    double mass_kg = 0, circle_radius_m = 0, radius_m = 0, inertia_kg_m2 = 0;
  };
  struct Parameters {
    double gravity_m_s2 = 0;
    std::array<double, 2> locked_deg{}, start_deg{}, start_rate_deg_s{};
    double duration_s = 0;
    Tray tray;
    Ball ball;
    std::vector<std::string> choices;
  };
  struct Integrator {
    std::string name;
    double rtol = 0, atol = 0;
    long steps_accepted = 0, steps_rejected = 0, evaluations = 0;
  };
  struct Series {
    std::vector<double> t_s;
    std::vector<std::vector<double>> q_rad, qd_rad_s;  ///< [[th1..th4] per sample]
    std::vector<double> kinetic_J, potential_J, total_J;
    std::vector<std::array<double, 2>> ball_xy_m, circle_centre_xy_m;
    std::optional<int> stride;  ///< every stride-th output sample and the last
  };
  struct Snapshot {
    double t_s = 0;
    int index = 0;
    std::vector<double> q_rad;
    std::array<double, 2> ball_xy_m{};
  };
  struct Energy {
    double initial_J = 0, scale_J = 0, drift_J = 0, drift_relative = 0, tolerance_relative = 0;
  };
  Parameters parameters;
  Integrator integrator;
  Series series;
  std::vector<Snapshot> snapshots;
  Energy energy;
  double run_time_s = 0;
};

template <class V>
void fields(V& v, PendulumStudyResults::Tray& x) {
  v("circle_offset_m", x.circle_offset_m, "centre of the ball's circle from the tray hinge");
  v("mass_kg", x.mass_kg, "tray mass");
  v("com_m", x.com_m, "tray centre of mass along the tray from the hinge");
  v("com_lateral_m", x.com_lateral_m, "tray centre of mass across the tray");
  v("inertia_kg_m2", x.inertia_kg_m2, "tray inertia about its centre of mass");
}
template <class V>
void fields(V& v, PendulumStudyResults::Ball& x) {
  v("mass_kg", x.mass_kg, "ball mass");
  v("circle_radius_m", x.circle_radius_m, "radius r4 of the circle the ball's centre moves on");
  v("radius_m", x.radius_m, "ball radius r_b");
  v("inertia_kg_m2", x.inertia_kg_m2, "ball inertia about its centre");
}
template <class V>
void fields(V& v, PendulumStudyResults::Parameters& x) {
  v("gravity_m_s2", x.gravity_m_s2, "gravitational acceleration");
  v("locked_deg", x.locked_deg, "locked joint angles [theta1, theta2]");
  v("start_deg", x.start_deg, "initial [theta3, theta4]");
  v("start_rate_deg_s", x.start_rate_deg_s, "initial [theta3', theta4']");
  v("duration_s", x.duration_s, "simulated time");
  v("tray", x.tray, "the tray");
  v("ball", x.ball, "the ball");
  v("choices", x.choices, "what the source leaves open and the value used (sentences)");
}
template <class V>
void fields(V& v, PendulumStudyResults::Integrator& x) {
  v("name", x.name, "integrator");
  v("rtol", x.rtol, "relative tolerance");
  v("atol", x.atol, "absolute tolerance (rad, rad/s)");
  v("steps_accepted", x.steps_accepted, "steps accepted");
  v("steps_rejected", x.steps_rejected, "steps rejected");
  v("evaluations", x.evaluations, "right-hand-side evaluations");
}
template <class V>
void fields(V& v, PendulumStudyResults::Series& x) {
  v("t_s", x.t_s, "sample times");
  v("q_rad", x.q_rad, "[theta1..theta4] per sample");
  v("qd_rad_s", x.qd_rad_s, "[theta1'..theta4'] per sample");
  v("kinetic_J", x.kinetic_J, "kinetic energy per sample");
  v("potential_J", x.potential_J, "potential energy per sample");
  v("total_J", x.total_J, "mechanical energy K + U per sample");
  v("ball_xy_m", x.ball_xy_m, "ball centre [x, y] per sample");
  v("circle_centre_xy_m", x.circle_centre_xy_m, "centre of the ball's circle [x, y] per sample");
  v.optional("stride", x.stride,
             "the samples are every stride-th output sample (pendulum.sample_s apart, with the "
             "snapshot times) and the last (1: every sample; more when there are over 2001, so "
             "that results.json stays within what armstudy reads back)");
}
template <class V>
void fields(V& v, PendulumStudyResults::Snapshot& x) {
  v("t_s", x.t_s, "snapshot time");
  v("index", x.index, "index of the output sample (series holds every series.stride-th)");
  v("q_rad", x.q_rad, "[theta1..theta4]");
  v("ball_xy_m", x.ball_xy_m, "ball centre [x, y]");
}
template <class V>
void fields(V& v, PendulumStudyResults::Energy& x) {
  v("initial_J", x.initial_J, "mechanical energy at t = 0");
  v("scale_J", x.scale_J, "largest kinetic energy (the energy exchanged)");
  v("drift_J", x.drift_J, "max |E(t) - E(0)|");
  v("drift_relative", x.drift_relative, "drift_J / scale_J");
  v("tolerance_relative", x.tolerance_relative,
    "allowed drift_relative (check pendulum_energy_drift)");
}
template <class V>
void fields(V& v, PendulumStudyResults& x) {
  v("parameters", x.parameters, "the model and the start as simulated");
  v("integrator", x.integrator, "the integrator and its effort");
  v("series", x.series, "the motion at every sample (at most 2001: series.stride)");
  v("snapshots", x.snapshots, "the motion every snapshot step (the source's Figure 2)");
  v("energy", x.energy, "energy conservation");
  v("run_time_s", x.run_time_s, "wall time of the simulation");
}

}  // namespace armstudy::studies
