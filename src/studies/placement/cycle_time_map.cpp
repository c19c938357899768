// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/placement/cycle_time_map.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <locale>
#include <optional>
#include <sstream>
#include <string>

#include "studies/grid.hpp"
#include "studies/placement/arm2.hpp"
#include "studies/placement/candidate.hpp"
#include "studies/placement/geometry.hpp"
#include "studies/placement/parallel.hpp"
#include "studies/placement/quadrature.hpp"

namespace armstudy::studies::placement {
namespace {

constexpr double kNoTime = std::numeric_limits<double>::infinity();
constexpr double kUnsolved = std::numeric_limits<double>::quiet_NaN();

// the line of root (X, Y) against the annulus of the spec's arm
LineCheck check_root(const Spec& spec, const Annulus& an, const Eigen::Vector2d& root) {
  const Eigen::Vector2d lp = line_of_root(root);
  return check_line(an.L1, an.L2, thesis_line(lp[0], lp[1]), spec.length);
}

CandidateStatus status_of(const Spec& spec, const LineCheck& c) {
  if (c.boundary_distance < -kTouch) return CandidateStatus::kUnreachable;
  if (c.boundary_distance < spec.singularity_margin - kMarginTol) return CandidateStatus::kSingular;
  return CandidateStatus::kFeasible;
}

// the time on `grid_points` nodes at root (X, Y), Y >= 0; infinite where not admissible or
// without a motion
struct Objective {
  const Spec& spec;
  Annulus an;
  int configuration = 1;
  int grid_points = 2;
  int* evaluations = nullptr;
  double operator()(const Eigen::Vector2d& root) const {
    if (root.y() < 0 || status_of(spec, check_root(spec, an, root)) != CandidateStatus::kFeasible)
      return kNoTime;
    ++*evaluations;
    const Eigen::Vector2d lp = line_of_root(root);
    const double t = cycle_time_on_grid(spec, configuration, lp[0], lp[1], grid_points);
    return std::isfinite(t) ? t : kNoTime;
  }
};

struct CompassEnd {
  Eigen::Vector2d p;
  double f = kNoTime;
  double step = 0;    // m, the last step at which no point around p was faster
  double spread = 0;  // s, the largest excess over f on that last ring (admissible points)
};

// Compass search from p (time fp) with steps from h down to h_min: the fastest of the 8
// points at distance h (axes and diagonals) when faster, else h halved.
CompassEnd compass(const Objective& f, Eigen::Vector2d p, double fp, double h, double h_min) {
  const double r = std::sqrt(0.5);
  static const std::array<Eigen::Vector2d, 8> dirs = {
      Eigen::Vector2d(1, 0),  Eigen::Vector2d(-1, 0), Eigen::Vector2d(0, 1),
      Eigen::Vector2d(0, -1), Eigen::Vector2d(r, r),  Eigen::Vector2d(r, -r),
      Eigen::Vector2d(-r, r), Eigen::Vector2d(-r, -r)};
  CompassEnd end{p, fp, h, 0};
  while (h >= h_min) {
    Eigen::Vector2d best = p;
    double fbest = fp, spread = 0;
    for (const Eigen::Vector2d& d : dirs) {
      const Eigen::Vector2d q = p + h * d;
      const double fq = f(q);
      if (std::isfinite(fq)) spread = std::max(spread, fq - fp);
      if (fq < fbest) {
        fbest = fq;
        best = q;
      }
    }
    if (fbest < fp) {
      p = best;
      fp = fbest;
    } else {
      end.step = h;
      end.spread = spread;
      h *= 0.5;
    }
  }
  end.p = p;
  end.f = fp;
  return end;
}

}  // namespace

CycleTimeMap cycle_time_map(const Spec& spec, int configuration, const ProgressFn& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  const Arm2 arm = make_arm2(spec.chain);
  const Annulus an = annulus(arm.L1, arm.L2);
  CycleTimeMap map;
  map.x = linspace(spec.length - an.outer, an.outer, spec.map_nx);  // (the energy map's nodes)
  map.y = linspace(0.0, an.outer, spec.map_ny);
  const size_t n = map.x.size() * map.y.size();
  map.time.assign(n, kUnsolved);
  map.status.assign(n, CandidateStatus::kUnreachable);
  std::vector<long> admissible;
  for (size_t m = 0; m < n; ++m) {
    const Eigen::Vector2d root(map.x[m % map.x.size()], map.y[m / map.x.size()]);
    map.status[m] = status_of(spec, check_root(spec, an, root));
    if (map.status[m] == CandidateStatus::kFeasible) admissible.push_back(long(m));
  }
  map.threads = sweep_threads(spec.threads);
  const int points = spec.cycle_time->map_grid_points;
  parallel_for(
      long(admissible.size()), map.threads, progress, 0.0, 1.0, "cycle-time map",
      [&](long t) {
        const size_t m = size_t(admissible[size_t(t)]);
        const Eigen::Vector2d lp = line_of_root({map.x[m % map.x.size()], map.y[m / map.x.size()]});
        map.time[m] = cycle_time_on_grid(spec, configuration, lp[0], lp[1], points);
      },
      8);
  for (const double t : map.time) map.solved += std::isfinite(t);
  map.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return map;
}

CycleTimeOptimum cycle_time_optimum(const Spec& spec, int configuration, const CycleTimeMap& map) {
  CycleTimeOptimum out;
  out.configuration = configuration;
  long best = -1;
  for (size_t m = 0; m < map.time.size(); ++m)
    if (std::isfinite(map.time[m]) && (best < 0 || map.time[m] < map.time[size_t(best)]))
      best = long(m);
  if (best < 0) {
    out.reason = "no admissible root location of the map has a motion within the limits";
    return out;
  }
  const Arm2 arm = make_arm2(spec.chain);
  const Annulus an = annulus(arm.L1, arm.L2);
  out.grid_root = {map.x[size_t(best) % map.x.size()], map.y[size_t(best) / map.x.size()]};
  out.grid_time = map.time[size_t(best)];
  // the coarse grid's basin from the map's spacing, then the converged grid's to 1e-6 m
  const double h = std::max(map.x[1] - map.x[0], map.y[1] - map.y[0]);
  const CycleTimeSpec& ct = *spec.cycle_time;
  const Objective coarse{spec, an, configuration, ct.map_grid_points, &out.evaluations};
  const CompassEnd c = compass(coarse, out.grid_root, out.grid_time, h, h / 64);
  const Objective fine{spec, an, configuration, ct.grid_points, &out.evaluations};
  const CompassEnd e = compass(fine, c.p, fine(c.p), h / 16, 1e-6);
  out.root = e.p;
  out.root_error = e.step;
  out.fine_time = e.f;
  const Eigen::Vector2d lp = line_of_root(out.root);
  out.x_s = lp[0];
  out.phi = lp[1];
  const LineCheck lc = check_root(spec, an, out.root);
  out.inner_slack = lc.r_min - an.inner - spec.singularity_margin;
  out.outer_slack = an.outer - lc.r_max - spec.singularity_margin;
  out.set_by_margin = std::min(out.inner_slack, out.outer_slack) <= 2 * out.root_error;
  out.converged = converged_cycle_time(spec, configuration, out.x_s, out.phi);
  if (!out.converged.solved) {
    out.reason =
        "the time-optimal study found no motion at the refined root: " + out.converged.message;
    return out;
  }
  out.found = true;
  out.duration_error = out.converged.error + e.spread;
  return out;
}

namespace {

// the point of the trade-off at root (X, Y): both objectives' values, or none when the
// placement is not admissible for the energy objective or has no motion within the limits
std::optional<CycleEnergyPoint> trade_off_point(const Spec& spec, const Arm2& arm,
                                                const ProgramTable& table, int configuration,
                                                const Eigen::Vector2d& root, std::string kind) {
  CycleEnergyPoint p;
  p.root = root;
  const Eigen::Vector2d lp = line_of_root(root);
  p.x_s = lp[0];
  p.phi = lp[1];
  const Candidate c = evaluate_candidate(spec, arm, table, configuration, p.x_s, p.phi);
  if (c.status != CandidateStatus::kFeasible || !c.metrics.finite()) return std::nullopt;
  p.energy = c.metrics.energy;
  const FastMotionOnGrid f =
      fastest_motion_on_grid(spec, configuration, p.x_s, p.phi, spec.cycle_time->grid_points);
  if (!std::isfinite(f.duration)) return std::nullopt;
  p.time = f.duration;
  p.fast_energy = f.energy;
  p.kind = std::move(kind);
  return p;
}

// the points none of `pts` beats in both time and energy, by increasing time
std::vector<CycleEnergyPoint> non_dominated(std::vector<CycleEnergyPoint> pts) {
  std::sort(pts.begin(), pts.end(), [](const CycleEnergyPoint& a, const CycleEnergyPoint& b) {
    return a.time < b.time || (a.time == b.time && a.energy < b.energy);
  });
  std::vector<CycleEnergyPoint> out;
  for (CycleEnergyPoint& p : pts)
    if (out.empty() || p.energy < out.back().energy) out.push_back(std::move(p));
  return out;
}

// the coarse grid's times read slow, by 0.2 to 1.7 % on example 3's map (docs/placement.md),
// not evenly: a node is dropped before its re-evaluation only when a node this much faster
// has less energy
constexpr double kCoarseTimeSlack = 5e-2;

// the points no point faster by more than `slack` (relative) beats in energy, by time
std::vector<CycleEnergyPoint> nearly_non_dominated(std::vector<CycleEnergyPoint> pts,
                                                   double slack) {
  std::sort(pts.begin(), pts.end(),
            [](const CycleEnergyPoint& a, const CycleEnergyPoint& b) { return a.time < b.time; });
  std::vector<CycleEnergyPoint> out;
  double least = std::numeric_limits<double>::infinity();  // over the points faster by slack
  size_t faster = 0;
  for (const CycleEnergyPoint& p : pts) {
    while (faster < pts.size() && pts[faster].time < p.time * (1 - slack))
      least = std::min(least, pts[faster++].energy);
    if (p.energy < least) out.push_back(p);
  }
  return out;
}

}  // namespace

std::vector<CycleEnergyPoint> cycle_energy_front(const Spec& spec, const ProgramConfig& energy,
                                                 const CycleTimeMap& map,
                                                 const CycleTimeOptimum& optimum) {
  const Arm2 arm = make_arm2(spec.chain);
  const ProgramTable table =
      make_program_table(energy.program, spec.duration, spec.length, spec.samples);
  const size_t n = map.time.size();
  if (energy.map.energy.size() != n || energy.map.status.size() != n) return {};
  // the nodes that no node faster by kCoarseTimeSlack beats in energy on the maps' own
  // values (the coarse time, the map's energy)...
  std::vector<CycleEnergyPoint> nodes;
  for (size_t m = 0; m < n; ++m) {
    if (!std::isfinite(map.time[m]) || energy.map.status[m] != CandidateStatus::kFeasible ||
        !std::isfinite(energy.map.energy[m]))
      continue;
    CycleEnergyPoint p;
    p.root = {map.x[m % map.x.size()], map.y[m / map.x.size()]};
    p.time = map.time[m];
    p.energy = energy.map.energy[m];
    nodes.push_back(p);
  }
  nodes = nearly_non_dominated(std::move(nodes), kCoarseTimeSlack);
  // ...each evaluated again on the converged grid and the sweep's samples, with both optima
  std::vector<CycleEnergyPoint> pts;
  auto add = [&](const Eigen::Vector2d& root, const char* kind) {
    if (auto p = trade_off_point(spec, arm, table, energy.configuration, root, kind))
      pts.push_back(std::move(*p));
  };
  for (const CycleEnergyPoint& p : nodes) add(p.root, "map_node");
  if (energy.found) add(energy.refined.root, "energy_optimum");
  if (optimum.found) add(optimum.root, "time_optimum");
  return non_dominated(std::move(pts));
}

namespace {

// the cycle-time objective's figures at the energy optimum of `pc` and the energy objective's
// at the cycle-time optimum of its configuration
EnergyOptimumCycleTime at_energy_optimum(const Spec& spec, const ProgramConfig& pc,
                                         const CycleTime& ct) {
  EnergyOptimumCycleTime e;
  e.program = pc.program;
  e.x_s = pc.refined.x_s;
  e.phi = pc.refined.phi;
  e.root = pc.refined.root;
  e.energy = pc.refined.reported_metrics().energy;
  e.time = converged_cycle_time(spec, ct.configuration, e.x_s, e.phi);
  e.fast_energy = fastest_motion_energy(spec, ct.configuration, e.x_s, e.phi);
  if (ct.optimum.found) {
    const Arm2 arm = make_arm2(spec.chain);
    const ProgramTable table =
        make_program_table(pc.program, spec.duration, spec.length, spec.samples);
    const Candidate c =
        evaluate_candidate(spec, arm, table, ct.configuration, ct.optimum.x_s, ct.optimum.phi);
    e.status_at_time_optimum = c.status;
    const EnergyQuadrature q =
        energy_quadrature(arm, pc.program, spec.duration, spec.length,
                          thesis_line(ct.optimum.x_s, ct.optimum.phi), ct.configuration);
    e.has_energy_at_time_optimum = std::isfinite(q.energy);
    e.energy_at_time_optimum = q.energy;
    e.energy_at_time_optimum_error = q.error;
  }
  e.front = cycle_energy_front(spec, pc, ct.map, ct.optimum);
  return e;
}

}  // namespace

std::vector<CycleTime> cycle_times(const Spec& spec, const std::vector<ProgramConfig>& energy,
                                   const ProgressFn& progress, double p0, double p1) {
  std::vector<CycleTime> out;
  const double share = (p1 - p0) / double(std::max<size_t>(1, spec.configurations.size()));
  for (const int configuration : spec.configurations) {
    CycleTime ct;
    ct.configuration = configuration;
    const double q0 = p0 + share * double(out.size());
    ct.map = cycle_time_map(spec, configuration, [&](double f, std::string_view stage) {
      if (progress) progress(q0 + 0.8 * share * f, stage);
    });
    if (progress) progress(q0 + 0.8 * share, "cycle-time optimum");
    ct.optimum = cycle_time_optimum(spec, configuration, ct.map);
    if (ct.optimum.found)
      ct.optimum.fast_energy =
          fastest_motion_energy(spec, configuration, ct.optimum.x_s, ct.optimum.phi);
    for (const ProgramConfig& pc : energy)
      if (pc.configuration == configuration && pc.found)
        ct.at_energy_optima.push_back(at_energy_optimum(spec, pc, ct));
    out.push_back(std::move(ct));
  }
  return out;
}

namespace {

std::string sig(double v, int digits) {
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os << std::setprecision(digits) << v;
  return os.str();
}

}  // namespace

std::string cycle_time_sentence(const std::vector<CycleTime>& cycle_time,
                                core::MotionProgram program, int configuration, double duration) {
  const CycleTime* fast = nullptr;
  for (const CycleTime& c : cycle_time)
    if (c.optimum.found &&
        (!fast || c.optimum.converged.duration <
                      fast->optimum.converged.duration -
                          (c.optimum.duration_error + fast->optimum.duration_error)))
      fast = &c;
  if (!fast) return "";
  const CycleTimeOptimum& o = fast->optimum;
  std::string out =
      "fastest cycle " + sig(o.converged.duration, 7) + " s ± " + sig(o.duration_error, 2) +
      " s (configuration " + std::to_string(o.configuration) +
      ") with the root at X = " + sig(o.root.x(), 6) + " m, Y = " + sig(o.root.y(), 6) + " m";
  // the energy-optimal placement of the least energy, in the same configuration as the
  // summary's (its mirror image otherwise has the same figures)
  const EnergyOptimumCycleTime* e = nullptr;
  for (const CycleTime& c : cycle_time)
    for (const EnergyOptimumCycleTime& a : c.at_energy_optima)
      if (a.program == program && c.configuration == configuration) e = &a;
  if (!e || !e->time.solved) return out;
  const double faster = 100 * (1 - o.converged.duration / e->time.duration);
  const std::string prog(core::program_name(program));
  out += ", " + sig(faster, 3) + " % faster than the least cycle at the energy-optimal " +
         "placement (" + prog + ", configuration " + std::to_string(configuration) + ": " +
         sig(e->time.duration, 6) + " s)";
  if (o.fast_energy.computed && e->fast_energy.computed) {
    const double d = o.fast_energy.energy - e->fast_energy.energy;
    out += "; that fastest cycle costs " + sig(o.fast_energy.energy, 4) + " J, " +
           sig(std::abs(d), 3) + " J " + (d >= 0 ? "more" : "less") +
           " than the fastest cycle at the energy-optimal placement";
  }
  if (e->has_energy_at_time_optimum)
    out += ", and the " + prog + " motion in T = " + sig(duration, 4) + " s costs " +
           sig(e->energy_at_time_optimum, 5) + " J there against " + sig(e->energy, 5) +
           " J at the energy optimum" +
           (e->status_at_time_optimum == CandidateStatus::kFeasible
                ? ""
                : " (not admissible for the energy objective there: " +
                      std::string(status_name(e->status_at_time_optimum)) + ")");
  return out;
}

}  // namespace armstudy::studies::placement
