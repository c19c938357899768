// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/placement/solve.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <thread>

#include <nlopt.hpp>

#include "core/check.hpp"
#include "studies/grid.hpp"
#include "studies/placement/candidate.hpp"
#include "studies/placement/checks.hpp"
#include "studies/placement/cycle_time_map.hpp"
#include "studies/placement/geometry.hpp"
#include "studies/placement/parallel.hpp"
#include "studies/placement/peaks.hpp"
#include "studies/placement/printed_limits.hpp"
#include "studies/placement/refine.hpp"

namespace armstudy::studies::placement {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
using core::kDeg;
// relative quadrature error below which a sampled energy counts as converged
constexpr double kEnergyTol = 1e-4;
// relative error the adaptive quadrature of a checked candidate's energy is asked for
constexpr double kQuadTol = 1e-9;

// which candidate set a geometric candidate belongs to
enum class Set : std::uint8_t { kSweep, kThesis, kMap };

struct GeoCandidate {
  double x_s = 0, phi = 0;
  Line line;
  LineCheck check;
  Set set = Set::kSweep;
  int i = 0, j = 0;            // sweep: (x_s index, phi index); map: (X index, Y index)
  bool thesis_admits = false;  // sweep only: phi inside the thesis's interval
};

std::string fmt(double v, int precision = 4) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(precision);
  os << v;
  return os.str();
}

// a checked candidate: its energy by adaptive quadrature (to kQuadTol, printed within
// kEnergyTol), its sampled peaks converged by doubling from the spec's samples; with a
// torque or power limit, a settled peak is the continuous motion's (peaks.hpp), what the
// limits are kept on
EnergyConvergence converged(const Spec& spec, const Arm2& arm, core::MotionProgram program,
                            const Candidate& c, int configuration) {
  EnergyConvergence ec = check_energy(
      arm, program, spec.duration, spec.length, thesis_line(c.x_s, c.phi), configuration,
      spec.samples, c.boundary_distance < kTouch, c.inner_clearance < kTouch, kEnergyTol, kQuadTol);
  if ((spec.torque_limit || spec.power_limit) && !ec.peak_withheld()) {
    const MotionPeaks p = continuous_peaks(arm, program, spec.duration, spec.length,
                                           thesis_line(c.x_s, c.phi), configuration, spec.samples);
    if (p.finite) {
      for (int j = 0; j < 2; ++j) {
        ec.metrics.peak_torque[j] = std::max(ec.metrics.peak_torque[j], p.torque[j]);
        ec.metrics.peak_power[j] = std::max(ec.metrics.peak_power[j], p.power[j]);
      }
      ec.peak_resolution = p.resolution;
    }
  }
  return ec;
}

// a sampled energy whose embedded error estimate is within the tolerance
bool energy_ok(const LineMetrics& m) { return m.energy_error_estimate() <= kEnergyTol; }

Placement placement_of(const Line& line, double L) {
  Placement p;
  p.start = line.start;
  p.end = line.start + L * line.dir;
  p.root_in_line_frame = Eigen::Vector2d(
      -line.start.dot(line.dir), -line.start.dot(Eigen::Vector2d(-line.dir.y(), line.dir.x())));
  return p;
}

// the active constraints after the first, in words: "; the power limit of joint 2 (2 W) is
// active too"
std::string also_active(const Spec& spec, const Decision& d) {
  std::string out;
  for (size_t k = 1; k < d.active.size(); ++k) {
    const ActiveConstraint& a = d.active[k];
    std::string what;
    switch (a.kind) {
      case Binding::kInnerClearance: what = "the clearance margin to the inner circle"; break;
      case Binding::kOuterClearance: what = "the clearance margin to the outer circle"; break;
      case Binding::kTorqueLimit:
        what = "the torque limit of joint " + std::to_string(a.joint + 1) + " (" +
               fmt((*spec.torque_limit)[size_t(a.joint)], 4) + " N m)";
        break;
      case Binding::kPowerLimit:
        what = "the power limit of joint " + std::to_string(a.joint + 1) + " (" +
               fmt((*spec.power_limit)[size_t(a.joint)], 4) + " W)";
        break;
      case Binding::kInterior: break;
    }
    out += (out.empty() ? "" : ", ") + what;
  }
  return out.empty() ? "" : "; " + out + (d.active.size() > 2 ? " are" : " is") + " active too";
}

// what decides an optimum, in words (the summary sentence)
std::string decision_sentence(const Spec& spec, const Annulus& an, const ProgramConfig& c) {
  const Decision& d = c.decision;
  std::ostringstream os;
  switch (d.binding) {
    case Binding::kInterior:
      os << "interior: no constraint binds (clearances "
         << fmt(d.inner_slack + spec.singularity_margin, 4) << " m to the inner and "
         << fmt(d.outer_slack + spec.singularity_margin, 4) << " m to the outer circle)";
      return os.str();
    case Binding::kInnerClearance:
    case Binding::kOuterClearance: {
      const bool inner = d.binding == Binding::kInnerClearance;
      os << "the optimum is set by the " << fmt(spec.singularity_margin, 4)
         << " m clearance margin to the "
         << (inner ? "inner circle |L1 - L2| = " + fmt(an.inner, 3)
                   : "outer circle L1 + L2 = " + fmt(an.outer, 3))
         << " m, not by the physics";
      const MarginPoint* lo = nullptr;
      const MarginPoint* hi = nullptr;
      for (const MarginPoint& m : c.margin_sensitivity) {
        if (!m.found || m.optimum.convergence.energy_withheld()) continue;
        if (!lo || m.margin < lo->margin) lo = &m;
        if (!hi || m.margin > hi->margin) hi = &m;
      }
      if (lo && hi && lo != hi)
        os << ": its energy is " << fmt(lo->optimum.reported_metrics().energy) << " J at a "
           << fmt(lo->margin, 4) << " m margin and " << fmt(hi->optimum.reported_metrics().energy)
           << " J at " << fmt(hi->margin, 4) << " m";
      os << also_active(spec, d);
      return os.str();
    }
    case Binding::kTorqueLimit:
      os << "the optimum is set by the torque limit of joint " << d.joint + 1 << " ("
         << fmt((*spec.torque_limit)[size_t(d.joint)], 4) << " N m)" << also_active(spec, d);
      return os.str();
    case Binding::kPowerLimit:
      os << "the optimum is set by the power limit of joint " << d.joint + 1 << " ("
         << fmt((*spec.power_limit)[size_t(d.joint)], 4) << " W)" << also_active(spec, d);
      return os.str();
  }
  return "";
}

// a (program, configuration) pair: indices into spec.programs and a configuration
struct Pc {
  int program;
  int configuration;
};

// what the stages of one solve share: the arm, the candidate grid and the sweep's metrics
struct SolveState {
  const Spec& spec;
  Arm2 arm;
  Annulus an;
  double L = 0;
  int threads = 1;
  std::vector<double> xs;      // the thesis's start points of the sweep
  std::vector<double> phis;    // the sweep's direction angles, [0, pi]
  std::vector<double> mx, my;  // the map's nodes
  std::vector<GeoCandidate> geo;
  size_t map_begin = 0;  // the first map node in geo
  std::vector<ProgramTable> tables;
  std::vector<Pc> pcs;
  std::vector<int> reachable;        // geo indices of the reachable candidates
  std::vector<LineMetrics> metrics;  // [pc * geo.size() + k]
  std::vector<char> conv_ok;         // same index: the sampled energy converged
  double hx = 0;                     // the refinement's x_s step

  explicit SolveState(const Spec& s) : spec(s) {}
  const LineMetrics& metric(size_t pc, size_t k) const { return metrics[pc * geo.size() + k]; }
  bool converged_at(size_t pc, size_t k) const { return conv_ok[pc * geo.size() + k] != 0; }
  double hphi_at(double x_s) const { return std::max(spec.phi_step, hx / std::max(x_s, 1e-3)); }

  size_t add(double x_s, double phi, Set set, int i, int j) {
    GeoCandidate g;
    g.x_s = x_s;
    g.phi = phi;
    g.line = thesis_line(x_s, phi);
    g.check = check_line(arm.L1, arm.L2, g.line, L);
    g.set = set;
    g.i = i;
    g.j = j;
    geo.push_back(g);
    return geo.size() - 1;
  }

  // the sweep's candidate k of pair pc as a classified candidate
  Candidate candidate(size_t pc, size_t k) const {
    Candidate c;
    c.x_s = geo[k].x_s;
    c.phi = geo[k].phi;
    c.root = root_in_line_frame(c.x_s, c.phi);
    c.boundary_distance = geo[k].check.boundary_distance;
    c.inner_clearance = geo[k].check.r_min - an.inner;
    c.outer_clearance = an.outer - geo[k].check.r_max;
    c.min_abs_sin = geo[k].check.min_abs_sin;
    if (c.boundary_distance >= -kTouch) c.metrics = metric(pc, k);
    c.status = classify(spec, c.boundary_distance, c.metrics);
    return c;
  }
};

void check_spec(const Spec& spec) {
  ARM_THROW_UNLESS(spec.samples >= 3,
                   "samples per trajectory " << spec.samples << " should be >= 3");
  ARM_THROW_UNLESS(spec.nx_s >= 1, "nx_s " << spec.nx_s << " should be >= 1");
  ARM_THROW_UNLESS(spec.phi_step > 0, "phi step " << spec.phi_step << " rad should be > 0");
  ARM_THROW_UNLESS(spec.singularity_margin > 0,
                   "singularity margin " << spec.singularity_margin << " m should be > 0");
  ARM_THROW_UNLESS(spec.map_nx >= 2 && spec.map_ny >= 2, "map needs >= 2 x 2 nodes");
}

// geometric candidates: the full sweep, the thesis's own phi grids, the map nodes; the
// program tables and the (program, configuration) pairs
void build_candidates(SolveState& s, const XsInterval& xsi) {
  const Spec& spec = s.spec;
  const double L = s.L;
  // the thesis's start points: x_s from init down to fin in nx_s steps (step 3 of Ch. 4)
  s.xs = xsi.init == xsi.fin ? std::vector<double>{xsi.init}
                             : linspace(xsi.init, xsi.fin, spec.nx_s + 1);
  // the full sweep of direction angles: [0, pi] in steps of phi_step, pi included
  for (int k = 0; k * spec.phi_step < core::kPi - 1e-9; ++k) s.phis.push_back(k * spec.phi_step);
  s.phis.push_back(core::kPi);

  const double tiny = 1e-9;
  for (size_t i = 0; i < s.xs.size(); ++i) {
    const PhiInterval pi = thesis_phi_interval(s.an, L, s.xs[i]);
    for (size_t j = 0; j < s.phis.size(); ++j) {
      const size_t k = s.add(s.xs[i], s.phis[j], Set::kSweep, int(i), int(j));
      s.geo[k].thesis_admits = s.phis[j] >= pi.init - tiny && s.phis[j] <= pi.fin + tiny;
    }
  }
  // the thesis's own grid (steps 3-5 of its Ch. 4): x_s over its interval and phi over
  // [phi_init, phi_fin] in thesis_divisions equal steps each, both ends included
  const int nd = spec.thesis_divisions;
  const std::vector<double> xs_thesis =
      xsi.init == xsi.fin ? std::vector<double>{xsi.init} : linspace(xsi.init, xsi.fin, nd + 1);
  for (size_t i = 0; i < xs_thesis.size(); ++i) {
    const PhiInterval pi = thesis_phi_interval(s.an, L, xs_thesis[i]);
    if (!(pi.fin >= pi.init)) continue;
    const int steps = pi.fin - pi.init < tiny ? 0 : nd;
    for (int k = 0; k <= steps; ++k)
      s.add(xs_thesis[i], k == steps ? pi.fin : pi.init + k * (pi.fin - pi.init) / nd, Set::kThesis,
            int(i), k);
  }
  // map nodes over the region where both ends can be reached: X in [L - R, R], Y in [0, R]
  s.mx = linspace(L - s.an.outer, s.an.outer, spec.map_nx);
  s.my = linspace(0.0, s.an.outer, spec.map_ny);
  s.map_begin = s.geo.size();
  for (int j = 0; j < spec.map_ny; ++j) {
    for (int i = 0; i < spec.map_nx; ++i) {
      const Eigen::Vector2d lp = line_of_root({s.mx[i], s.my[j]});
      s.add(lp[0], lp[1], Set::kMap, i, j);
    }
  }

  // program tables and the (program, configuration) pairs
  for (const auto p : spec.programs)
    s.tables.push_back(make_program_table(p, spec.duration, L, spec.samples));
  for (size_t p = 0; p < spec.programs.size(); ++p)
    for (const int c : spec.configurations) s.pcs.push_back({int(p), c});
  s.hx = std::max({s.xs.size() > 1 ? std::abs(s.xs[0] - s.xs[1]) : 0.0, s.mx[1] - s.mx[0],
                   s.my[1] - s.my[0], 1e-4});
}

// the sweep: every reachable geometric candidate for every pair, on all threads, then the
// samples doubled where the sampled energy has not converged; returns the samples evaluated
long long sweep(SolveState& s, const ProgressFn& progress) {
  const Spec& spec = s.spec;
  const auto& geo = s.geo;
  for (size_t k = 0; k < geo.size(); ++k)
    if (geo[k].check.boundary_distance >= -kTouch) s.reachable.push_back(int(k));
  const long n_tasks = long(s.reachable.size()) * long(s.pcs.size());
  s.metrics.resize(geo.size() * s.pcs.size());
  parallel_for(n_tasks, s.threads, progress, 0.0, 0.8, "placement sweep", [&](long t) {
    const size_t pc = size_t(t / long(s.reachable.size()));
    const int k = s.reachable[size_t(t % long(s.reachable.size()))];
    s.metrics[pc * geo.size() + k] =
        evaluate_line(s.arm, s.tables[s.pcs[pc].program], geo[k].line, s.pcs[pc].configuration);
  });
  long long samples = n_tasks * spec.samples;

  // candidates clear of the margin whose sampled energy is not converged (the embedded
  // estimate above 1e-4): samples doubled until it converges; inside the margin they are
  // inadmissible and stay unconverged (no number is drawn for them)
  s.conv_ok.assign(s.metrics.size(), 0);
  std::vector<long> redo;
  for (size_t pc = 0; pc < s.pcs.size(); ++pc) {
    for (const int k : s.reachable) {
      const size_t m = pc * geo.size() + size_t(k);
      s.conv_ok[m] = energy_ok(s.metrics[m]);
      if (!s.conv_ok[m] && s.metrics[m].finite() &&
          geo[size_t(k)].check.boundary_distance >= spec.singularity_margin - kMarginTol)
        redo.push_back(long(m));
    }
  }
  std::atomic<long long> redo_samples{0};
  parallel_for(long(redo.size()), s.threads, progress, 0.8, 0.82, "placement sweep convergence",
               [&](long t) {
                 const size_t m = size_t(redo[size_t(t)]);
                 const size_t pc = m / geo.size(), k = m % geo.size();
                 const EnergyConvergence c = converge_energy(
                     s.arm, spec.programs[size_t(s.pcs[pc].program)], spec.duration, s.L,
                     geo[k].line, s.pcs[pc].configuration, spec.samples, false, kEnergyTol);
                 long long n = 0;
                 for (const auto& row : c.rows) n += row.samples;
                 redo_samples += n;
                 if (c.converged) {
                   s.metrics[m] = c.metrics;
                   s.conv_ok[m] = 1;
                 }
               });
  return samples + redo_samples.load();
}

// the least-energy candidates of one pair: the optimum (feasible, converged, any set) and
// the thesis's own (its candidates only, by its rule)
struct PairBest {
  long best = -1, thesis_best = -1;
};

// counts of the full sweep, the thesis's candidates and their disagreements; the optimum
PairBest count_candidates(const SolveState& s, size_t pc, const std::vector<CandidateStatus>& st,
                          Counts& n) {
  PairBest b;
  for (size_t k = 0; k < s.geo.size(); ++k) {
    const bool accepted =
        st[k] == CandidateStatus::kFeasible || st[k] == CandidateStatus::kOverLimit;
    if (s.geo[k].set == Set::kSweep) {
      ++n.total;
      switch (st[k]) {
        case CandidateStatus::kUnreachable: ++n.unreachable; break;
        case CandidateStatus::kSingular: ++n.singular; break;
        case CandidateStatus::kOverLimit: ++n.over_limit; break;
        case CandidateStatus::kFeasible: ++n.feasible; break;
      }
      if (accepted && !s.geo[k].thesis_admits) ++n.exact_outside_thesis;
    } else if (s.geo[k].set == Set::kThesis) {
      ++n.thesis_total;
      if (!accepted) ++n.thesis_rejected;
      if (st[k] != CandidateStatus::kUnreachable && s.metric(pc, k).finite() &&
          (b.thesis_best < 0 ||
           s.metric(pc, k).energy < s.metric(pc, size_t(b.thesis_best)).energy))
        b.thesis_best = long(k);
    }
    // the optimum: the least energy of every feasible candidate of every set whose
    // sampled energy has converged
    if (st[k] == CandidateStatus::kFeasible && s.converged_at(pc, k) &&
        (b.best < 0 || s.metric(pc, k).energy < s.metric(pc, size_t(b.best)).energy))
      b.best = long(k);
  }
  return b;
}

EnergyMap energy_map(const SolveState& s, size_t pc, const std::vector<CandidateStatus>& st) {
  EnergyMap map;
  map.x = s.mx;
  map.y = s.my;
  map.energy.resize(size_t(s.spec.map_nx) * s.spec.map_ny);
  map.status.resize(map.energy.size());
  map.peak_torque.resize(map.energy.size());
  for (size_t m = 0; m < map.energy.size(); ++m) {
    const size_t k = s.map_begin + m;
    map.status[m] = st[k];
    const bool ok = st[k] != CandidateStatus::kUnreachable && s.converged_at(pc, k);
    const LineMetrics& lm = s.metric(pc, k);
    map.energy[m] = ok ? float(lm.energy) : float(kNaN);
    map.peak_torque[m] = ok ? float(std::max(lm.peak_torque[0], lm.peak_torque[1])) : float(kNaN);
  }
  return map;
}

// why a pair has no optimum, in words
std::string no_optimum_reason(const Spec& spec, const Annulus& an, const Counts& n) {
  return "no candidate keeps the line " + fmt(spec.singularity_margin) +
         " m inside the reachable annulus [" + fmt(an.inner, 3) + ", " + fmt(an.outer, 3) + "] m" +
         (spec.torque_limit || spec.power_limit ? " within the actuator limits" : "") +
         "; of the " + std::to_string(n.total) + " sweep candidates " +
         std::to_string(n.unreachable) + " are unreachable, " + std::to_string(n.singular) +
         " inside the margin, " + std::to_string(n.over_limit) + " over a limit";
}

// the refined candidate r is not worse than the start c: by their converged energies (the
// refinement's objective) when both converged, else by the sampled ones
bool not_worse(const Candidate& r, const Candidate& c) {
  if (r.convergence.energy_converged() && c.convergence.energy_converged())
    return r.convergence.energy <= c.convergence.energy;
  return r.metrics.energy <= c.metrics.energy;
}

// constrained local refinement of (x_s, phi) around the grid optimum (refine.hpp), what
// decides the optimum, its converged energy, placement and series
long long refine_optimum(const SolveState& s, size_t pc, ProgramConfig& out) {
  const Spec& spec = s.spec;
  const ProgramTable& table = s.tables[s.pcs[pc].program];
  long long samples = 0;
  with_continuous_peaks(spec, s.arm, table, out.configuration, out.grid);
  out.grid.convergence = converged(spec, s.arm, out.program, out.grid, out.configuration);
  out.refined = out.grid;
  if (spec.refine) {
    const Refinement rf = refine_constrained(spec, s.arm, table, out.configuration, out.grid, s.hx,
                                             s.hphi_at(out.grid.x_s));
    out.refine_evaluations = rf.evaluations;
    out.refine_method = rf.method;
    out.refine_tolerance_rel = rf.tolerance_rel;
    out.refine_converged = rf.converged;
    if (rf.best.status == CandidateStatus::kFeasible) {
      Candidate r = rf.best;
      r.convergence = converged(spec, s.arm, out.program, r, out.configuration);
      // (a grid point that breaks a limit between its samples is no fallback)
      if (out.grid.status != CandidateStatus::kFeasible || not_worse(r, out.grid)) {
        out.refined = r;
        out.limit_energy_error = rf.limit_energy_error;
        out.x_s_error = rf.x_s_error;
        out.phi_error = rf.phi_error;
      }
    }
    // (the second pass's quadratures counted as table.size() samples each)
    samples += long(rf.evaluations) * spec.samples;
  }
  out.decision = decide(spec, out.refined);
  const Line line = thesis_line(out.refined.x_s, out.refined.phi);
  out.placement = placement_of(line, s.L);
  out.series = sample_series(s.arm, table, line, out.configuration);
  return samples;
}

// the best sweep candidate of pair pc clear of `margin` (converged, within the limits)
long best_clear_of(const SolveState& s, size_t pc, double margin) {
  long k_best = -1;
  for (size_t k = 0; k < s.geo.size(); ++k) {
    if (s.geo[k].check.boundary_distance < margin - kMarginTol) continue;
    const LineMetrics& m = s.metric(pc, k);
    if (!m.finite() || !s.converged_at(pc, k) || !within_limits(s.spec, m)) continue;
    if (k_best < 0 || m.energy < s.metric(pc, size_t(k_best)).energy) k_best = long(k);
  }
  return k_best;
}

// the optimum against the clearance margin, when a clearance decides it: the spec's margin
// and the sensitivity margins, each refined from the best sweep candidate clear of it
long long margin_sensitivity(const SolveState& s, size_t pc, ProgramConfig& out) {
  const Spec& spec = s.spec;
  const ProgramTable& table = s.tables[s.pcs[pc].program];
  long long samples = 0;
  std::vector<double> margins = spec.sensitivity_margins;
  margins.push_back(spec.singularity_margin);
  std::sort(margins.begin(), margins.end());
  margins.erase(std::unique(margins.begin(), margins.end(),
                            [](double a, double b) { return std::abs(a - b) < 1e-12; }),
                margins.end());
  for (const double m : margins) {
    if (!(m > 0) || m >= (s.an.outer - s.an.inner) / 2) continue;
    MarginPoint mp;
    mp.margin = m;
    if (std::abs(m - spec.singularity_margin) < 1e-12) {
      mp.found = true;
      mp.optimum = out.refined;
      mp.decision = out.decision;
      mp.refine_converged = out.refine_converged;
      mp.refine_tolerance_rel = out.refine_tolerance_rel;
      mp.x_s_error = out.x_s_error;
      mp.phi_error = out.phi_error;
      out.margin_sensitivity.push_back(mp);
      continue;
    }
    const long k0 = best_clear_of(s, pc, m);
    if (k0 < 0) {
      out.margin_sensitivity.push_back(mp);
      continue;
    }
    Spec sm = spec;
    sm.singularity_margin = m;
    const Candidate start = evaluate_candidate(sm, s.arm, table, out.configuration,
                                               s.geo[size_t(k0)].x_s, s.geo[size_t(k0)].phi);
    const Refinement rf =
        refine_constrained(sm, s.arm, table, out.configuration, start, s.hx, s.hphi_at(start.x_s));
    samples += long(rf.evaluations) * spec.samples;
    Candidate r = rf.best;
    r.convergence = converged(sm, s.arm, out.program, r, out.configuration);
    Candidate c0 = start;
    with_continuous_peaks(sm, s.arm, table, out.configuration, c0);
    c0.convergence = converged(sm, s.arm, out.program, c0, out.configuration);
    const bool refined = r.status == CandidateStatus::kFeasible &&
                         (c0.status != CandidateStatus::kFeasible || not_worse(r, c0));
    const Candidate& c = refined ? r : c0;
    mp.found = c.status == CandidateStatus::kFeasible;
    mp.optimum = c;
    mp.decision = decide(sm, c);
    mp.refine_converged = rf.converged;
    mp.refine_tolerance_rel = rf.tolerance_rel;
    if (refined) {
      mp.x_s_error = rf.x_s_error;
      mp.phi_error = rf.phi_error;
    }
    out.margin_sensitivity.push_back(mp);
  }
  return samples;
}

struct FrontPoint {
  const LineMetrics* m;
  double x_s, phi;
};

// the Pareto front of (peak torque of `joint`, energy) over pts (sorted in place)
std::vector<ParetoPoint> front_of(std::vector<FrontPoint>& pts, int joint, bool singular) {
  std::sort(pts.begin(), pts.end(), [&](const FrontPoint& a, const FrontPoint& b) {
    return a.m->peak_torque[joint] < b.m->peak_torque[joint];
  });
  std::vector<ParetoPoint> front;
  double e_min = kInf;
  for (const FrontPoint& fp : pts) {
    if (fp.m->energy < e_min * (1 - 1e-9)) {
      e_min = fp.m->energy;
      ParetoPoint pp;
      pp.peak_torque[0] = fp.m->peak_torque[0];
      pp.peak_torque[1] = fp.m->peak_torque[1];
      pp.energy = e_min;
      pp.x_s = fp.x_s;
      pp.phi = fp.phi;
      pp.singular = singular;
      front.push_back(pp);
    }
  }
  return front;
}

// Pareto fronts of (peak torque of one joint, energy) over the admissible candidates
// (feasible, energy converged) with the refined optimum; the candidates inside the
// margin make a separate, excluded front
void pareto_fronts(const SolveState& s, size_t pc, const std::vector<CandidateStatus>& st,
                   ProgramConfig& out) {
  std::vector<FrontPoint> admissible, excluded;
  for (size_t k = 0; k < s.geo.size(); ++k) {
    if (!s.converged_at(pc, k)) continue;
    if (st[k] == CandidateStatus::kFeasible)
      admissible.push_back({&s.metric(pc, k), s.geo[k].x_s, s.geo[k].phi});
    else if (st[k] == CandidateStatus::kSingular && s.geo[k].check.boundary_distance >= kTouch)
      excluded.push_back({&s.metric(pc, k), s.geo[k].x_s, s.geo[k].phi});
  }
  if (out.found) admissible.push_back({&out.refined.metrics, out.refined.x_s, out.refined.phi});
  for (int joint = 0; joint < 2; ++joint) {
    out.pareto[joint] = front_of(admissible, joint, false);
    out.pareto_excluded[joint] = front_of(excluded, joint, true);
  }
}

// energy versus phi at the refined optimum's own start point (or the thesis's first),
// through the optimum's own direction
long long energy_curve(const SolveState& s, size_t pc, ProgramConfig& out) {
  const Spec& spec = s.spec;
  const ProgramTable& table = s.tables[s.pcs[pc].program];
  out.curve.x_s = out.found ? out.refined.x_s : s.xs.front();
  std::vector<double> cphi = s.phis;
  if (out.found) {
    // the optimum itself and a finer comb around it (an optimum on the margin has only a
    // narrow admissible range of phi at its own x_s)
    cphi.push_back(out.refined.phi);
    for (int k = 1; k <= 20; ++k)
      for (const int side : {-1, 1})
        cphi.push_back(out.refined.phi + side * k * 0.05 * spec.phi_step);
    std::sort(cphi.begin(), cphi.end());
    cphi.erase(
        std::remove_if(cphi.begin(), cphi.end(), [](double p) { return p < 0 || p > core::kPi; }),
        cphi.end());
  }
  for (const double ph : cphi) {
    Candidate c = evaluate_candidate(spec, s.arm, table, out.configuration, out.curve.x_s, ph);
    out.curve.phi.push_back(ph);
    bool ok = c.status != CandidateStatus::kUnreachable && energy_ok(c.metrics);
    if (!ok && c.status != CandidateStatus::kUnreachable && c.metrics.finite() &&
        c.boundary_distance >= spec.singularity_margin - kMarginTol) {
      // as in the sweep: clear of the margin, samples doubled until the energy converges
      const EnergyConvergence ec =
          converge_energy(s.arm, out.program, spec.duration, s.L, thesis_line(c.x_s, c.phi),
                          out.configuration, spec.samples, false, kEnergyTol);
      if (ec.converged) {
        c.metrics = ec.metrics;
        ok = true;
      }
    }
    out.curve.energy.push_back(ok ? c.metrics.energy : kNaN);
    out.curve.status.push_back(c.status);
  }
  return long(cphi.size()) * spec.samples;
}

// one (program, configuration) pair: classify, count, optimum, thesis's optimum, map,
// refinement, margin sensitivity, Pareto front, curve
ProgramConfig solve_pair(const SolveState& s, size_t pc, long long& samples_evaluated) {
  const Spec& spec = s.spec;
  ProgramConfig out;
  out.program = spec.programs[s.pcs[pc].program];
  out.configuration = s.pcs[pc].configuration;
  std::vector<CandidateStatus> st(s.geo.size());
  for (size_t k = 0; k < s.geo.size(); ++k) {
    st[k] = classify(spec, s.geo[k].check.boundary_distance,
                     s.geo[k].check.boundary_distance >= -kTouch ? s.metric(pc, k) : LineMetrics{});
  }
  const PairBest b = count_candidates(s, pc, st, out.counts);
  if (b.thesis_best >= 0) {
    out.thesis_found = true;
    out.thesis_best = s.candidate(pc, size_t(b.thesis_best));
    out.thesis_best.convergence =
        converged(spec, s.arm, out.program, out.thesis_best, out.configuration);
    if (!out.thesis_best.convergence.energy_withheld())
      out.thesis_best.metrics = out.thesis_best.convergence.metrics;
  }
  out.map = energy_map(s, pc, st);
  if (b.best < 0) {
    out.found = false;
    out.reason = no_optimum_reason(spec, s.an, out.counts);
  } else {
    out.found = true;
    out.grid = s.candidate(pc, size_t(b.best));
    out.refined = out.grid;
    samples_evaluated += refine_optimum(s, pc, out);
    if (spec.refine && out.decision.margin_active())
      samples_evaluated += margin_sensitivity(s, pc, out);
  }
  pareto_fronts(s, pc, st, out);
  samples_evaluated += energy_curve(s, pc, out);
  return out;
}

// evaluations of fixed placements, with the saving of the optimum
void evaluate_fixed(const SolveState& s, Result& res) {
  const Spec& spec = s.spec;
  for (const EvaluationSpec& ev : spec.evaluations) {
    for (size_t pc = 0; pc < s.pcs.size(); ++pc) {
      const ProgramTable& table = s.tables[s.pcs[pc].program];
      Evaluation e;
      e.label = ev.label;
      e.program = spec.programs[s.pcs[pc].program];
      e.configuration = s.pcs[pc].configuration;
      e.candidate = evaluate_candidate(spec, s.arm, table, e.configuration, ev.x_s, ev.phi);
      if (e.candidate.status != CandidateStatus::kUnreachable) {
        e.candidate.convergence = converged(spec, s.arm, e.program, e.candidate, e.configuration);
        // the printed metrics are those at the samples where the doubling converged
        if (!e.candidate.convergence.energy_withheld())
          e.candidate.metrics = e.candidate.convergence.metrics;
      }
      const Line line = thesis_line(ev.x_s, ev.phi);
      e.placement = placement_of(line, s.L);
      if (e.candidate.status != CandidateStatus::kUnreachable) {
        const EnergyConvergence& ec = e.candidate.convergence;
        const int n = ec.touches_boundary || !ec.converged ? spec.samples : ec.samples;
        e.series = n == spec.samples
                       ? sample_series(s.arm, table, line, e.configuration)
                       : sample_series(s.arm, make_program_table(e.program, spec.duration, s.L, n),
                                       line, e.configuration);
      }
      const ProgramConfig& opt = res.cases[pc];
      // a saving only between energies that converged (a peak torque that does not settle
      // does not withhold it)
      if (opt.found && e.candidate.status != CandidateStatus::kUnreachable &&
          e.candidate.convergence.checked && e.candidate.convergence.energy_converged() &&
          opt.refined.convergence.energy_converged()) {
        e.has_saving = true;
        e.saving = e.candidate.metrics.energy - opt.refined.reported_metrics().energy;
        e.saving_percent = 100.0 * e.saving / e.candidate.metrics.energy;
      }
      res.evaluations.push_back(std::move(e));
    }
  }
}

// convergence of the first optimum's energy with samples per trajectory
void sample_convergence(const SolveState& s, Result& res) {
  for (const auto& c : res.cases) {
    if (!c.found) continue;
    const Line line = thesis_line(c.refined.x_s, c.refined.phi);
    for (const int n : {51, 101, 201, 401, 801, 1601, 3201}) {
      const ProgramTable t = make_program_table(c.program, s.spec.duration, s.L, n);
      res.convergence.push_back({n, evaluate_line(s.arm, t, line, c.configuration).energy});
    }
    break;
  }
}

// every program's sampled metrics of every candidate line, with the line's boundary distance
void check_signed_work(const SolveState& s, Result& res) {
  std::vector<std::pair<double, const LineMetrics*>> lines;
  for (size_t pc = 0; pc < s.pcs.size(); ++pc)
    for (size_t k = 0; k < s.geo.size(); ++k)
      lines.emplace_back(s.geo[k].check.boundary_distance, &s.metric(pc, k));
  res.checks.push_back(signed_work_check(s.spec, lines));
}

}  // namespace

// relative to each candidate's energy: near the margin the joint rates grow steeply and
// an absolute bound would only measure how close the grid comes to a singular pose
Check signed_work_check(const Spec& spec,
                        const std::vector<std::pair<double, const LineMetrics*>>& lines) {
  double max_work = 0;
  int feasible = 0;
  for (const auto& [boundary_distance, metrics] : lines) {
    if (boundary_distance < spec.singularity_margin) continue;
    const LineMetrics& m = *metrics;
    if (!m.finite() || !(m.energy > 0)) continue;
    max_work = std::max(max_work, std::abs(m.signed_work) / m.energy);
    ++feasible;
  }
  return make_check("signed_work_rest_to_rest",
                    "largest |signed actuator work| / energy of the " + std::to_string(feasible) +
                        " rest-to-rest candidates clear of the margin (no gravity: the kinetic "
                        "energy starts and ends at 0, so this measures the quadrature error)",
                    max_work, 1e-6);
}

// the checks on the optima: clear of the singularities, refinement converged and not
// worse, energies converged
void check_optima(const Spec& spec, Result& res) {
  double worst_margin = 0;
  for (const auto& c : res.cases)
    if (c.found)
      worst_margin = std::max(worst_margin, spec.singularity_margin - c.refined.boundary_distance);
  res.checks.push_back(make_check("optima_clear_of_singularities",
                                  "largest amount by which an optimum's line comes closer to a "
                                  "workspace boundary than the singularity margin, m (an optimum "
                                  "refined along the margin ends on it within roundoff)",
                                  worst_margin, kMarginTol));
  double worst_refine = 0;
  int refined = 0;
  for (const auto& c : res.cases) {
    if (!c.found || c.refine_method.empty()) continue;
    worst_refine = std::max(worst_refine, c.refine_converged ? c.refine_tolerance_rel : kInf);
    ++refined;
  }
  if (refined > 0)
    res.checks.push_back(
        make_check("refinement_converged",
                   "largest relative energy a final COBYLA restart still gained at an optimum (the "
                   "constrained refinement's final tolerance)",
                   worst_refine, 1e-7));
  double worst_conv = 0;
  int conv_n = 0;
  for (const auto& c : res.cases) {
    if (!c.found) continue;
    const EnergyConvergence& ec = c.refined.convergence;
    worst_conv = std::max(worst_conv, ec.energy_withheld() ? kInf : ec.energy_error / ec.energy);
    ++conv_n;
  }
  if (conv_n > 0)
    res.checks.push_back(
        make_check("optima_energy_converged",
                   "largest relative error estimate of an optimum's energy (adaptive Gauss-Kronrod "
                   "quadrature, asked for 1e-9; each optimum on its own)",
                   worst_conv, kEnergyTol));
  double worse = 0;
  for (const auto& c : res.cases)
    if (c.found)
      worse =
          std::max(worse, c.refined.reported_metrics().energy - c.grid.reported_metrics().energy);
  res.checks.push_back(make_check("refinement_not_worse",
                                  "largest increase of an optimum's energy (the quadrature's) by "
                                  "the local refinement, J",
                                  worse, 0.0));
}

// the first optimum's energy at the spec's samples against its value at the most samples
void check_sample_convergence(const Spec& spec, Result& res) {
  if (res.convergence.size() >= 2) {
    const double e_ref = res.convergence.back().energy;
    double e_spec = kNaN;
    for (const auto& c : res.cases) {
      if (c.found) {
        e_spec = c.refined.metrics.energy;
        break;
      }
    }
    res.checks.push_back(make_check("energy_converged",
                                    "relative difference of the first optimum's energy at " +
                                        std::to_string(spec.samples) +
                                        " samples from its value at " +
                                        std::to_string(res.convergence.back().samples) + " samples",
                                    std::abs(e_spec - e_ref) / e_ref, 1e-4));
  }
}

namespace {

// why no pair has an admissible placement, in words
std::string unsolvable_message(const Spec& spec, const Annulus& an, double L) {
  std::string why = "no admissible placement: every candidate line comes closer than " +
                    fmt(spec.singularity_margin, 3) +
                    " m to a boundary of the reachable annulus [" + fmt(an.inner, 3) + ", " +
                    fmt(an.outer, 3) + "] m";
  if (spec.torque_limit || spec.power_limit) why += " or breaks an actuator limit";
  const double longest = longest_line(an, spec.singularity_margin);
  if (L > longest)
    why += "; with this margin the longest line that fits is " + fmt(longest) +
           " m (L = " + fmt(L) + " m, Lmax = " + fmt(an.lmax) +
           " m: a line of length Lmax only fits tangent to the inner circle "
           "with both ends on the outer one, a singular motion)";
  return why;
}

// the summary sentence of `found` optima
std::string summary_message(const Spec& spec, const Annulus& an, const Result& res, int found) {
  // the least printed energy; energies equal within their error estimates (mirror-image
  // optima) are a tie and the first stays (the exports and the report's picture agree)
  const ProgramConfig* best = nullptr;
  for (const auto& c : res.cases)
    if (c.found && (!best || c.refined.reported_metrics().energy <
                                 best->refined.reported_metrics().energy -
                                     (c.refined.convergence.energy_error +
                                      best->refined.convergence.energy_error)))
      best = &c;
  std::ostringstream os;
  // the cycle-time objective's answer first when the case asks for it
  const std::string fastest =
      cycle_time_sentence(res.cycle_time, best->program, best->configuration, spec.duration);
  if (!fastest.empty()) os << fastest << "; ";
  os << "least energy " << fmt(best->refined.reported_metrics().energy) << " J ("
     << core::program_name(best->program) << ", configuration " << best->configuration
     << ") with the root at X = " << fmt(best->refined.root.x())
     << " m, Y = " << fmt(best->refined.root.y())
     << " m from the line's start (x_s = " << fmt(best->refined.x_s, 5)
     << " m, phi = " << fmt(best->refined.phi / kDeg, 3) << " deg)";
  os << "; " << decision_sentence(spec, an, *best);
  int by_margin = 0;
  for (const auto& c : res.cases) by_margin += c.found && c.decision.margin_active();
  if (found > 1 && by_margin > 0)
    os << " (" << by_margin << " of " << found << " optima are set by the clearance margin)";
  if (found < int(res.cases.size()))
    os << "; " << (res.cases.size() - found)
       << " program/configuration pair(s) have no admissible placement";
  return os.str();
}

}  // namespace

Result solve(const Spec& spec, const ProgressFn& progress) {
  const auto t_start = std::chrono::steady_clock::now();
  check_spec(spec);
  SolveState s(spec);
  s.arm = make_arm2(spec.chain);
  s.an = annulus(s.arm.L1, s.arm.L2);
  s.L = spec.length;
  const Annulus& an = s.an;
  const double L = s.L;
  Result res;
  res.lmax = an.lmax;
  res.length = L;
  res.inner = an.inner;
  res.outer = an.outer;
  if (!(L > 0) || L > an.lmax * (1 + 1e-12)) {
    res.status = Status::kUnsolvable;
    res.message =
        "line length " + fmt(L) +
        " m exceeds the longest line the arm can follow, Lmax = 4 sqrt(L1 L2) = " + fmt(an.lmax) +
        " m";
    return res;
  }
  s.threads = sweep_threads(spec.threads);
  const XsInterval xsi = thesis_xs_interval(an, L);
  res.xs_init = xsi.init;
  res.xs_fin = xsi.fin;
  res.thesis_xs_case = xsi.thesis_case;

  build_candidates(s, xsi);
  res.samples_evaluated += sweep(s, progress);
  for (size_t pc = 0; pc < s.pcs.size(); ++pc)
    res.cases.push_back(solve_pair(s, pc, res.samples_evaluated));
  if (progress) progress(0.85, "placement refinement");
  evaluate_fixed(s, res);
  if (spec.cycle_time) res.cycle_time = cycle_times(spec, res.cases, progress, 0.86, 0.97);

  int found = 0;
  for (const auto& c : res.cases) found += c.found;
  sample_convergence(s, res);
  check_signed_work(s, res);
  check_optima(spec, res);
  check_sample_convergence(spec, res);
  if (const std::optional<Check> c = printed_limits_check(spec, res)) res.checks.push_back(*c);
  if (found == 0) {
    res.status = Status::kUnsolvable;
    res.message = unsolvable_message(spec, an, L);
  } else {
    res.message = summary_message(spec, an, res, found);
  }
  if (progress) progress(1.0, "placement done");
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  return res;
}

}  // namespace armstudy::studies::placement
