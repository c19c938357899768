// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The throwing study's part of results.json as a typed value: what the pipeline writes
/// (app/throwing_pipeline.cpp fills it from the ThrowingResult) and what the report and
/// `armstudy merge` read back. `fields` names every key once: report/results_fields.hpp
/// turns it into the writer, the strict reader and the schema (results.schema.json). SI;
/// keys ending in _deg are degrees. Everything after saving_percent is present only when
/// the study ran its optimisers (an unsolvable case stops before).

#include <optional>
#include <string>
#include <vector>

namespace armstudy::studies {

struct ThrowingStudyResults {
  using Rows = std::vector<std::vector<double>>;
  struct Link {
    double length_m = 0, mass_kg = 0, com_m = 0, inertia_kg_m2 = 0;
  };
  struct Tray {
    double circle_offset_m = 0, mass_kg = 0, com_m = 0, com_lateral_m = 0, inertia_kg_m2 = 0,
           width_deg = 0;
  };
  struct Ball {
    double mass_kg = 0, circle_radius_m = 0, radius_m = 0, inertia_kg_m2 = 0;
  };
  struct Motors {
    double kt_Nm_per_A = 0, kv_V_s_per_rad = 0, resistance_ohm = 0, viscous_Nm_s_per_rad = 0,
           coulomb_Nm = 0, rotor_inertia_kg_m2 = 0;
    std::string motor2;
    bool count_regeneration = true;
  };
  struct Task {
    std::vector<double> start_deg, release_deg, release_rate_rad_s;
    double duration_s = 0, landing_height_m = 0;
  };
  struct Parameters {
    double gravity_m_s2 = 0;
    Link link1, link2;
    Tray tray;
    Ball ball;
    Motors motors;
    Task task;
    std::vector<std::string> choices;
  };
  struct Assumption {
    std::string name;
    double value = 0;
    std::string unit, key;
  };
  struct Limits {
    double voltage_max_V = 0, current_max_A = 0, power_max_W = 0;
    std::vector<double> theta4_limit_rad;
    double contact_margin_N = 0, friction_coefficient = 0, release_tolerance_rad = 0, backoff = 0;
  };
  /// per constraint: normalised worst value (> 0 broken)
  struct Worst {
    double contact = 0, friction = 0, tray = 0, voltage = 0, current = 0, power = 0, release = 0;
  };
  /// per constraint: margin in its unit (> 0 met)
  struct Margins {
    double contact_N = 0, friction = 0, tray_rad = 0, release_rad = 0, voltage_V = 0, current_A = 0,
           power_W = 0;
  };
  struct Break {
    std::string constraint;
    double worst_normalised = 0, margin = 0;
    std::string unit;
  };
  struct Repair {
    std::string method, return_code;
    bool converged = false, feasible = false;
    int iterations = 0;
    long simulations = 0;
    double run_time_s = 0, max_rate_change_rad_s = 0;
  };
  struct Reference {
    std::string kind;
    bool initial_feasible = false;
    std::vector<Break> raw_breaks;
    std::optional<Repair> repair;
  };
  struct ReleaseError {
    std::vector<double> angle_rad, rate_rad_s;
  };
  struct EnergySplit {
    double electrical_J = 0, mechanical_J = 0, copper_J = 0, friction_J = 0, rest_J = 0;
  };
  struct Profile {
    std::vector<double> t_s;
    Rows rate_rad_s;
  };
  struct Series {
    std::vector<double> t_s;
    std::vector<int> stage;
    Rows q_rad, qd_rad_s, torque_Nm, voltage_V, current_A, power_W;
    std::vector<double> energy_J;
    Rows ball_xy_m;
    std::vector<double> normal_force_N, tangential_force_N, friction_needed;
  };
  struct Motion {
    double energy_J = 0, max_abs_theta4_rad = 0, max_voltage_V = 0, max_current_A = 0,
           max_power_W = 0, min_normal_force_N = 0, max_friction_ratio = 0;
    bool feasible = false;
    Worst worst_normalised;
    Margins margins;
    ReleaseError release_error;
    EnergySplit energy_split;
    Profile profile;
    Series series;
  };
  struct SeedRun {
    unsigned seed = 0;
    double energy_J = 0;
    bool feasible = false, converged = false;
    int passes = 0;
    double last_gain = 0;
    long evaluations = 0;
    double run_time_s = 0;
  };
  struct Spread {
    double best_J = 0, median_J = 0, worst_J = 0;
  };
  /// the first-order optimality of an answer
  struct FirstOrder {
    double kkt_residual = 0, kkt_tolerance = 0;
    int active_constraints = 0;
    std::vector<std::string> binding;
  };
  struct IdpStep {
    int iteration = 0, pass = 0;
    double energy_J = 0, violation = 0;
    std::vector<double> region_rad_s;
    long evaluations = 0;
    int improvements = 0;
  };
  struct Idp {
    int stages = 0, steps_per_stage = 0, iterations = 0, max_passes = 0;
    double tolerance = 0;
    int quiet_passes = 0, candidates = 0;
    double shrink = 0, restore = 0;
    std::vector<double> region_rad_s;
    unsigned seed = 0;
    int seeds = 0;
    double backoff = 0;
    int threads = 0;
    bool converged = false;
    unsigned best_seed = 0;
    int passes = 0;
    double last_gain = 0;
    long evaluations = 0;
    double run_time_s = 0;
    std::vector<SeedRun> seed_runs;
    Spread spread;
    std::vector<IdpStep> convergence;
    std::optional<FirstOrder> first_order;
  };
  /// one SLSQP start and the local optimum it reached
  struct Start {
    std::string name;
    double energy_J = 0;
    bool feasible = false, converged = false;
    double kkt_residual = 0;
    int iterations = 0, restarts = 0;
    std::string return_code;
  };
  struct NloptRun {
    std::string algorithm, return_code;
    bool converged = false, feasible = false;
    double last_gain = 0;
    int iterations = 0;
    long simulations = 0;
    double run_time_s = 0;
    int max_evaluations = 0;
    double max_time_s = 0, ftol_rel = 0, xtol_rel = 0;
    std::vector<double> history_J;
    Motion motion;
    std::optional<FirstOrder> first_order;
    std::optional<std::vector<Start>> starts;
    std::optional<std::string> best_start;
  };
  struct Nlopt {
    bool ran = false;
    std::optional<NloptRun> run;  ///< its keys sit beside ran, when it ran
  };
  struct Comparison {
    std::string optimiser;
    double energy_J = 0, mechanical_J = 0, copper_J = 0, friction_J = 0;
    bool converged = false;
    long simulations = 0;
    double run_time_s = 0;
    bool feasible = false;
    Margins margins;
    std::vector<std::string> binding;
    std::string binding_rating;
  };
  struct Verified {
    bool feasible = false;
    Margins margins;
    Worst worst_normalised;
  };
  struct Verification {
    int refinement = 0;
    Verified idp;
    std::optional<Verified> nlopt;
  };
  struct Release {
    double time_s = 0;
    std::vector<double> ball_xy_m, ball_velocity_m_s;
  };
  struct Flight {
    bool reaches = false;
    double landing_height_m = 0, duration_s = 0;
    std::vector<double> landing_xy_m;
    double apex_m = 0;
    std::vector<double> t_s;
    Rows path_xy_m;
  };
  struct Replay {
    double max_error_rad = 0, tolerance_rad = 0;
    std::string integrator;
    std::vector<double> t_s;
    Rows q_rad;
  };
  struct Integration {
    std::string method;
    int steps_per_stage = 0;
    double step_s = 0;
    int fine_steps_factor = 0;
    double energy_error_vs_fine_steps = 0, theta3_error_vs_fine_steps_rad = 0;
  };
  /// one control grid of the answer's sequence
  struct Grid {
    int stages = 0, steps_per_stage = 0;
    double energy_J = 0;
    bool feasible = false, converged = false;
    double kkt_residual = 0;
    std::string from;
    double run_time_s = 0;
    long simulations = 0;
  };
  /// the answer's control grids and the verdict on them
  struct ControlGrids {
    std::string status;  ///< converged, not_converged or not_refined
    double tolerance = 0;
    int refinements = 0;
    std::vector<Grid> grids;
    double change_per_doubling_J = 0, error_J = 0, extrapolated_J = 0;
    double energy_first_grid_J = 0;
  };
  /// what only a run of the optimisers has
  struct Optimised {
    Reference reference;
    Motion initial;
    std::optional<Motion> reference_motion;
    Motion optimum;
    Idp idp;
    Nlopt nlopt;
    std::optional<ControlGrids> control_grids;  ///< when SLSQP ran
    std::vector<Comparison> comparison;
    std::string answer;  ///< "idp" or "slsqp": the optimiser whose throw the study answers with
    Verification verification;
    Release release;
    Flight flight;
    Replay replay;
    Integration integration;
    double run_time_s = 0;
  };

  Parameters parameters;
  std::vector<Assumption> assumptions;
  Limits limits;
  double energy_initial_J = 0, energy_reference_J = 0, energy_optimised_J = 0, saving_percent = 0;
  std::optional<Optimised> run;  ///< its keys sit beside the energies, when the optimisers ran
};

template <class V>
void fields(V& v, ThrowingStudyResults::Link& x) {
  v("length_m", x.length_m, "link length");
  v("mass_kg", x.mass_kg, "link mass");
  v("com_m", x.com_m, "centre of mass from the joint");
  v("inertia_kg_m2", x.inertia_kg_m2, "inertia about the centre of mass");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Tray& x) {
  v("circle_offset_m", x.circle_offset_m, "centre of the ball's circle from the tray hinge");
  v("mass_kg", x.mass_kg, "tray mass");
  v("com_m", x.com_m, "tray centre of mass along the tray");
  v("com_lateral_m", x.com_lateral_m, "tray centre of mass across the tray");
  v("inertia_kg_m2", x.inertia_kg_m2, "tray inertia about its centre of mass");
  v("width_deg", x.width_deg, "tray angular width lambda");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Ball& x) {
  v("mass_kg", x.mass_kg, "ball mass");
  v("circle_radius_m", x.circle_radius_m, "radius r4 of the ball's circle");
  v("radius_m", x.radius_m, "ball radius r_b");
  v("inertia_kg_m2", x.inertia_kg_m2, "ball inertia about its centre");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Motors& x) {
  v("kt_Nm_per_A", x.kt_Nm_per_A, "torque constant");
  v("kv_V_s_per_rad", x.kv_V_s_per_rad, "back-emf constant");
  v("resistance_ohm", x.resistance_ohm, "armature resistance");
  v("viscous_Nm_s_per_rad", x.viscous_Nm_s_per_rad, "viscous friction");
  v("coulomb_Nm", x.coulomb_Nm, "Coulomb friction");
  v("rotor_inertia_kg_m2", x.rotor_inertia_kg_m2, "rotor inertia of each motor");
  v("motor2", x.motor2, "where motor 2 sits: on_link1 or on_base");
  v("count_regeneration", x.count_regeneration, "the energy counts regeneration (signed e i)");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Task& x) {
  v("start_deg", x.start_deg, "[theta1, theta2, theta3, theta4] at the start");
  v("release_deg", x.release_deg, "[theta1, theta2, theta3] at release");
  v("release_rate_rad_s", x.release_rate_rad_s, "[theta1', theta2'] at release");
  v("duration_s", x.duration_s, "time to release tf");
  v("landing_height_m", x.landing_height_m, "height where the flight ends");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Parameters& x) {
  v("gravity_m_s2", x.gravity_m_s2, "gravitational acceleration");
  v("link1", x.link1, "link 1");
  v("link2", x.link2, "link 2");
  v("tray", x.tray, "the tray");
  v("ball", x.ball, "the ball");
  v("motors", x.motors, "the motors");
  v("task", x.task, "the throw");
  v("choices", x.choices, "modelling choices (sentences)");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Assumption& x) {
  v("name", x.name, "what the source leaves open");
  v("value", x.value, "the value used, in unit");
  v("unit", x.unit, "unit of value");
  v("key", x.key, "the case key that sets it");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Limits& x) {
  v("voltage_max_V", x.voltage_max_V, "motor voltage limit |e|");
  v("current_max_A", x.current_max_A, "motor current limit");
  v("power_max_W", x.power_max_W, "motor power limit |e i|");
  v("theta4_limit_rad", x.theta4_limit_rad, "[-lambda/2, lambda/2]: the ball stays in the tray");
  v("contact_margin_N", x.contact_margin_N, "least normal force of the tray on the ball");
  v("friction_coefficient", x.friction_coefficient, "rolling needs |F_t| <= mu N");
  v("release_tolerance_rad", x.release_tolerance_rad, "allowed |theta3(tf) - release theta3|");
  v("backoff", x.backoff, "normalised constraint back-off of both optimisers");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Worst& x) {
  v("contact", x.contact, "normalised worst contact constraint (> 0 broken)");
  v("friction", x.friction, "normalised worst friction constraint (> 0 broken)");
  v("tray", x.tray, "normalised worst tray constraint (> 0 broken)");
  v("voltage", x.voltage, "normalised worst voltage constraint (> 0 broken)");
  v("current", x.current, "normalised worst current constraint (> 0 broken)");
  v("power", x.power, "normalised worst power constraint (> 0 broken)");
  v("release", x.release, "normalised release constraint (> 0 broken)");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Margins& x) {
  v("contact_N", x.contact_N, "smallest normal force minus the contact margin (> 0 met)");
  v("friction", x.friction, "mu minus the largest |F_t| / N (> 0 met)");
  v("tray_rad", x.tray_rad, "lambda/2 minus the largest |theta4| (> 0 met)");
  v("release_rad", x.release_rad, "release tolerance minus |theta3(tf) - release| (> 0 met)");
  v("voltage_V", x.voltage_V, "voltage limit minus the largest |e| (> 0 met)");
  v("current_A", x.current_A, "current limit minus the largest |i| (> 0 met)");
  v("power_W", x.power_W, "power limit minus the largest |e i| (> 0 met)");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Break& x) {
  v("constraint", x.constraint, "the constraint eq. 8 breaks");
  v("worst_normalised", x.worst_normalised, "its normalised worst value");
  v("margin", x.margin, "its margin, in unit (< 0 broken)");
  v("unit", x.unit, "unit of margin");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Repair& x) {
  v("method", x.method, "how the reference is repaired");
  v("return_code", x.return_code, "NLopt's return code");
  v("converged", x.converged, "the repair stopped on its tolerance");
  v("feasible", x.feasible, "the repaired reference meets every constraint");
  v("iterations", x.iterations, "SLSQP iterations");
  v("simulations", x.simulations, "simulations");
  v("run_time_s", x.run_time_s, "wall time");
  v("max_rate_change_rad_s", x.max_rate_change_rad_s, "largest change of a node rate");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Reference& x) {
  v("kind", x.kind, "eq8, repaired or none");
  v("initial_feasible", x.initial_feasible, "eq. 8 meets every constraint");
  v("raw_breaks", x.raw_breaks, "the constraints eq. 8 breaks");
  v.optional("repair", x.repair, "the repair (when eq. 8 is not feasible)");
}
template <class V>
void fields(V& v, ThrowingStudyResults::ReleaseError& x) {
  v("angle_rad", x.angle_rad, "[theta1, theta2, theta3] at tf minus the release angles");
  v("rate_rad_s", x.rate_rad_s, "[theta1', theta2'] at tf minus the release rates");
}
template <class V>
void fields(V& v, ThrowingStudyResults::EnergySplit& x) {
  v("electrical_J", x.electrical_J, "electrical energy");
  v("mechanical_J", x.mechanical_J, "mechanical work of the motors");
  v("copper_J", x.copper_J, "copper losses");
  v("friction_J", x.friction_J, "friction losses");
  v("rest_J", x.rest_J, "the remainder");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Profile& x) {
  v("t_s", x.t_s, "stage node times");
  v("rate_rad_s", x.rate_rad_s, "[theta1', theta2'] per node");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Series& x) {
  v("t_s", x.t_s, "every RK4 step start (two samples share each stage boundary)");
  v("stage", x.stage, "stage of each sample");
  v("q_rad", x.q_rad, "[theta1..theta4] per sample");
  v("qd_rad_s", x.qd_rad_s, "[theta1'..theta4'] per sample");
  v("torque_Nm", x.torque_Nm, "motor torques [m1, m2] per sample");
  v("voltage_V", x.voltage_V, "motor voltages per sample");
  v("current_A", x.current_A, "motor currents per sample");
  v("power_W", x.power_W, "motor powers per sample");
  v("energy_J", x.energy_J, "energy so far");
  v("ball_xy_m", x.ball_xy_m, "ball centre [x, y] per sample");
  v("normal_force_N", x.normal_force_N, "normal force of the tray on the ball");
  v("tangential_force_N", x.tangential_force_N, "tangential force of the tray on the ball");
  v("friction_needed", x.friction_needed, "|F_t| / N (null where the tray does not push)");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Motion& x) {
  v("energy_J", x.energy_J, "energy of the throw");
  v("max_abs_theta4_rad", x.max_abs_theta4_rad, "largest |theta4|");
  v("max_voltage_V", x.max_voltage_V, "largest |motor voltage|");
  v("max_current_A", x.max_current_A, "largest |motor current|");
  v("max_power_W", x.max_power_W, "largest |motor power|");
  v("min_normal_force_N", x.min_normal_force_N, "smallest normal force");
  v("max_friction_ratio", x.max_friction_ratio, "largest |F_t| / N");
  v("feasible", x.feasible, "meets every constraint");
  v("worst_normalised", x.worst_normalised, "normalised worst value of each constraint");
  v("margins", x.margins, "margin of each constraint");
  v("release_error", x.release_error, "the state at tf against the release");
  v("energy_split", x.energy_split, "where the energy goes");
  v("profile", x.profile, "the joint-velocity profile");
  v("series", x.series, "the motion");
}
template <class V>
void fields(V& v, ThrowingStudyResults::SeedRun& x) {
  v("seed", x.seed, "random seed");
  v("energy_J", x.energy_J, "energy found");
  v("feasible", x.feasible, "meets every constraint");
  v("converged", x.converged, "stopped on its tolerance");
  v("passes", x.passes, "passes run");
  v("last_gain", x.last_gain, "relative gain of the last pass");
  v("evaluations", x.evaluations, "simulations");
  v("run_time_s", x.run_time_s,
    "wall time from its start to its end (the seeds of one thread run side by side)");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Spread& x) {
  v("best_J", x.best_J, "best seed's energy");
  v("median_J", x.median_J, "median seed energy");
  v("worst_J", x.worst_J, "worst seed's energy");
}
template <class V>
void fields(V& v, ThrowingStudyResults::IdpStep& x) {
  v("iteration", x.iteration, "iteration, counted over all passes");
  v("pass", x.pass, "pass");
  v("energy_J", x.energy_J, "energy after the iteration");
  v("violation", x.violation, "total constraint violation");
  v("region_rad_s", x.region_rad_s, "search half-width per joint");
  v("evaluations", x.evaluations, "simulations so far");
  v("improvements", x.improvements, "stage nodes improved");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Idp& x) {
  v("stages", x.stages, "stages P");
  v("steps_per_stage", x.steps_per_stage, "RK4 steps per stage");
  v("iterations", x.iterations, "iterations per pass");
  v("max_passes", x.max_passes, "budget of passes");
  v("tolerance", x.tolerance, "relative energy gain of a pass that counts as quiet");
  v("quiet_passes", x.quiet_passes, "quiet passes in a row that stop a seed");
  v("candidates", x.candidates, "candidates per stage node");
  v("shrink", x.shrink, "region factor per iteration");
  v("restore", x.restore, "region factor between passes");
  v("region_rad_s", x.region_rad_s, "initial half-width per joint");
  v("seed", x.seed, "first random seed");
  v("seeds", x.seeds, "seeds run");
  v("backoff", x.backoff, "normalised constraint back-off");
  v("threads", x.threads, "evaluation threads");
  v("converged", x.converged, "every seed converged");
  v("best_seed", x.best_seed, "the best seed");
  v("passes", x.passes, "passes of the best seed");
  v("last_gain", x.last_gain, "relative gain of the best seed's last pass");
  v("evaluations", x.evaluations, "simulations of all seeds");
  v("run_time_s", x.run_time_s, "wall time of all seeds");
  v("seed_runs", x.seed_runs, "every seed");
  v("spread", x.spread, "the seeds' energies");
  v("convergence", x.convergence, "the best seed's iterations");
  v.optional("first_order", x.first_order, "first-order optimality of the best seed's optimum");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Start& x) {
  v("name", x.name,
    "where SLSQP started: reference, idp, eq8, smooth N (eq. 8 changed by sine modes: the global "
    "phase), or a hop from the best so far");
  v("energy_J", x.energy_J, "energy of the local optimum it reached");
  v("feasible", x.feasible, "meets every constraint");
  v("converged", x.converged, "feasible with its first-order residual within the tolerance");
  v("kkt_residual", x.kkt_residual, "first-order residual / E per rad/s at its end");
  v("iterations", x.iterations, "gradient evaluations");
  v("restarts", x.restarts, "SLSQP restarts from its last iterate");
  v("return_code", x.return_code, "NLopt's return code of the last run");
}
template <class V>
void fields(V& v, ThrowingStudyResults::FirstOrder& x) {
  v("kkt_residual", x.kkt_residual,
    "|grad E + sum lambda_i grad g_i| / E per rad/s of node rate, multipliers >= 0 of the "
    "displacement equalities and the active inequalities");
  v("kkt_tolerance", x.kkt_tolerance, "converged: kkt_residual at most this");
  v("active_constraints", x.active_constraints, "inequalities within 1e-3 of their bound");
  v("binding", x.binding, "constraint kinds with a positive multiplier");
}
template <class V>
void fields(V& v, ThrowingStudyResults::NloptRun& x) {
  v("algorithm", x.algorithm, "the gradient method (when it ran)");
  v("return_code", x.return_code, "NLopt's return code (when it ran)");
  v("converged", x.converged,
    "feasible with its first-order residual within the tolerance (when it ran)");
  v("feasible", x.feasible, "meets every constraint (when it ran)");
  v("last_gain", x.last_gain, "relative change of the last iteration (when it ran)");
  v("iterations", x.iterations, "SLSQP iterations (when it ran)");
  v("simulations", x.simulations, "simulations (when it ran)");
  v("run_time_s", x.run_time_s, "wall time (when it ran)");
  v("max_evaluations", x.max_evaluations, "budget of iterations (when it ran)");
  v("max_time_s", x.max_time_s, "wall-time budget (when it ran)");
  v("ftol_rel", x.ftol_rel, "relative energy tolerance (when it ran)");
  v("xtol_rel", x.xtol_rel, "relative step tolerance (when it ran)");
  v("history_J", x.history_J, "energy per iteration (when it ran)");
  v("motion", x.motion, "the SLSQP optimum (when it ran)");
  v.optional("first_order", x.first_order, "the answer's first-order optimality");
  v.optional("starts", x.starts, "every SLSQP start and the local optimum it reached");
  v.optional("best_start", x.best_start, "the start whose local optimum is the answer");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Grid& x) {
  v("stages", x.stages, "control stages of this grid");
  v("steps_per_stage", x.steps_per_stage, "RK4 steps per stage (the step kept)");
  v("energy_J", x.energy_J, "the lowest throw feasible in the re-check on this grid");
  v("feasible", x.feasible, "that throw meets every limit, also in the re-check");
  v("converged", x.converged, "that throw is first-order converged on this grid");
  v("kkt_residual", x.kkt_residual, "its first-order residual / E per rad/s");
  v("from", x.from, "the start it descends from");
  v("run_time_s", x.run_time_s, "wall time of this grid's searches");
  v("simulations", x.simulations, "simulations of this grid's searches");
}
template <class V>
void fields(V& v, ThrowingStudyResults::ControlGrids& x) {
  v("status", x.status,
    "converged (the last doubling changed the energy by at most the tolerance), "
    "not_converged (still falling at the last grid) or not_refined (one grid)");
  v("tolerance", x.tolerance, "relative energy change per doubling that counts as converged");
  v("refinements", x.refinements, "doublings allowed after the first grid");
  v("grids", x.grids, "every grid, coarsest first");
  v("change_per_doubling_J", x.change_per_doubling_J,
    "energy of the finest grid minus the one before (null: one grid)");
  v("error_J", x.error_J,
    "estimated distance of the answer's energy to the limit (null: one grid, or not "
    "converged: not estimated while the energy still falls by more than the tolerance)");
  v("extrapolated_J", x.extrapolated_J,
    "the answer's energy minus that error (null: one grid, or not converged)");
  v("energy_first_grid_J", x.energy_first_grid_J, "SLSQP's answer on the first grid (IDP's)");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Nlopt& x) {
  v("ran", x.ran, "the gradient optimiser ran");
  v.inline_if(x.ran, x.run);
}
template <class V>
void fields(V& v, ThrowingStudyResults::Comparison& x) {
  v("optimiser", x.optimiser, "the optimiser");
  v("energy_J", x.energy_J, "energy of its optimum");
  v("mechanical_J", x.mechanical_J, "mechanical work");
  v("copper_J", x.copper_J, "copper losses");
  v("friction_J", x.friction_J, "friction losses");
  v("converged", x.converged, "stopped on its tolerance");
  v("simulations", x.simulations, "simulations");
  v("run_time_s", x.run_time_s, "wall time");
  v("feasible", x.feasible, "meets every constraint at the finer re-simulation");
  v("margins", x.margins, "margins at the finer re-simulation");
  v("binding", x.binding,
    "constraint kinds with a positive multiplier at the optimum (first order; the "
    "sensitivity part's binding list)");
  v("binding_rating", x.binding_rating, "the motor rating nearest its limit");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Verified& x) {
  v("feasible", x.feasible, "meets every constraint at the finer re-simulation");
  v("margins", x.margins, "margins at the finer re-simulation");
  v("worst_normalised", x.worst_normalised, "normalised worst values at the finer re-simulation");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Verification& x) {
  v("refinement", x.refinement, "the re-simulation's steps as a multiple of the plan's");
  v("idp", x.idp, "the IDP optimum re-simulated");
  v.optional("nlopt", x.nlopt, "the SLSQP optimum re-simulated (when it ran)");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Release& x) {
  v("time_s", x.time_s, "release time");
  v("ball_xy_m", x.ball_xy_m, "ball centre at release");
  v("ball_velocity_m_s", x.ball_velocity_m_s, "ball velocity at release");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Flight& x) {
  v("reaches", x.reaches, "the ball reaches the landing height");
  v("landing_height_m", x.landing_height_m, "landing height");
  v("duration_s", x.duration_s, "flight time");
  v("landing_xy_m", x.landing_xy_m, "where the ball lands");
  v("apex_m", x.apex_m, "apex height");
  v("t_s", x.t_s, "flight sample times");
  v("path_xy_m", x.path_xy_m, "ball centre [x, y] per sample");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Replay& x) {
  v("max_error_rad", x.max_error_rad, "largest angle error of the open-loop replay");
  v("tolerance_rad", x.tolerance_rad, "allowed error (check open_loop_replay)");
  v("integrator", x.integrator, "how the replay integrates");
  v("t_s", x.t_s, "replay sample times");
  v("q_rad", x.q_rad, "replayed [theta1..theta4] per sample");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Integration& x) {
  v("method", x.method, "the plan's integrator");
  v("steps_per_stage", x.steps_per_stage, "RK4 steps per stage");
  v("step_s", x.step_s, "RK4 step");
  v("fine_steps_factor", x.fine_steps_factor, "the accuracy check's step factor");
  v("energy_error_vs_fine_steps", x.energy_error_vs_fine_steps,
    "relative energy change with the finer steps");
  v("theta3_error_vs_fine_steps_rad", x.theta3_error_vs_fine_steps_rad,
    "theta3(tf) change with the finer steps");
}
template <class V>
void fields(V& v, ThrowingStudyResults::Optimised& x) {
  v("reference", x.reference, "the reference the saving is measured from");
  v("initial", x.initial, "the eq. 8 start");
  v.optional("reference_motion", x.reference_motion, "the repaired reference (when repaired)");
  v("optimum", x.optimum, "the IDP optimum");
  v("idp", x.idp, "the IDP runs");
  v("nlopt", x.nlopt, "the gradient optimiser");
  v.optional("control_grids", x.control_grids,
             "the answer on finer control grids (when the gradient optimiser ran)");
  v("answer", x.answer,
    "the optimiser whose throw is the answer: slsqp when its converged answer is feasible in the "
    "re-check and lower than IDP's, else idp");
  v("comparison", x.comparison, "the optimisers on equal terms");
  v("verification", x.verification, "the optima re-simulated with finer steps");
  v("release", x.release, "the release");
  v("flight", x.flight, "the flight after release");
  v("replay", x.replay, "the open-loop voltage replay");
  v("integration", x.integration, "the integration and its accuracy");
  v("run_time_s", x.run_time_s, "wall time of the study");
}
template <class V>
void fields(V& v, ThrowingStudyResults& x) {
  v("parameters", x.parameters, "the model and the task");
  v("assumptions", x.assumptions, "what the source leaves open, with the values used");
  v("limits", x.limits, "the constraints");
  v("energy_initial_J", x.energy_initial_J, "energy of the raw eq. 8 start");
  v("energy_reference_J", x.energy_reference_J,
    "energy of the reference (IDP's feasible start; no saving is quoted against it)");
  v("energy_optimised_J", x.energy_optimised_J, "energy of the answer");
  v("saving_percent", x.saving_percent,
    "the answer's saving against the eq. 8 start (null: no feasible answer)");
  v.inline_when("reference", x.run);  // the optimisers' part: there when its first key is
}

}  // namespace armstudy::studies
