// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The placement study's part of results.json as a typed value: what the pipeline
/// writes (app/placement_pipeline.cpp fills it from the Result) and what the report and
/// `armstudy merge` read back. `fields` names every key once: report/results_fields.hpp
/// turns it into the writer, the strict reader and the schema (results.schema.json). SI;
/// keys ending in _deg are degrees; positions are in the arm's frame A unless a key says
/// otherwise (root_xy_m: the root in the line frame P, see geometry.hpp).
///
/// A checked motion's energy_J is the adaptive quadrature's (converge.hpp, quadrature.hpp)
/// with its error estimate energy_error_J. A motion whose energy is withheld (a line on the
/// inner circle, or a quadrature that did not converge) has energy_J and peak_torque_Nm
/// null, singular_trajectory true and the note kSingularNote; its saving is null. A motion
/// whose energy converged but whose sampled peak torque does not settle (a line on or near a
/// boundary) has its energy, peak_torque_Nm null, singular_trajectory true and the note
/// kPeakUnboundedNote.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "studies/replay_results.hpp"

namespace armstudy::studies::placement {

/// the cycle-time objective (cycle_time_map.hpp): a limit's largest use by a fastest motion.
/// This and CycleTimeAt sit outside StudyResults: a class nested in another, with default
/// member initialisers, is not default-constructible before the enclosing class is complete
/// for clang, so std::optional<CycleTimeAt> inside StudyResults did not compile there (the
/// fuzz targets' build); GCC accepts it.
struct CycleTimeLimitUse {
  std::string kind;
  int joint = 1;
  double ratio = 0;
  bool binding = false;
};
/// the least traversal time at one placement, converged by the time-optimal study
struct CycleTimeAt {
  bool solved = false;
  std::string message;
  std::optional<double> duration_s, error_s, grid_duration_s;
  int grid_points = 0;
  std::vector<CycleTimeLimitUse> limits;
};

/// the energy of a fastest motion (cycle_time_result.hpp, FastMotionEnergy)
struct FastEnergy {
  double energy_J = 0, error_J = 0, duration_s = 0;
  int grid_points = 0;
};
/// a placement of the trade-off between the cycle time and the energy (CycleEnergyPoint)
struct TradeOffPoint {
  std::string kind;
  std::array<double, 2> root_xy_m{};
  double x_s_m = 0, phi_deg = 0, cycle_time_s = 0, energy_J = 0, fast_motion_energy_J = 0;
};

struct StudyResults {
  using Pair = std::array<double, 2>;
  /// which motion program and elbow configuration an entry belongs to
  struct Id {
    std::string program;
    int configuration = 1;
  };
  struct ConvergenceRow {
    int samples = 0;
    double energy_J = 0, peak_torque_Nm = 0;
  };
  /// the adaptive quadrature of one motion's energy (quadrature.hpp)
  struct Quadrature {
    double energy_J = 0, error_J = 0, tolerance_rel = 0;
    bool converged = false;
    int intervals = 0, evaluations = 0;
  };
  /// the doubling of one motion's samples (converge.hpp)
  struct EnergyConvergence {
    bool converged = false, touches_boundary = false, singular = false;
    int samples = 0;
    double rel_change = 0, peak_torque_rel_change = 0, tolerance_rel = 0;
    std::vector<ConvergenceRow> rows;
    std::optional<bool> peak_converged;
    std::optional<Quadrature> quadrature;
  };
  /// energy and peak torque of a motion, null (and a note) when it is singular
  struct Metrics {
    double energy_J = 0;
    std::optional<double> energy_error_J;
    std::optional<Pair> peak_torque_Nm;
    std::optional<int> energy_samples;
    std::optional<bool> singular_trajectory;
    std::optional<std::string> note;
    std::optional<EnergyConvergence> energy_convergence;
  };
  /// the counts of one program and configuration's sweep (limits applied)
  struct SweepCounts {
    int total = 0, unreachable = 0, singular = 0, over_limit = 0, feasible = 0, thesis_admitted = 0,
        thesis_rejected_by_exact_check = 0, exact_accepted_outside_thesis = 0;
  };
  /// the counts of the geometric sweep, the same for every program and configuration
  struct GeometryCounts {
    int total = 0, unreachable = 0, singular = 0, clear = 0, thesis_admitted = 0,
        thesis_rejected_by_exact_check = 0, exact_accepted_outside_thesis = 0;
  };
  struct ThesisIntervals {
    int x_s_case = 0;
    double x_s_init_m = 0, x_s_fin_m = 0;
  };
  struct Series {
    int stride = 1;
    std::vector<double> t_s, q1_rad, q2_rad, qd1_rad_s, qd2_rad_s, qdd1_rad_s2, qdd2_rad_s2,
        tau1_Nm, tau2_Nm, power1_W, power2_W, energy_J;
  };
  struct Active {
    std::string constraint;  ///< inner_clearance, outer_clearance, torque_limit, power_limit
    std::optional<int> joint;
    double slack = 0;
  };
  struct Decision {
    std::string binding;
    std::vector<Active> active;
    double inner_slack_m = 0, outer_slack_m = 0, margin_m = 0;
    std::optional<int> joint;
    Pair torque_slack_Nm{}, power_slack_W{};
    bool set_by_margin = false;
  };
  struct Refinement {
    std::optional<std::string> method;
    double final_tolerance_rel = 0, target_rel = 0;
    bool converged = false;
    int evaluations = 0;
    double x_s_error_m = 0, phi_error_deg = 0, energy_error_J = 0;
    double root_error_m = 0;  ///< root_xy_m's: hypot(x_s_error_m, x_s_m phi_error in rad)
  };
  struct MarginOptimum : Metrics {
    double x_s_m = 0, phi_deg = 0;
    Pair root_xy_m{};
    std::string binding;
    bool refine_converged = false;
    double refine_tolerance_rel = 0;
    double x_s_error_m = 0, phi_error_deg = 0;
  };
  struct MarginPoint {
    double margin_m = 0;
    bool found = false;
    std::optional<MarginOptimum> optimum;  ///< its keys sit beside found, when found
  };
  struct Optimum : Id, Metrics {
    double x_s_m = 0, phi_deg = 0;
    Pair root_xy_m{};
    double grid_energy_J = 0, grid_x_s_m = 0, grid_phi_deg = 0, min_abs_sin_elbow = 0,
           boundary_distance_m = 0;
    Pair peak_power_W{};
    double signed_work_J = 0;
    bool singular = false;
    int refine_evaluations = 0;
    Decision decided_by;
    Refinement refinement;
    std::vector<MarginPoint> margin_sensitivity;
    Pair line_start_m{}, line_end_m{};
    SweepCounts counts;
    Series series;
  };
  struct Unsolved : Id {
    std::string reason;
    SweepCounts counts;
  };
  struct ThesisBest : Id, Metrics {
    double x_s_m = 0, phi_deg = 0;
    Pair root_xy_m{};
    std::string status;
    bool singular = false;
    double boundary_distance_m = 0, min_abs_sin_elbow = 0;
  };
  struct Evaluation : Id, Metrics {
    std::string label;
    double x_s_m = 0, phi_deg = 0;
    Pair root_xy_m{};
    std::string status;
    bool singular = false;
    double boundary_distance_m = 0, min_abs_sin_elbow = 0, saving_J = 0, saving_percent = 0;
    Pair line_start_m{}, line_end_m{};
    std::optional<Series> series;
  };
  struct Curve : Id {
    double x_s_m = 0;
    std::vector<double> phi_deg, energy_J;
    std::string status;
  };
  struct Excluded {
    std::string what;
    std::vector<Pair> peak_torque_Nm;
    std::vector<double> energy_J;
  };
  struct Pareto : Id {
    int joint = 1;
    std::vector<Pair> peak_torque_Nm;
    std::vector<double> energy_J, x_s_m, phi_deg;
    std::vector<bool> singular;
    Excluded excluded;
  };
  struct Map : Id {
    std::vector<double> x_m, y_m;
    std::optional<Pair> optimum_xy_m;
    std::string encoding;
    std::vector<std::string> energy_J_rows, status_rows;
  };
  struct SampleRow {
    int samples = 0;
    double energy_J = 0;
  };
  struct Convergence : Id {
    std::vector<SampleRow> rows;
  };
  struct Replay : Id, ReplayResults {};
  /// the cycle-time objective (cycle_time_map.hpp): a limit's largest use by a fastest
  /// motion, and the least traversal time at one placement (at namespace scope: see there)
  using LimitUse = CycleTimeLimitUse;
  using CycleTimeAt = placement::CycleTimeAt;
  struct CycleTimeOptimum {
    bool found = false;
    std::string reason;
    std::optional<Pair> root_xy_m, grid_root_xy_m;
    std::optional<double> x_s_m, phi_deg, root_error_m, duration_s, duration_error_s, grid_time_s,
        fine_time_s, inner_slack_m, outer_slack_m;
    std::optional<bool> set_by_margin;
    int refinement_solves = 0;
    std::optional<CycleTimeAt> converged;
    std::optional<FastEnergy> fast_motion_energy;
  };
  struct CycleTimeMap {
    std::vector<double> x_m, y_m;
    std::string encoding;
    std::vector<std::string> time_s_rows, status_rows;
    int nodes_solved = 0, grid_points = 0, threads = 1;
    double seconds = 0;
  };
  struct EnergyOptimumTime {
    std::string program;
    double x_s_m = 0, phi_deg = 0, energy_J = 0;
    Pair root_xy_m{};
    CycleTimeAt cycle_time;
    std::optional<FastEnergy> fast_motion_energy;
    std::optional<double> energy_at_time_optimum_J, energy_at_time_optimum_error_J;
    std::string status_at_time_optimum;
    std::vector<TradeOffPoint> front;
  };
  struct CycleTime {
    int configuration = 1;
    CycleTimeMap map;
    CycleTimeOptimum optimum;
    std::vector<EnergyOptimumTime> at_energy_optima;
  };
  struct CycleTimeSection {
    Pair velocity_limit_rad_s{}, torque_limit_Nm{};
    std::optional<Pair> acceleration_limit_rad_s2;
    std::vector<CycleTime> configurations;
  };

  double lmax_m = 0, length_m = 0, length_fraction = 0, duration_s = 0;
  int samples = 0;
  int thesis_divisions = 0;
  double singularity_margin_m = 0;
  Pair annulus_m{};
  std::optional<Pair> torque_limits_Nm, power_limits_W;
  ThesisIntervals thesis_intervals;
  std::optional<GeometryCounts> geometry_counts;
  std::vector<Optimum> optima;
  std::vector<Unsolved> unsolved;
  std::vector<ThesisBest> thesis_search;
  std::vector<Evaluation> evaluations;
  std::vector<Curve> curves;
  std::vector<Pareto> pareto;
  std::vector<Map> maps;
  std::optional<Convergence> convergence;
  std::vector<Replay> mujoco_replay;
  std::optional<CycleTimeSection> cycle_time;
  double solve_seconds = 0;
  long long samples_evaluated = 0;
  std::optional<std::vector<std::string>> arm_model;
};

template <class V>
void fields(V& v, StudyResults::Id& x) {
  v("program", x.program, "motion program (core/motion_program.hpp)");
  v("configuration", x.configuration, "elbow configuration (1 or 2)");
}
template <class V>
void fields(V& v, StudyResults::ConvergenceRow& x) {
  v("samples", x.samples, "samples of the motion");
  v("energy_J", x.energy_J, "energy at these samples");
  v("peak_torque_Nm", x.peak_torque_Nm, "peak |torque| over both joints at these samples");
}
template <class V>
void fields(V& v, StudyResults::Quadrature& x) {
  v("energy_J", x.energy_J, "energy by adaptive Gauss-Kronrod (G7-K15) quadrature");
  v("error_J", x.error_J, "its error estimate (sum over the intervals of |K15 - G7|)");
  v("tolerance_rel", x.tolerance_rel, "the relative error asked for");
  v("converged", x.converged, "error_J <= tolerance_rel * energy_J");
  v("intervals", x.intervals, "final subintervals");
  v("evaluations", x.evaluations, "integrand evaluations");
}
template <class V>
void fields(V& v, StudyResults::EnergyConvergence& x) {
  v("converged", x.converged,
    "the sampled energy changed by < tolerance_rel and the sampled peak torque by < 1e-3 on "
    "one doubling");
  v("touches_boundary", x.touches_boundary, "the line is on a boundary of the annulus");
  v("singular", x.singular, "the energy or the peak torque is withheld (see the motion's note)");
  v("samples", x.samples, "samples of the reported metrics");
  v("rel_change", x.rel_change, "relative energy change at the last doubling");
  v("peak_torque_rel_change", x.peak_torque_rel_change,
    "relative peak torque change at the last doubling");
  v("tolerance_rel", x.tolerance_rel, "the relative tolerance asked for");
  v("rows", x.rows, "every doubling tried, coarsest first");
  v.optional("peak_converged", x.peak_converged,
             "the sampled peak torque changed by < 1e-3 on the last doubling");
  v.optional("quadrature", x.quadrature,
             "the energy by adaptive quadrature (absent: the line is on the inner circle)");
}
template <class V>
void fields(V& v, StudyResults::Metrics& x) {
  v("energy_J", x.energy_J, "energy of the motion (null: withheld or unreachable)");
  v.optional("energy_error_J", x.energy_error_J,
             "error estimate of energy_J (its adaptive quadrature; when checked and printed)");
  v("peak_torque_Nm", x.peak_torque_Nm,
    "peak |torque| [j1, j2] (null: unbounded, singular pose, or unreachable)");
  v.optional("energy_samples", x.energy_samples,
             "samples where the energy converged (when checked)");
  v.optional("singular_trajectory", x.singular_trajectory,
             "the motion's energy or peak torque is withheld");
  v.optional("note", x.note, "what is withheld and why (present when something is)");
  v.optional("energy_convergence", x.energy_convergence,
             "the doubling of the samples (when checked)");
}
template <class V>
void fields(V& v, StudyResults::SweepCounts& x) {
  v("total", x.total, "candidates of the full sweep (x_s grid x phi in [0, 180] deg)");
  v("unreachable", x.unreachable, "candidates partly outside the annulus");
  v("singular", x.singular, "candidates closer to a boundary than the margin");
  v("over_limit", x.over_limit, "clear candidates over a torque or power limit");
  v("feasible", x.feasible, "admissible candidates");
  v("thesis_admitted", x.thesis_admitted,
    "candidates of the thesis's own grid (its intervals 4.7-4.13, thesis_divisions steps each)");
  v("thesis_rejected_by_exact_check", x.thesis_rejected_by_exact_check,
    "of those, rejected by the exact check (unreachable or singular)");
  v("exact_accepted_outside_thesis", x.exact_accepted_outside_thesis,
    "candidates the exact check accepts outside the thesis's phi interval");
}
template <class V>
void fields(V& v, StudyResults::GeometryCounts& x) {
  v("total", x.total, "candidates of the full sweep (x_s grid x phi in [0, 180] deg)");
  v("unreachable", x.unreachable, "candidates partly outside the annulus");
  v("singular", x.singular, "candidates closer to a boundary than the margin");
  v("clear", x.clear, "candidates clear of both boundaries (limits not applied)");
  v("thesis_admitted", x.thesis_admitted,
    "candidates of the thesis's own grid (its intervals 4.7-4.13, thesis_divisions steps each)");
  v("thesis_rejected_by_exact_check", x.thesis_rejected_by_exact_check,
    "of those, rejected by the exact check (unreachable or singular)");
  v("exact_accepted_outside_thesis", x.exact_accepted_outside_thesis,
    "candidates the exact check accepts outside the thesis's phi interval");
}
template <class V>
void fields(V& v, StudyResults::ThesisIntervals& x) {
  v("x_s_case", x.x_s_case, "the thesis's case of the start-point interval");
  v("x_s_init_m", x.x_s_init_m, "start of the thesis's start-point interval");
  v("x_s_fin_m", x.x_s_fin_m, "end of the thesis's start-point interval");
}
template <class V>
void fields(V& v, StudyResults::Series& x) {
  v("stride", x.stride, "every stride-th sample of the motion (<= 101 points, the last included)");
  v("t_s", x.t_s, "time");
  v("q1_rad", x.q1_rad, "joint 1 angle");
  v("q2_rad", x.q2_rad, "joint 2 angle");
  v("qd1_rad_s", x.qd1_rad_s, "joint 1 velocity");
  v("qd2_rad_s", x.qd2_rad_s, "joint 2 velocity");
  v("qdd1_rad_s2", x.qdd1_rad_s2, "joint 1 acceleration");
  v("qdd2_rad_s2", x.qdd2_rad_s2, "joint 2 acceleration");
  v("tau1_Nm", x.tau1_Nm, "joint 1 torque");
  v("tau2_Nm", x.tau2_Nm, "joint 2 torque");
  v("power1_W", x.power1_W, "joint 1 power (signed)");
  v("power2_W", x.power2_W, "joint 2 power (signed)");
  v("energy_J", x.energy_J, "cumulative |power1| + |power2|");
}
template <class V>
void fields(V& v, StudyResults::Active& x) {
  v("constraint", x.constraint, "inner_clearance, outer_clearance, torque_limit or power_limit");
  v("joint", x.joint, "the joint of a limit (1-based; null for a clearance)");
  v("slack", x.slack, "bound minus value (m for a clearance, N m or W for a limit)");
}
template <class V>
void fields(V& v, StudyResults::Decision& x) {
  v("binding", x.binding,
    "the first active constraint in the fixed order of `active` (interior: none)");
  v("active", x.active,
    "every constraint within tolerance at the optimum, in a fixed order (inner clearance, "
    "outer clearance, joint 1's torque and power, joint 2's), the same for a configuration and "
    "its mirror image");
  v("inner_slack_m", x.inner_slack_m, "clearance to the inner circle minus the margin");
  v("outer_slack_m", x.outer_slack_m, "clearance to the outer circle minus the margin");
  v("margin_m", x.margin_m, "the singularity margin");
  v("joint", x.joint, "the joint of a binding limit (1-based; null otherwise)");
  v("torque_slack_Nm", x.torque_slack_Nm, "limit minus peak |torque| [j1, j2] (null: no limit)");
  v("power_slack_W", x.power_slack_W, "limit minus peak |power| [j1, j2] (null: no limit)");
  v("set_by_margin", x.set_by_margin,
    "a clearance margin is active: the optimum is set by the margin");
}
template <class V>
void fields(V& v, StudyResults::Refinement& x) {
  v("method", x.method, "the refinement's stages (null: not refined)");
  v("final_tolerance_rel", x.final_tolerance_rel,
    "relative energy a final restart still gained (null: not refined)");
  v("target_rel", x.target_rel, "the relative gain below which the refinement is converged");
  v("converged", x.converged, "final_tolerance_rel <= target_rel");
  v("evaluations", x.evaluations, "energy evaluations of the refinement");
  v("x_s_error_m", x.x_s_error_m,
    "error of x_s_m: its distance from the minimum of the converged energy (quadratic fit "
    "with its truncation and the quadrature's error; null: not refined or no fit)");
  v("phi_error_deg", x.phi_error_deg, "error of phi_deg, the same");
  v("root_error_m", x.root_error_m,
    "error of root_xy_m, the root's distance from where the minimum puts it: "
    "sqrt(x_s_error_m^2 + (x_s_m phi_error)^2), phi_error in rad, the root (-x_s cos phi, "
    "x_s sin phi) moving by those two orthogonal steps (null: either is)");
  v("energy_error_J", x.energy_error_J,
    "how far energy_J may lie from the least converged energy: its quadrature error plus "
    "final_tolerance_rel times the energy (null: not refined)");
}
template <class V>
void fields(V& v, StudyResults::MarginOptimum& x) {
  fields(v, static_cast<StudyResults::Metrics&>(x));
  v("x_s_m", x.x_s_m, "the optimum's line start abscissa (when found)");
  v("phi_deg", x.phi_deg, "the optimum's line direction (when found)");
  v("root_xy_m", x.root_xy_m, "the optimum's root in the line frame (when found)");
  v("binding", x.binding, "what decides the optimum (when found)");
  v("refine_converged", x.refine_converged, "the refinement converged (when found)");
  v("refine_tolerance_rel", x.refine_tolerance_rel,
    "relative gain of the last restart (when found)");
  v("x_s_error_m", x.x_s_error_m,
    "error of x_s_m: its distance from the minimum of the converged energy at this margin "
    "(when found; null: not refined)");
  v("phi_error_deg", x.phi_error_deg, "error of phi_deg, the same (when found)");
}
template <class V>
void fields(V& v, StudyResults::MarginPoint& x) {
  v("margin_m", x.margin_m, "the clearance margin");
  v("found", x.found, "an admissible optimum exists at this margin");
  v.inline_if(x.found, x.optimum);
}
template <class V>
void fields(V& v, StudyResults::Optimum& x) {
  fields(v, static_cast<StudyResults::Id&>(x));
  fields(v, static_cast<StudyResults::Metrics&>(x));
  v("x_s_m", x.x_s_m, "line start abscissa");
  v("phi_deg", x.phi_deg, "line direction");
  v("root_xy_m", x.root_xy_m, "root (X, Y) in the line frame");
  v("grid_energy_J", x.grid_energy_J, "energy of the sweep's best candidate");
  v("grid_x_s_m", x.grid_x_s_m, "the sweep's best candidate: x_s");
  v("grid_phi_deg", x.grid_phi_deg, "the sweep's best candidate: phi");
  v("min_abs_sin_elbow", x.min_abs_sin_elbow, "smallest |sin q2| along the line");
  v("boundary_distance_m", x.boundary_distance_m, "distance of the line to the annulus's boundary");
  v("peak_power_W", x.peak_power_W, "peak |power| [j1, j2]");
  v("signed_work_J", x.signed_work_J, "signed work of both joints (0 rest to rest)");
  v("singular", x.singular, "not feasible or the motion is singular");
  v("refine_evaluations", x.refine_evaluations, "energy evaluations of the refinement");
  v("decided_by", x.decided_by, "what decides the optimum");
  v("refinement", x.refinement, "the local refinement");
  v("margin_sensitivity", x.margin_sensitivity,
    "the optimum re-solved at other margins (when a clearance binds)");
  v("line_start_m", x.line_start_m, "line start in the arm's frame");
  v("line_end_m", x.line_end_m, "line end in the arm's frame");
  v("counts", x.counts, "the sweep's counts of this program and configuration");
  v("series", x.series, "the optimum's motion");
}
template <class V>
void fields(V& v, StudyResults::Unsolved& x) {
  fields(v, static_cast<StudyResults::Id&>(x));
  v("reason", x.reason, "why no admissible placement exists");
  v("counts", x.counts, "the sweep's counts of this program and configuration");
}
template <class V>
void fields(V& v, StudyResults::ThesisBest& x) {
  fields(v, static_cast<StudyResults::Id&>(x));
  fields(v, static_cast<StudyResults::Metrics&>(x));
  v("x_s_m", x.x_s_m, "line start abscissa");
  v("phi_deg", x.phi_deg, "line direction");
  v("root_xy_m", x.root_xy_m, "root (X, Y) in the line frame");
  v("status", x.status, "unreachable, singular, over_limit or feasible");
  v("singular", x.singular, "status is singular");
  v("boundary_distance_m", x.boundary_distance_m, "distance of the line to the annulus's boundary");
  v("min_abs_sin_elbow", x.min_abs_sin_elbow, "smallest |sin q2| along the line");
}
template <class V>
void fields(V& v, StudyResults::Evaluation& x) {
  fields(v, static_cast<StudyResults::Id&>(x));
  fields(v, static_cast<StudyResults::Metrics&>(x));
  v("label", x.label, "the case's name for the placement");
  v("x_s_m", x.x_s_m, "line start abscissa");
  v("phi_deg", x.phi_deg, "line direction");
  v("root_xy_m", x.root_xy_m, "root (X, Y) in the line frame");
  v("status", x.status, "unreachable, singular, over_limit or feasible");
  v("singular", x.singular, "status is singular");
  v("boundary_distance_m", x.boundary_distance_m, "distance of the line to the annulus's boundary");
  v("min_abs_sin_elbow", x.min_abs_sin_elbow, "smallest |sin q2| along the line");
  v("saving_J", x.saving_J, "energy minus the optimum's (null: not comparable)");
  v("saving_percent", x.saving_percent,
    "saving_J as a share of this energy (null: not comparable)");
  v("line_start_m", x.line_start_m, "line start in the arm's frame");
  v("line_end_m", x.line_end_m, "line end in the arm's frame");
  v.optional("series", x.series, "the motion (when reachable)");
}
template <class V>
void fields(V& v, StudyResults::Curve& x) {
  fields(v, static_cast<StudyResults::Id&>(x));
  v("x_s_m", x.x_s_m, "the start abscissa of the curve");
  v("phi_deg", x.phi_deg, "line directions");
  v("energy_J", x.energy_J, "energy per direction (null: unreachable)");
  v("status", x.status,
    "one status character per direction: '.' unreachable, 's' singular, 'x' over a limit, 'o' "
    "feasible");
}
template <class V>
void fields(V& v, StudyResults::Excluded& x) {
  v("what", x.what, "what the excluded points are");
  v("peak_torque_Nm", x.peak_torque_Nm, "peak |torque| [j1, j2] per point");
  v("energy_J", x.energy_J, "energy per point");
}
template <class V>
void fields(V& v, StudyResults::Pareto& x) {
  fields(v, static_cast<StudyResults::Id&>(x));
  v("joint", x.joint, "the joint whose peak torque the front trades (1 or 2)");
  v("peak_torque_Nm", x.peak_torque_Nm, "peak |torque| [j1, j2] per point");
  v("energy_J", x.energy_J, "energy per point");
  v("x_s_m", x.x_s_m, "line start abscissa per point");
  v("phi_deg", x.phi_deg, "line direction per point");
  v("singular", x.singular, "per point (all false: the front holds admissible placements only)");
  v("excluded", x.excluded, "the same front over the candidates inside the margin");
}
template <class V>
void fields(V& v, StudyResults::Map& x) {
  fields(v, static_cast<StudyResults::Id&>(x));
  v("x_m", x.x_m, "node abscissae X in the line frame");
  v("y_m", x.y_m, "node ordinates Y in the line frame");
  v("optimum_xy_m", x.optimum_xy_m, "the optimum's root (null: none)");
  v("encoding", x.encoding, "how the rows are written");
  v("energy_J_rows", x.energy_J_rows,
    "row j is y_m[j]: energies at 4 significant digits, '-' where unreachable");
  v("status_rows", x.status_rows, "row j is y_m[j]: one status character per node");
}
template <class V>
void fields(V& v, StudyResults::SampleRow& x) {
  v("samples", x.samples, "samples of the motion");
  v("energy_J", x.energy_J, "energy at these samples");
}
template <class V>
void fields(V& v, StudyResults::Convergence& x) {
  fields(v, static_cast<StudyResults::Id&>(x));
  v("rows", x.rows, "the first optimum's energy as the samples double");
}
template <class V>
void fields(V& v, StudyResults::Replay& x) {
  fields(v, static_cast<StudyResults::Id&>(x));
  fields(v, static_cast<ReplayResults&>(x));
}
template <class V>
void fields(V& v, StudyResults::LimitUse& x) {
  v("kind", x.kind, "velocity, torque or acceleration");
  v("joint", x.joint, "the joint (1-based)");
  v("ratio", x.ratio, "largest |value| / limit over the densely resampled fastest motion");
  v("binding", x.binding, "ratio >= 1 - 1e-3: the fastest motion runs on this limit");
}
template <class V>
void fields(V& v, StudyResults::CycleTimeAt& x) {
  v("solved", x.solved, "the time-optimal study found a motion");
  v("message", x.message, "its summary, or why no motion exists");
  v("duration_s", x.duration_s,
    "the least traversal time, extrapolated over the exact solver's grids (null: unsolved)");
  v("error_s", x.error_s, "its stated error, the extrapolation's (null: unsolved)");
  v("grid_duration_s", x.grid_duration_s, "the exact solver's time on its grid (null: unsolved)");
  v("grid_points", x.grid_points, "that grid's nodes");
  v("limits", x.limits, "every limit's largest use by the fastest motion");
}
template <class V>
void fields(V& v, FastEnergy& x) {
  v("energy_J", x.energy_J,
    "integral of |tau1 qd1| + |tau2 qd2| dt over the time-optimal motion (the energy "
    "objective's measure), on the exact solver's grid with every interval halved");
  v("error_J", x.error_J, "its change from the unhalved grid (its error estimate)");
  v("duration_s", x.duration_s, "that motion's time on the halved grid");
  v("grid_points", x.grid_points, "the halved grid's nodes");
}
template <class V>
void fields(V& v, TradeOffPoint& x) {
  v("kind", x.kind, "energy_optimum, time_optimum or map_node");
  v("root_xy_m", x.root_xy_m, "the root (X, Y) in the line frame");
  v("x_s_m", x.x_s_m, "its line start abscissa");
  v("phi_deg", x.phi_deg, "its line direction");
  v("cycle_time_s", x.cycle_time_s,
    "the least cycle time there on the converged grid (uniform, not extrapolated)");
  v("energy_J", x.energy_J,
    "the energy objective there: the program's motion in the case's duration (the sweep's "
    "samples)");
  v("fast_motion_energy_J", x.fast_motion_energy_J,
    "the energy of the fastest motion there (the same solve)");
}
template <class V>
void fields(V& v, StudyResults::CycleTimeOptimum& x) {
  v("found", x.found, "an admissible placement with a motion exists");
  v("reason", x.reason, "why not ('' when found)");
  v("root_xy_m", x.root_xy_m, "the fastest root (X, Y) in the line frame (null: not found)");
  v("x_s_m", x.x_s_m, "its line start abscissa");
  v("phi_deg", x.phi_deg, "its line direction");
  v("root_error_m", x.root_error_m,
    "the compass search's last step, at which no admissible point around the root was faster "
    "on the converged grid: the location's resolution");
  v("duration_s", x.duration_s, "the least cycle time there, extrapolated (the answer)");
  v("duration_error_s", x.duration_error_s,
    "its error: the extrapolation's plus the time's largest change over the last compass ring");
  v("grid_root_xy_m", x.grid_root_xy_m, "the map's fastest node");
  v("grid_time_s", x.grid_time_s, "its time on the map's coarse grid");
  v("fine_time_s", x.fine_time_s, "the optimum's time on the refinement's grid");
  v("inner_slack_m", x.inner_slack_m, "clearance to the inner circle minus the margin");
  v("outer_slack_m", x.outer_slack_m, "clearance to the outer circle minus the margin");
  v("set_by_margin", x.set_by_margin, "a clearance slack is within 2 root_error_m of 0");
  v("refinement_solves", x.refinement_solves, "exact solves of the compass search");
  v("converged", x.converged, "the time-optimal study at the optimum (null: not found)");
  v("fast_motion_energy", x.fast_motion_energy,
    "what the fastest motion at the optimum costs in energy (null: not computed)");
}
template <class V>
void fields(V& v, StudyResults::CycleTimeMap& x) {
  v("x_m", x.x_m, "node abscissae X in the line frame (the energy maps' nodes)");
  v("y_m", x.y_m, "node ordinates Y in the line frame");
  v("encoding", x.encoding, "how the rows are written");
  v("time_s_rows", x.time_s_rows,
    "row j is y_m[j]: least times at 6 significant digits, '-' where not admissible or unsolved");
  v("status_rows", x.status_rows, "row j is y_m[j]: one status character per node");
  v("nodes_solved", x.nodes_solved, "admissible nodes with a motion");
  v("grid_points", x.grid_points, "the exact solver's grid at each node (the coarse grid)");
  v("threads", x.threads, "threads the map ran on");
  v("seconds", x.seconds, "wall time of the map");
}
template <class V>
void fields(V& v, StudyResults::EnergyOptimumTime& x) {
  v("program", x.program, "the energy optimum's motion program");
  v("x_s_m", x.x_s_m, "its line start abscissa");
  v("phi_deg", x.phi_deg, "its line direction");
  v("root_xy_m", x.root_xy_m, "its root in the line frame");
  v("energy_J", x.energy_J, "its energy (fixed duration, the program's motion)");
  v("cycle_time", x.cycle_time, "the least cycle time at that placement");
  v("fast_motion_energy", x.fast_motion_energy,
    "what the fastest motion at that placement costs in energy (null: not computed)");
  v("energy_at_time_optimum_J", x.energy_at_time_optimum_J,
    "the program's motion in the case's duration at the cycle-time optimum of the "
    "configuration, by adaptive quadrature (null: no time optimum)");
  v("energy_at_time_optimum_error_J", x.energy_at_time_optimum_error_J,
    "its quadrature error estimate");
  v("status_at_time_optimum", x.status_at_time_optimum,
    "the cycle-time optimum's status for the energy objective (feasible, over_limit, ...; "
    "'' without a time optimum)");
  v("front", x.front,
    "the Pareto front of (least cycle time, this program's energy in the case's duration) over "
    "the map's nodes admissible for both objectives and both optima, by increasing time");
}
template <class V>
void fields(V& v, StudyResults::CycleTime& x) {
  v("configuration", x.configuration, "elbow configuration (1 or 2)");
  v("map", x.map, "the least cycle time over root locations");
  v("optimum", x.optimum, "the fastest placement, refined and converged");
  v("at_energy_optima", x.at_energy_optima,
    "the least cycle time at each energy optimum of this configuration");
}
template <class V>
void fields(V& v, StudyResults::CycleTimeSection& x) {
  v("velocity_limit_rad_s", x.velocity_limit_rad_s, "velocity limits [j1, j2]");
  v("torque_limit_Nm", x.torque_limit_Nm, "torque limits [j1, j2]");
  v("acceleration_limit_rad_s2", x.acceleration_limit_rad_s2,
    "acceleration limits [j1, j2] (null: none)");
  v("configurations", x.configurations, "the objective per configuration");
}
template <class V>
void fields(V& v, StudyResults& x) {
  v("lmax_m", x.lmax_m, "4 sqrt(L1 L2) (4.6)");
  v("length_m", x.length_m, "line length L");
  v("length_fraction", x.length_fraction, "L / Lmax");
  v("duration_s", x.duration_s, "duration of the motion");
  v("samples", x.samples, "samples of the sweep's motions");
  v("thesis_divisions", x.thesis_divisions,
    "steps of the thesis's own grid in x_S and in phi (thesis_search)", {{"minimum", 1}});
  v("singularity_margin_m", x.singularity_margin_m, "least clearance to a boundary of the annulus");
  v("annulus_m", x.annulus_m, "[inner, outer] radii of the reachable annulus");
  v("torque_limits_Nm", x.torque_limits_Nm, "torque limits [j1, j2] (null: none)");
  v("power_limits_W", x.power_limits_W, "power limits [j1, j2] (null: none)");
  v("thesis_intervals", x.thesis_intervals, "the thesis's start-point interval");
  v.optional("geometry_counts", x.geometry_counts,
             "the geometric sweep (x_s grid x phi in [0, 180] deg), the same for every program and "
             "configuration");
  v("optima", x.optima, "the refined optimum of each program and configuration that has one");
  v("unsolved", x.unsolved, "programs and configurations without an admissible placement");
  v("thesis_search", x.thesis_search,
    "the least energy among the thesis's own candidates (4.7-4.13), whatever their status");
  v("evaluations", x.evaluations, "the fixed placements the case asked for");
  v("curves", x.curves, "energy over direction at the optimum's start abscissa");
  v("pareto", x.pareto,
    "Pareto fronts of peak torque and energy (thinned to steps of >= 0.2 % in energy)");
  v("maps", x.maps, "energy and status over root locations");
  v.optional("convergence", x.convergence, "the first optimum's energy as the samples double");
  v("mujoco_replay", x.mujoco_replay, "each optimum's torques applied open loop in MuJoCo");
  v.optional("cycle_time", x.cycle_time,
             "the cycle-time objective: the least traversal time under joint limits over root "
             "locations and its optimum (present when the case asks for it)");
  v("solve_seconds", x.solve_seconds, "wall time of the solve");
  v("samples_evaluated", x.samples_evaluated, "motion samples evaluated in all");
  v.optional("arm_model", x.arm_model,
             "an arm read from a URDF or MJCF file (arm.model): the file, the plane and gravity "
             "it was solved in, and where each limit came from (the model or the case); absent "
             "for an arm written out in the case");
}

}  // namespace armstudy::studies::placement
