// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The placement study's answer: plain data for the scene (replay of every optimum and
/// evaluated placement) and the report (tables, maps, curves, Pareto front).
///
/// Frames (see geometry.hpp): the arm's frame A (root at the origin, the thesis's lines
/// start at (x_s, 0)); the line frame P (origin at the line's start, X along the line).

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/motion_program.hpp"
#include "studies/common.hpp"
#include "studies/placement/arm2.hpp"
#include "studies/placement/converge.hpp"
#include "studies/placement/cycle_time_result.hpp"

namespace armstudy::studies::placement {

/// Class of a candidate line, most severe first.
enum class CandidateStatus : std::uint8_t {
  kUnreachable,  ///< part of the line lies outside the annulus: no motion exists
  kSingular,     ///< inside, but closer to a boundary than the singularity margin
  kOverLimit,    ///< clear of the boundaries, but breaks a torque or power limit
  kFeasible,     ///< an admissible placement
};

/// One character per status, as in the map rows: '.', 's', 'x', 'o'.
char status_char(CandidateStatus s);
/// "unreachable", "singular", "over_limit", "feasible".
const char* status_name(CandidateStatus s);

/// What decides an optimum.
enum class Binding : std::uint8_t {
  kInterior,        ///< no constraint active: a stationary point of the energy
  kInnerClearance,  ///< the line's clearance to the inner circle |L1 - L2| equals the margin
  kOuterClearance,  ///< the line's clearance to the outer circle L1 + L2 equals the margin
  kTorqueLimit,     ///< a joint's peak |torque| equals its limit
  kPowerLimit,      ///< a joint's peak |power| equals its limit
};

/// A constraint within the activity tolerance of its bound at an optimum.
struct ActiveConstraint {
  Binding kind = Binding::kInterior;
  int joint = -1;    ///< 0 or 1 for a limit, else -1
  double slack = 0;  ///< m, N m or W: bound minus value
};

/// The constraints' slacks at an optimum, every active one, and the one named as binding.
struct Decision {
  /// the first of `active` (interior when none): a configuration and its mirror image,
  /// whose slacks differ only by rounding, name the same one
  Binding binding = Binding::kInterior;
  int joint = -1;  ///< 0 (root) or 1 (elbow) for a limit, else -1
  /// every constraint within tolerance, in a fixed order (inner clearance, outer clearance,
  /// then joint 1's torque and power, joint 2's torque and power), never by slack
  std::vector<ActiveConstraint> active;
  /// a clearance margin is among the active constraints: the margin sets the optimum
  bool margin_active() const {
    for (const ActiveConstraint& a : active)
      if (a.kind == Binding::kInnerClearance || a.kind == Binding::kOuterClearance) return true;
    return false;
  }
  double inner_slack = 0;  ///< m, clearance to the inner circle minus the margin
  double outer_slack = 0;  ///< m, clearance to the outer circle minus the margin
  double torque_slack[2] = {std::numeric_limits<double>::quiet_NaN(),
                            std::numeric_limits<double>::quiet_NaN()};  ///< N m (NaN: no limit)
  double power_slack[2] = {std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::quiet_NaN()};  ///< W (NaN: no limit)
};

/// A candidate placement with its metrics (for one program and configuration).
struct Candidate {
  double x_s = 0;                                  ///< m
  double phi = 0;                                  ///< rad
  Eigen::Vector2d root = Eigen::Vector2d::Zero();  ///< m, root (X, Y) in the line frame (4.14)
  CandidateStatus status = CandidateStatus::kUnreachable;
  double boundary_distance = 0;  ///< m, exact (< 0: unreachable)
  double inner_clearance = 0;    ///< m, r_min - |L1 - L2| (exact)
  double outer_clearance = 0;    ///< m, L1 + L2 - r_max (exact)
  double min_abs_sin = 0;        ///< exact smallest |sin q2| along the line
  LineMetrics metrics;           ///< energy, signed work, peaks (unset when unreachable)
  /// the energy by adaptive quadrature and the peaks converged by doubling (optima,
  /// evaluations, the thesis's best); convergence.energy_withheld(): no energy or saving of
  /// this candidate is printed; convergence.peak_withheld(): no peak torque or power
  EnergyConvergence convergence;
  /// the metrics a report prints: at the samples where the doubling converged, with the
  /// quadrature's energy, or the sweep's when the candidate was not checked
  const LineMetrics& reported_metrics() const {
    return convergence.checked ? convergence.metrics : metrics;
  }
};

/// The refined optimum at one clearance margin (the margin sensitivity curve).
struct MarginPoint {
  double margin = 0;  ///< m
  bool found = false;
  Candidate optimum;
  Decision decision;
  bool refine_converged = false;
  double refine_tolerance_rel = 0;
  /// m, rad: the optimum's distance from the minimum of the converged energy at this margin
  /// (refine.hpp; NaN: not refined)
  double x_s_error = std::numeric_limits<double>::quiet_NaN();
  double phi_error = std::numeric_limits<double>::quiet_NaN();
};

/// Where the arm and the line are, for a renderer: everything in the arm's frame A.
struct Placement {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();               ///< m, line start S
  Eigen::Vector2d end = Eigen::Vector2d::Zero();                 ///< m, line end F = S + L u (8.4)
  Eigen::Vector2d root_in_line_frame = Eigen::Vector2d::Zero();  ///< m, (X, Y)
};

/// Candidate counts of one sweep.
struct Counts {
  int total = 0;  ///< candidates of the full sweep (x_s grid x phi in [0, 180] deg)
  int unreachable = 0;
  int singular = 0;
  int over_limit = 0;
  int feasible = 0;
  int thesis_total = 0;     ///< candidates the thesis's intervals (4.7-4.13) generate
  int thesis_rejected = 0;  ///< of those, rejected by the exact check (unreachable or singular)
  int exact_outside_thesis = 0;  ///< full-sweep candidates the exact check accepts that lie
                                 ///< outside the thesis's phi interval
};

/// The energy over root locations (X, Y) in the line frame, on a node grid; row-major,
/// row j is Y = y[j], column i is X = x[i]. Y >= 0 only: the half-plane Y < 0 is the mirror
/// image with configurations 1 and 2 swapped.
struct EnergyMap {
  std::vector<double> x, y;             ///< m, node coordinates
  std::vector<float> energy;            ///< J (NaN where unreachable), ny * nx
  std::vector<CandidateStatus> status;  ///< ny * nx
  std::vector<float> peak_torque;       ///< N m, max over both joints (NaN if unreachable)
};

/// Energy versus direction angle at one start abscissa (the thesis's Fig. 9.11 etc.).
struct PhiCurve {
  double x_s = 0;              ///< m
  std::vector<double> phi;     ///< rad
  std::vector<double> energy;  ///< J (NaN where unreachable)
  std::vector<CandidateStatus> status;
};

/// A point of a Pareto front: the least energy of any reachable candidate whose peak torque
/// of the front's joint is at most peak_torque[joint].
struct ParetoPoint {
  double peak_torque[2] = {0, 0};  ///< N m, peak |tau| of joints 1 and 2 of this candidate
  double energy = 0;               ///< J
  double x_s = 0, phi = 0;         ///< m, rad
  bool singular = false;  ///< closer to a boundary than the margin (only in pareto_excluded)
};

/// Everything found for one motion program and configuration.
struct ProgramConfig {
  core::MotionProgram program = core::MotionProgram::kCycloidal;
  int configuration = 1;
  Counts counts;
  bool found = false;  ///< an admissible optimum exists
  std::string reason;  ///< why not, when !found
  Candidate grid;      ///< best feasible candidate of the sweep
  Candidate refined;   ///< after the local refinement (== grid when not refined)
  int refine_evaluations = 0;
  std::string refine_method;        ///< the refinement's stages ("" when not refined)
  double refine_tolerance_rel = 0;  ///< relative energy a final restart still gained
  bool refine_converged = false;    ///< refine_tolerance_rel <= 1e-7
  /// m, rad: the refined optimum's distance from the minimum of the converged energy
  /// (refine.hpp; NaN: not refined, or no quadratic could be fitted)
  double x_s_error = std::numeric_limits<double>::quiet_NaN();
  double phi_error = std::numeric_limits<double>::quiet_NaN();
  /// J, the part of energy_error() from the resolution of a nearly active limit's continuous
  /// peak (refine.hpp; 0 without one)
  double limit_energy_error = 0;
  /// J: how far the printed energy may lie from the least converged energy, the refined
  /// optimum's quadrature error plus refine_tolerance_rel times its energy plus the limit's
  /// resolution carried to the energy (NaN: not refined, or its energy withheld)
  double energy_error() const {
    if (refine_method.empty() || refined.convergence.energy_withheld())
      return std::numeric_limits<double>::quiet_NaN();
    return refined.convergence.energy_error + refine_tolerance_rel * refined.convergence.energy +
           limit_energy_error;
  }
  Decision decision;  ///< what decides the refined optimum
  /// the optimum re-solved at a range of margins (when a clearance binds), by margin
  std::vector<MarginPoint> margin_sensitivity;
  Placement placement;  ///< of the refined optimum
  TimeSeries series;    ///< of the refined optimum
  bool thesis_found = false;
  Candidate thesis_best;  ///< least energy among the thesis's own candidates, any status
  EnergyMap map;
  PhiCurve curve;  ///< at the refined optimum's own x_s (or the thesis's first x_s)
  /// Pareto fronts of (peak torque of joint j, energy), j = 0 (root), 1 (elbow), over the
  /// admissible candidates only (feasible, energy converged) and the refined optimum; by
  /// increasing peak torque of that joint and decreasing energy
  std::array<std::vector<ParetoPoint>, 2> pareto;
  /// the same front over the inadmissible candidates inside the margin whose energy
  /// converged: drawn distinctly, never part of the front
  std::array<std::vector<ParetoPoint>, 2> pareto_excluded;
};

/// A fixed placement the case asked for, with its saving against the optimum.
struct Evaluation {
  std::string label;
  core::MotionProgram program = core::MotionProgram::kCycloidal;
  int configuration = 1;
  Candidate candidate;
  Placement placement;
  TimeSeries series;          ///< empty when unreachable
  bool has_saving = false;    ///< both energies converged (quadrature within its tolerance)
  double saving = 0;          ///< J, energy minus the refined optimum's
  double saving_percent = 0;  ///< % of this placement's energy
};

struct Result {
  Status status = Status::kSolved;
  std::string message;
  double lmax = 0;                 ///< m, 4 sqrt(L1 L2) (4.6)
  double length = 0;               ///< m
  double inner = 0, outer = 0;     ///< m, annulus radii
  double xs_init = 0, xs_fin = 0;  ///< m, the thesis's start-point interval
  int thesis_xs_case = 0;
  std::vector<ProgramConfig> cases;  ///< programs x configurations, in the spec's order
  std::vector<Evaluation> evaluations;
  /// the cycle-time objective per configuration (empty: the spec has no cycle_time)
  std::vector<CycleTime> cycle_time;
  std::vector<ConvergenceRow> convergence;  ///< of the first found optimum
  std::vector<Check> checks;
  double seconds = 0;  ///< wall time of the solve
  long long samples_evaluated = 0;
};

}  // namespace armstudy::studies::placement
