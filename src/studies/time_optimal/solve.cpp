// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/time_optimal/solve.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <thread>

#include "core/check.hpp"
#include "core/ik2.hpp"
#include "studies/side_thread.hpp"
#include "studies/time_optimal/profile.hpp"
#include "studies/time_optimal/solvers.hpp"

namespace armstudy::studies::time_optimal {
namespace {
constexpr int kKeepSamples = 600;   // samples per solver kept for plots
constexpr int kDenseTotal = 4000;   // least dense re-check points of a coarse solution
constexpr int kMaxRefinements = 3;  // doublings of the solvers' check points

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string fixed(double v, int digits) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(digits);
  os << v;
  return os.str();
}

// re-check a solver's profile densely and fill its result
void finish(const Problem& pb, const SolverOutput& o, int per_interval, SolverResult* r,
            std::vector<double>* interval_worst = nullptr) {
  r->solved = o.solved;
  r->message = o.message;
  r->evaluations = o.evaluations;
  r->iterations = o.iterations;
  if (!o.solved) return;
  r->duration = o.duration;
  r->law = o.profile.law;
  r->node_s = o.profile.s;
  r->node_sd = o.profile.sd;
  resample(pb, o.profile, per_interval, kKeepSamples, &r->samples, &r->violation, &r->node_t,
           interval_worst);
}

int dense_points(int intervals, int at_least) {
  return std::max(at_least, (kDenseTotal + intervals - 1) / intervals);
}
// the least of f on [lo, hi] by golden-section search to 1e-12, into (s_min, f_min) when it
// is below f_min
template <typename F>
void golden_section_min(const F& f, double lo, double hi, double& s_min, double& f_min) {
  constexpr double g = 0.6180339887498949;
  double a = lo, b = hi, c = b - g * (b - a), d = a + g * (b - a);
  double fc = f(c), fd = f(d);
  while (b - a > 1e-12) {
    if (fc < fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - g * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + g * (b - a);
      fd = f(d);
    }
  }
  const double s = 0.5 * (a + b);
  if (f(s) < f_min) {
    s_min = s;
    f_min = f(s);
  }
}

// singular poses: a probe whose elbow is clearly bent (|sin q2| > 1e-6 without angles)
// passes joint_point's test (|sin q2| >= 1e-9); any other goes through joint_point itself.
// The first probe's trouble, or "".
std::string singular_probe(const Problem& pb, const std::vector<double>& probe) {
  const TipRateEvaluator rates(pb.chain, pb.path.tip(), pb.configuration);
  for (size_t k = 0; k < probe.size(); ++k)
    for (bool left : {false, true}) {
      if (left && !pb.path.tip().joins_pieces(probe[k])) continue;  // the same point
      TipRates r;
      if (rates.at(probe[k], left, &r) && std::abs(r.s2) > 1e-6) continue;
      PathTrouble trouble;
      if (!joint_point(pb.chain, pb.path.tip(), pb.configuration, probe[k], left, &trouble))
        return trouble.message;
    }
  return "";
}

// The path's worst point outside the workspace (largest excess, located to 1e-12 m of s
// between the probes by golden-section search), or the first singular probe; "" if none.
std::string path_trouble(const Problem& pb, int probes,
                         const std::vector<Eigen::Vector2d>& joint_range) {
  if (pb.path.joint_space()) {
    // a joint-space path has no workspace or singularity to leave, only the joints' ranges
    const auto e = range_excursion(pb.path.joint(), joint_range);
    return e ? e->text : "";
  }
  const std::vector<double> probe = make_nodes(pb.path, probes);
  // workspace_margin's operations with the base's rotation taken once (it takes std::cos and
  // std::sin of the base angle at every call): the same numbers
  ARM_THROW_UNLESS(pb.chain.num_links() == 2,
                   "time-optimal arm has " << pb.chain.num_links() << " links; should have 2");
  const double cb = std::cos(pb.chain.base_angle), sb = std::sin(pb.chain.base_angle);
  Eigen::Matrix2d rt;
  rt << cb, sb, -sb, cb;
  const double l1 = pb.chain.links[0].length, l2 = pb.chain.links[1].length;
  const auto margin = [&](double s) {
    const Eigen::Vector2d p = rt * (pb.path.tip().at(s).p - pb.chain.base);
    return core::reach_2link(l1, l2, p).margin;
  };
  size_t worst = 0, first_out = probe.size(), last_out = 0;
  std::vector<double> m(probe.size());
  for (size_t k = 0; k < probe.size(); ++k) {
    m[k] = margin(probe[k]);
    if (m[k] < m[worst]) worst = k;
    if (m[k] < 0) {
      first_out = std::min(first_out, k);
      last_out = k;
    }
  }
  // the true worst may lie between probes: minimise the margin around the worst probe
  double lo = probe[worst > 0 ? worst - 1 : 0], hi = probe[std::min(worst + 1, probe.size() - 1)];
  double s_worst = probe[worst], m_worst = m[worst];
  golden_section_min(margin, lo, hi, s_worst, m_worst);
  if (m_worst < 0) {
    const core::Reach reach = core::reach_2link(pb.chain.links[0].length, pb.chain.links[1].length,
                                                Eigen::Vector2d(1, 0));
    const Eigen::Vector2d p = pb.tip(s_worst);
    std::ostringstream os;
    os.precision(6);
    os << "the path leaves the workspace at s = " << s_worst << " m, (x, y) = (" << p.x() << ", "
       << p.y() << ") m, its worst point: " << length_text(-m_worst)
       << " outside the reachable annulus [" << fixed(reach.inner, 2) << ", "
       << fixed(reach.outer, 2) << "] m";
    if (first_out < probe.size() && last_out > first_out)
      os << " (points outside between s = " << probe[first_out] << " and " << probe[last_out]
         << " m of " << pb.path.length() << " m)";
    return os.str();
  }
  return singular_probe(pb, probe);
}

// The smallest |sin q2| of Problem::at over points lo..hi of `s` (the last one from the
// left), 1 on a joint-space path: the elbow's sine without angles (TipRateEvaluator) finds
// the candidates within 1e-12 of the smallest, Problem::at gives their values.
class MinSinQ2 {
 public:
  MinSinQ2(const Problem& pb, std::vector<double> s)
      : pb_(&pb), s_(std::move(s)), fast_(s_.size(), 1.0) {
    if (pb.path.joint_space()) return;
    const TipRateEvaluator rates(pb.chain, pb.path.tip(), pb.configuration);
    for (size_t k = 0; k < s_.size(); ++k) {
      TipRates r;
      fast_[k] = rates.at(s_[k], k + 1 == s_.size(), &r) ? std::abs(r.s2) : 0.0;
    }
  }
  double operator()(size_t lo, size_t hi) const {
    if (pb_->path.joint_space()) return 1.0;
    double least = std::numeric_limits<double>::infinity();
    for (size_t k = lo; k <= hi; ++k) least = std::min(least, fast_[k]);
    double out = std::numeric_limits<double>::infinity();
    for (size_t k = lo; k <= hi; ++k)
      if (fast_[k] <= least + 1e-12 * std::max(1.0, least))
        out = std::min(out, std::abs(pb_->at(s_[k], k + 1 == s_.size()).sin_q2));
    return out;
  }
  /// The points it was made on.
  const std::vector<double>& points() const { return s_; }

 private:
  const Problem* pb_;
  std::vector<double> s_;
  std::vector<double> fast_;
};

// The exact solver on the case's grid with every interval halved, both halves of interval
// k with its check points, and |sin q2| at the refined grid's points: what grid_convergence
// compares the case's solution with. It does not depend on that solution, so the study
// solves it on a second thread while the solution is re-checked.
struct RefinedGrid {
  std::vector<int> checks;  // the case grid's check points per interval it was solved with
  SolverOutput solution;
  MinSinQ2 min_sin_q2;  // (on the refined grid's points: points() is that grid)
};
// What the side thread computes once the case's grid is solved: the halved grid, and the
// maximum velocity curve on the case's grid (which does not depend on the check points)
struct SideResults {
  RefinedGrid refined;
  std::vector<double> mvc_sd, mvc_velocity_sd;
  std::optional<SolverOutput> coarse;   // (on a graded grid: coarser_grids' coarse one)
  std::optional<SolverOutput> quarter;  // (coarser_grids' quarter one)
};
// the grid with every interval halved, and its check points (interval k's in both halves)
std::vector<double> halved(const std::vector<double>& grid) {
  const int n = static_cast<int>(grid.size());
  std::vector<double> fine;
  fine.reserve(2 * n - 1);
  for (int k = 0; k < n; ++k) {
    if (k > 0) fine.push_back(0.5 * (grid[k - 1] + grid[k]));
    fine.push_back(grid[k]);
  }
  return fine;
}
std::vector<int> halved_checks(const std::vector<int>& checks) {
  std::vector<int> fine(2 * checks.size());
  for (size_t i = 0; i < fine.size(); ++i) fine[i] = checks[i / 2];
  return fine;
}
RefinedGrid solve_refined_grid(const Problem& pb, const std::vector<double>& grid,
                               const std::vector<int>& checks, ExactPointCache* points,
                               const SolverOutput* previous = nullptr) {
  std::vector<double> fine = halved(grid);
  SolverOutput o = solve_exact(pb, fine, halved_checks(checks), points, previous);
  return RefinedGrid{checks, std::move(o), MinSinQ2(pb, std::move(fine))};
}

// The graded grid the study solves on when the case's uniform grid is not converged to
// exact.tolerance_rel, and how it was made.
struct GradedGrid {
  std::vector<double> nodes;
  /// the points the uniform study and the grading evaluated (of the same path; the study on
  /// the graded grid takes only the new ones)
  ExactPointCache* points = nullptr;
  int uniform_points = 0;
  double uniform_change = NAN;
  int rounds = 0;
  bool capped = false;
  /// the exact solutions on nodes and on halved(nodes) with the case's check points in every
  /// interval, when the grading's last round solved them (it stopped converged): the study
  /// on the graded grid starts from them instead of solving them again (the same numbers)
  std::optional<SolverOutput> solution, halved_solution;
};

// per interval k of `grid`: |its time on grid - the time of its two halves on halved(grid)|
std::vector<double> interval_changes(const std::vector<double>& grid, const std::vector<double>& sd,
                                     const std::vector<double>& fine,
                                     const std::vector<double>& fine_sd) {
  const size_t n = grid.size();
  std::vector<double> d(n - 1);
  for (size_t k = 0; k + 1 < n; ++k) {
    const double t_coarse = 2 * (grid[k + 1] - grid[k]) / (sd[k] + sd[k + 1]);
    double t_fine = 0;
    for (size_t i = 2 * k; i < 2 * k + 2; ++i)
      t_fine += 2 * (fine[i + 1] - fine[i]) / (fine_sd[i] + fine_sd[i + 1]);
    d[k] = std::abs(t_coarse - t_fine);
  }
  return d;
}

// Refine `grid` where its halving change arises: solve it and its halved grid, and bisect
// the fewest intervals that hold half of the summed per-interval change (the largest
// first), until the relative change of the duration is within ex.tolerance_rel, the grid
// holds ex.max_grid_points nodes (capped) or a solve fails (the study's own solves say why).
// Near a singular pose this grades the grid geometrically towards it.
// The first round takes the uniform grid's solutions the study already has (on `grid` and
// on its halved grid); each round's solves take the sets of the last round's where their
// intervals are the same (solve_exact's `previous`).
GradedGrid grade_grid(const Problem& pb, std::vector<double> grid, int checks,
                      const ExactSettings& ex, double uniform_change, ExactPointCache* cache,
                      const SolverOutput& grid_solution, const SolverOutput& fine_solution) {
  GradedGrid out;
  out.uniform_points = static_cast<int>(grid.size());
  out.uniform_change = uniform_change;
  out.points = cache;
  constexpr int kMaxRounds = 200;
  SolverOutput og = grid_solution, oh = fine_solution;
  for (int round = 0; round < kMaxRounds; ++round) {
    const std::vector<double> fine = halved(grid);
    // (round 0: the study found the change over the tolerance)
    if (round > 0) {
      og = solve_exact(pb, grid, std::vector<int>(grid.size() - 1, checks), cache, &og);
      if (!og.solved) break;
      oh = solve_exact(pb, fine, std::vector<int>(fine.size() - 1, checks), cache, &oh);
      if (!oh.solved) break;
      if (std::abs(og.duration / oh.duration - 1) <= ex.tolerance_rel) {
        out.solution = std::move(og);
        out.halved_solution = std::move(oh);
        break;
      }
    }
    const int room = ex.max_grid_points - static_cast<int>(grid.size());
    if (room <= 0) {
      out.capped = true;
      break;
    }
    const std::vector<double> d = interval_changes(grid, og.profile.sd, fine, oh.profile.sd);
    std::vector<size_t> order(d.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return d[a] > d[b]; });
    double total = 0;
    for (double v : d) total += v;
    std::vector<char> mark(d.size(), 0);
    double held = 0;
    int marked = 0;
    for (size_t i = 0; i < order.size() && held < 0.5 * total && marked < room; ++i) {
      mark[order[i]] = 1;
      held += d[order[i]];
      ++marked;
    }
    if (marked == 0) break;
    std::vector<double> next;
    next.reserve(grid.size() + marked);
    for (size_t k = 0; k < grid.size(); ++k) {
      if (k > 0 && mark[k - 1]) next.push_back(0.5 * (grid[k - 1] + grid[k]));
      next.push_back(grid[k]);
    }
    grid.swap(next);
    ++out.rounds;
  }
  out.nodes = std::move(grid);
  return out;
}

// every other node of a grid, keeping its ends and the path's stops: a nested coarsening
// with about half the intervals (the uniform coarser grid when the grid is uniform)
std::vector<double> every_other(const std::vector<double>& grid, const std::vector<double>& stops) {
  std::vector<double> out{grid.front()};
  int since = 0;
  for (size_t k = 1; k < grid.size(); ++k) {
    ++since;
    const bool stop = std::find(stops.begin(), stops.end(), grid[k]) != stops.end();
    if (k + 1 == grid.size() || stop || since == 2) {
      out.push_back(grid[k]);
      since = 0;
    }
  }
  return out;
}

// the shortest window [lo, hi] of the n - 1 intervals holding 90 % of their summed change d
// (two pointers); every interval when the change is 0
std::pair<int, int> change_window(const std::vector<double>& d, double total, int n) {
  int best_lo = 0, best_hi = n - 2;
  if (total > 0) {
    double sum = 0;
    int lo = 0;
    for (int hi = 0; hi + 1 < n; ++hi) {
      sum += d[hi];
      while (lo < hi && sum - d[lo] >= 0.9 * total) sum -= d[lo++];
      if (sum >= 0.9 * total && hi - lo < best_hi - best_lo) {
        best_lo = lo;
        best_hi = hi;
      }
    }
  }
  return {best_lo, best_hi};
}

// the words after the relative change: over the tolerance, where the change lies and what
// to do; the grading's own account on a graded grid
void convergence_words(std::ostream& os, const Problem& pb, const GridConvergence& g,
                       const ExactSettings& ex, const GradedGrid* graded, int n) {
  const double tolerance = ex.grid_tolerance;
  if (g.change > tolerance) {
    const std::string u = pb.path.unit();
    os << ", over the tolerance " << tolerance << ": the grid is too coarse, not converged. "
       << fixed(100 * g.share, 0) << " % of the change lies in s = " << fixed(g.s_lo, 4) << " to "
       << fixed(g.s_hi, 4) << " " << u << " (grid points " << g.point_lo << " to " << g.point_hi
       << " of " << n << "; path length " << fixed(pb.path.length(), 4) << " " << u
       << "), where s' <= " << g.max_sd << " " << u << "/s";
    if (!pb.path.joint_space()) os << " and |sin q2| falls to " << g.min_sin_q2;
    if (!pb.path.joint_space() && g.min_sin_q2 < 0.05)
      os << " (near a singular pose: the joint rates per metre of path grow without bound there)";
    if (graded && g.capped)
      os << "; the graded grid (refined from " << g.uniform_points
         << " uniform points where the change arose) stopped at its cap of " << ex.max_grid_points
         << " points (exact.max_grid_points): raise the cap or keep the path away from it";
    else if (graded)
      os << "; the graded grid (refined from " << g.uniform_points
         << " uniform points) stopped at a failing solve or its round limit: keep the path away "
            "from it";
    else if (ex.tolerance_rel > 0)
      os << "; the grid was not graded (its refined solve failed or the node cap "
         << ex.max_grid_points
         << " (exact.max_grid_points) is reached): keep the path away from it";
    else
      os << "; set exact.tolerance_rel > 0 to grade the grid there, or keep the path away from "
            "it";
  } else {
    os << " (tolerance " << tolerance << ")";
  }
  if (graded) {
    os.precision(3);
    os << "; graded from " << g.uniform_points << " uniform points (relative change "
       << g.uniform_change << ") in " << g.graded_rounds
       << " round(s) of bisecting the intervals that hold half the change, to "
       << (g.capped ? "its cap of exact.max_grid_points" : "exact.tolerance_rel") << " "
       << (g.capped ? static_cast<double>(ex.max_grid_points) : ex.tolerance_rel);
  }
}

// the grid study's settings and, on a graded grid, how the grading went
GridConvergence grid_settings(const SolverResult& exact, const ExactSettings& ex,
                              const GradedGrid* graded) {
  GridConvergence g;
  g.computed = true;
  g.tolerance = ex.grid_tolerance;
  g.graded_tolerance = ex.tolerance_rel;
  g.max_points = ex.max_grid_points;
  if (graded) {
    g.graded = true;
    g.uniform_points = graded->uniform_points;
    g.uniform_change = graded->uniform_change;
    g.graded_rounds = graded->rounds;
    g.capped = graded->capped;
  } else {
    g.uniform_points = static_cast<int>(exact.node_s.size());
  }
  return g;
}

// The exact solution on the case's grid against the same problem on the grid with every
// interval halved (`refined`, solved with the solution's check points): the relative change
// and where it lies.
GridConvergence grid_convergence(const Problem& pb, const SolverResult& exact,
                                 const RefinedGrid& refined, const ExactSettings& ex,
                                 const GradedGrid* graded) {
  GridConvergence g = grid_settings(exact, ex, graded);
  const std::vector<double>& grid = exact.node_s;
  const int n = static_cast<int>(grid.size());
  const std::vector<double>& fine = refined.min_sin_q2.points();
  g.grid_points = n;
  g.refined_points = static_cast<int>(fine.size());
  g.duration = exact.duration;
  const SolverOutput& o = refined.solution;
  // |sin q2| along the path (at the refined grid's points); the smallest over a range of them
  const MinSinQ2& min_sin_q2 = refined.min_sin_q2;
  g.path_min_sin_q2 = std::min(g.path_min_sin_q2, min_sin_q2(0, fine.size() - 1));
  std::ostringstream os;
  os.precision(4);
  if (!o.solved) {
    g.change = std::numeric_limits<double>::infinity();
    os << "the exact solver fails on the refined grid of " << g.refined_points
       << " points though it solves the case's " << n << ": " << o.message;
    g.text = os.str();
    return g;
  }
  g.refined_solved = true;
  g.refined_duration = o.duration;
  g.change = std::abs(exact.duration / o.duration - 1);
  // time per case-grid interval on both grids (fine nodes 2k and 2k + 2 bound interval k)
  const std::vector<double> d = interval_changes(grid, exact.node_sd, fine, o.profile.sd);
  double total = 0;
  for (double v : d) total += v;
  const auto [best_lo, best_hi] = change_window(d, total, n);
  double share = 0;
  for (int k = best_lo; k <= best_hi; ++k) share += d[k];
  g.share = total > 0 ? share / total : 1.0;
  g.point_lo = best_lo;
  g.point_hi = best_hi + 1;
  g.s_lo = grid[best_lo];
  g.s_hi = grid[best_hi + 1];
  for (int k = best_lo; k <= best_hi + 1; ++k) g.max_sd = std::max(g.max_sd, exact.node_sd[k]);
  g.min_sin_q2 = std::min(g.min_sin_q2, min_sin_q2(2 * size_t(best_lo), 2 * size_t(best_hi) + 2));
  os.precision(7);
  os << "duration " << exact.duration << " s on " << n << (graded ? " graded" : "")
     << " grid points, " << o.duration << " s on " << g.refined_points
     << " (every interval halved): relative change ";
  os.precision(3);
  os << g.change;
  convergence_words(os, pb, g, ex, graded, n);
  g.text = os.str();
  return g;
}

// v with the digits its error allows plus one (at least 4 significant digits)
std::string significant(double v, double error) {
  int digits = 4;
  if (error > 0 && std::isfinite(error) && v != 0)
    digits = std::clamp(static_cast<int>(std::ceil(std::log10(std::abs(v) / error))) + 1, 4, 12);
  std::ostringstream os;
  os.precision(digits);
  os << v;
  return os.str();
}

// The observed order p of T(I) = T_inf + C I^-p through the durations of three grids of
// i1 < i2 < i3 intervals: it solves (t1 - t2) / (t2 - t3) = ((i2 / i1)^p - 1) / (1 - (i2 /
// i3)^p) (its right side grows with p, so bisection on [0.5, 4]). Nothing when the changes
// differ in sign or p falls outside [0.5, 4].
std::optional<double> observed_order(int i1, double t1, int i2, double t2, int i3, double t3) {
  const double d1 = t1 - t2, d2 = t2 - t3;
  if (!(std::isfinite(t1) && std::isfinite(t2) && std::isfinite(t3)) || d2 == 0 || d1 * d2 <= 0)
    return std::nullopt;
  const double ratio = d1 / d2, a = static_cast<double>(i2) / i1, b = static_cast<double>(i2) / i3;
  auto f = [&](double p) { return (std::pow(a, p) - 1) / (1 - std::pow(b, p)) - ratio; };
  double lo = 0.5, hi = 4.0;
  if (f(lo) > 0 || f(hi) < 0) return std::nullopt;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Richardson's extrapolation at order 1 over grids of i1 < i2 intervals:
// T(I) = T_inf + C / I through both
double richardson1(int i1, double t1, int i2, double t2) { return t2 - (t1 - t2) * i1 / (i2 - i1); }

// The converged duration over the quarter (quarter_intervals 0: none), coarse, case and
// refined grids, and its error (GridConvergence says how)
void extrapolate(GridConvergence& g, int quarter_intervals, int coarse_intervals, int intervals) {
  const double tq = g.quarter_duration, tc = g.coarse_duration, t = g.duration,
               tf = g.refined_duration;
  g.extrapolation_computed = true;
  const std::optional<double> p =
      observed_order(coarse_intervals, tc, intervals, t, 2 * intervals, tf);
  g.asymptotic = p.has_value();
  g.order = p ? *p : NAN;
  g.extrapolated = richardson1(intervals, t, 2 * intervals, tf);
  if (!std::isfinite(tc)) {  // (the coarser grid failed: the extrapolation's own size)
    g.extrapolation_error = kExtrapolationSafety * std::abs(g.extrapolated - tf);
    return;
  }
  g.extrapolated_coarse = richardson1(coarse_intervals, tc, intervals, t);
  double spread = std::abs(g.extrapolated - g.extrapolated_coarse);
  if (quarter_intervals > 0 && std::isfinite(tq)) {
    g.extrapolated_quarter = richardson1(quarter_intervals, tq, coarse_intervals, tc);
    spread = std::max(spread, 0.5 * std::abs(g.extrapolated_coarse - g.extrapolated_quarter));
  }
  g.extrapolation_error = kExtrapolationSafety * spread;
}

// The headline's relative error is within exact.tolerance_rel (without an extrapolation:
// the grid's halving change)
bool headline_converged(const GridConvergence& g, double tolerance_rel) {
  if (g.extrapolation_computed && std::isfinite(g.extrapolation_error))
    return g.extrapolation_error <= tolerance_rel * std::abs(g.extrapolated);
  return g.change <= tolerance_rel;
}

// The exact motion at `steps` + 1 equal time steps: inside interval k,
// s = s_k + s'_k tau + u tau^2 / 2 (Problem::at's joint numbers)
void sample_exact_motion(const Problem& pb, const SolverResult& exact, int steps, Result* res) {
  const int nj = pb.limits.joints();
  res->motion_t.resize(steps + 1);
  res->motion_s.resize(steps + 1);
  res->motion_p.resize(2, steps + 1);
  res->motion_q.resize(nj, steps + 1);
  res->motion_qd.resize(nj, steps + 1);
  size_t k = 0;
  const PointSource source(pb);
  JointPoint jp;
  for (int i = 0; i <= steps; ++i) {
    const double t = exact.duration * i / steps;
    while (k + 2 < exact.node_t.size() && exact.node_t[k + 1] < t) ++k;
    const double ds = exact.node_s[k + 1] - exact.node_s[k];
    const double x0 = exact.node_sd[k] * exact.node_sd[k];
    const double x1 = exact.node_sd[k + 1] * exact.node_sd[k + 1];
    const double u = (x1 - x0) / (2 * ds);
    const double tau = std::clamp(t - exact.node_t[k], 0.0, exact.node_t[k + 1] - exact.node_t[k]);
    const double s = std::clamp(exact.node_s[k] + exact.node_sd[k] * tau + 0.5 * u * tau * tau,
                                exact.node_s[k], exact.node_s[k + 1]);
    source.at(s, i == steps, &jp);
    res->motion_t[i] = t;
    res->motion_s[i] = s;
    res->motion_p.col(i) = jp.p;
    res->motion_q.col(i) = jp.q;
    res->motion_qd.col(i) = jp.dq * std::max(0.0, exact.node_sd[k] + u * tau);
  }
}
}  // namespace

namespace {
void report(const ProgressFn& progress, double f, std::string_view stage) {
  if (progress) progress(f, stage);
}

// the spec's checks the case loader should have made already
void check_spec(const Spec& spec) {
  const int nj = spec.chain.num_links();
  if (spec.space == PathSpace::kTip) {
    ARM_THROW_UNLESS(nj == 2, "time-optimal arm has "
                                  << nj
                                  << " links; a tip path needs 2 (give "
                                     "a redundant arm its path in joint space)");
  } else {
    ARM_THROW_UNLESS(
        nj >= 2, "time-optimal arm has " << nj << " links; should have 2 to " << core::kMaxLinks);
    for (size_t i = 0; i < spec.joint_path.points.size(); ++i)
      ARM_THROW_UNLESS(spec.joint_path.points[i].size() == nj,
                       "joint path waypoint " << i + 1 << " has "
                                              << spec.joint_path.points[i].size()
                                              << " angles; the arm has " << nj << " joints");
    ARM_THROW_UNLESS(
        spec.joint_path.range.empty() || static_cast<int>(spec.joint_path.range.size()) == nj,
        "joint range has " << spec.joint_path.range.size() << " entries; the arm has " << nj
                           << " joints");
  }
  for (int j = 0; j < nj; ++j)
    ARM_THROW_UNLESS(spec.chain.links[j].active,
                     "time-optimal joint " << j + 1 << " is passive; every joint must be active");
  ARM_THROW_UNLESS(spec.velocity_limit.size() == nj && spec.torque_limit.size() == nj &&
                       (!spec.acceleration_limit || spec.acceleration_limit->size() == nj),
                   "time-optimal limits should have one entry per joint (" << nj << ")");
  ARM_THROW_UNLESS(spec.configuration == 1 || spec.configuration == 2,
                   "configuration " << spec.configuration << " should be 1 or 2");
  ARM_THROW_UNLESS(spec.exact.grid_points >= 2,
                   "exact grid points " << spec.exact.grid_points << " should be >= 2");
  ARM_THROW_UNLESS(spec.exact.checks_per_interval >= 1 && spec.dp.checks_per_segment >= 1,
                   "checks per interval should be >= 1");
  ARM_THROW_UNLESS(spec.exact.grid_tolerance > 0,
                   "exact grid tolerance " << spec.exact.grid_tolerance << " should be > 0");
  ARM_THROW_UNLESS(spec.dp.levels >= 2, "DP levels " << spec.dp.levels << " should be >= 2");
  for (int j = 0; j < nj; ++j) {
    ARM_THROW_UNLESS(spec.velocity_limit[j] >= 0 && spec.torque_limit[j] >= 0,
                     "joint " << j + 1 << " limits should be >= 0");
  }
}

// the exact solver's method in words: its grid and where its check points were doubled
std::string exact_method(const Spec& spec, const std::vector<double>& grid,
                         const std::vector<int>& exact_checks, const GradedGrid* graded) {
  const int base = spec.exact.checks_per_interval;
  int more = 0, most = base;
  for (int c : exact_checks) {
    if (c > base) ++more;
    most = std::max(most, c);
  }
  std::string method =
      "reachability analysis (backward controllable sets, greedy forward pass) on " +
      std::to_string(grid.size()) +
      (graded ? " grid points (graded from " + std::to_string(graded->uniform_points) +
                    " uniform ones where the grid's halving change arose)"
              : std::string(" grid points")) +
      ", limits enforced at " + std::to_string(base + 1) + " points of every interval";
  if (more > 0)
    method += " and at up to " + std::to_string(most + 1) + " in the " + std::to_string(more) +
              " interval(s) where the dense re-check found a limit overshot between them";
  return method;
}

// The extrapolation's coarser grids of `grid`: on a graded grid every other node of it and
// every other node of that (nested coarsenings, keeping the path's stops), on a uniform one
// the uniform grids of half and a quarter of its intervals. A grid of under 4 intervals is
// left empty (the quarter one: no quarter grid).
struct CoarserGrids {
  std::vector<double> coarse, quarter;
};
CoarserGrids coarser_grids(const Problem& pb, const std::vector<double>& grid, bool graded) {
  CoarserGrids out;
  const auto big_enough = [](const std::vector<double>& g) { return g.size() >= 5; };
  if (graded) {
    out.coarse = every_other(grid, pb.path.stops());
    if (big_enough(out.coarse)) out.quarter = every_other(out.coarse, pb.path.stops());
  } else {
    const int intervals = static_cast<int>(grid.size()) - 1;
    if (intervals / 2 >= 4) out.coarse = make_nodes(pb.path, intervals / 2);
    if (intervals / 4 >= 4) out.quarter = make_nodes(pb.path, intervals / 4);
  }
  if (!big_enough(out.coarse)) out.coarse.clear();
  if (out.coarse.empty() || !big_enough(out.quarter)) out.quarter.clear();
  return out;
}

// The exact solver on `nodes` with `checks` check points per interval, or nothing when
// there are none or its solve raises (the study solves it again then, for its message). The
// extrapolation's coarser grids depend on neither the answer nor its re-check: on a uniform
// grid the coarser one is solved by the study's thread while the side thread solves the
// halved grid (its points evaluated anew: the shared cache is the side thread's until it is
// waited for), the quarter one on the side thread after the halved grid; on a graded grid
// both on the side thread.
std::optional<SolverOutput> try_solve(const Problem& pb, const std::vector<double>& nodes,
                                      int checks, ExactPointCache* points) {
  if (nodes.empty()) return std::nullopt;
  try {
    return solve_exact(pb, nodes, std::vector<int>(nodes.size() - 1, checks), points);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// the intervals whose check points the re-check `round` doubles: those over the tolerance
// in the first round, then every interval with any overshoot and its neighbours (a re-solve
// can move the overshoot next door); false when it marks none
bool double_checks(int round, const std::vector<double>& interval_worst,
                   std::vector<int>& exact_checks) {
  bool refined = false;
  const double over = round == 0 ? kExactTolerance : 0.0;
  const int around = round == 0 ? 0 : 1;
  const int N = static_cast<int>(exact_checks.size());
  std::vector<char> mark(N, 0);
  for (int i = 0; i < N; ++i)
    if (interval_worst[i] > over)
      for (int d = std::max(0, i - around); d <= std::min(N - 1, i + around); ++d) mark[d] = 1;
  for (int i = 0; i < N; ++i)
    if (mark[i]) {
      exact_checks[i] *= 2;
      refined = true;
    }
  return refined;
}

// Whether the torque limits can hold the arm at rest against gravity along the path: the
// first joint whose gravity torque |c_j| (the torque at rest, s' = s'' = 0) exceeds its
// limit somewhere on `probes` + 1 points, with the point where it needs most ("" when they
// can everywhere). A path that needs more than its limits to be held still may be
// traversed where the motion itself carries the arm, but never started, stopped or slowed
// to rest there: the first thing to say when the solver finds no motion.
std::string holding_trouble(const Problem& pb, int probes) {
  const std::vector<double> probe = make_nodes(pb.path, probes);
  int joint = -1;
  double worst = 1, s_worst = 0, need = 0;
  for (size_t k = 0; k < probe.size(); ++k) {
    JointPoint jp;
    try {
      jp = pb.at(probe[k], k + 1 == probe.size());
    } catch (const std::exception&) {
      continue;
    }
    for (int j = 0; j < static_cast<int>(jp.c.size()); ++j) {
      const double ratio = std::abs(jp.c[j]) / pb.limits.torque[j];
      if (ratio > worst) {
        worst = ratio;
        joint = j;
        s_worst = probe[k];
        need = std::abs(jp.c[j]);
      }
    }
  }
  if (joint < 0) return "";
  std::ostringstream os;
  os << "the joint " << joint + 1 << " torque limit " << pb.limits.torque[joint]
     << " N m cannot hold the arm at rest against gravity on the path: at "
     << pb.where(s_worst, s_worst >= probe.back()) << " holding it needs " << std::setprecision(4)
     << need << " N m, so the arm can neither start, stop nor slow to rest there";
  return os.str();
}

// The exact solver's answer `o` re-checked densely: limits hold at the check points of
// each interval; between them a limit may be overshot by O(h^2). While the dense resampling
// of the whole answer finds a limit overshot by more than kExactTolerance (at most
// kMaxRefinements times), the check points are doubled where it fails and the grid solved
// again; run time includes it. Starts the halved grid's solve on the side thread
// (`speculative`) meanwhile. Adds the exact solver to res and leaves its last solve in `o`;
// false when it is unsolvable.
bool refine_exact(const Problem& pb, const Spec& spec, const std::vector<double>& grid,
                  std::vector<int>& exact_checks, ExactPointCache& points,
                  ExactPointCache& fine_points, SolverOutput& o,
                  std::chrono::steady_clock::time_point t_exact, const GradedGrid* graded,
                  SideTask<SideResults>& speculative, Result& res) {
  SolverResult r;
  r.name = "exact";
  r.intervals = static_cast<int>(grid.size()) - 1;
  std::vector<double> interval_worst;
  // the halved grid on a second thread meanwhile, with these check points (solved again
  // below if the re-check doubles any); it owns the point cache until it is waited for
  // (the grading's last round solved the graded grid's halved grid with these check points)
  const SolverOutput* known =
      graded && graded->halved_solution ? &*graded->halved_solution : nullptr;
  if (o.solved)
    speculative = SideTask<SideResults>(
        [&pb, &grid, &points, &fine_points, known, checks = exact_checks] {
          points.absorb(fine_points);  // (after the prefetch: the side thread runs tasks in turn)
          points.merge();
          SideResults out{known ? RefinedGrid{checks, *known, MinSinQ2(pb, halved(grid))}
                                : solve_refined_grid(pb, grid, checks, &points),
                          {},
                          {},
                          std::nullopt,
                          std::nullopt};
          max_velocity_curve(pb, grid, &out.mvc_sd, &out.mvc_velocity_sd, &points);
          const CoarserGrids coarser = coarser_grids(pb, grid, known != nullptr);
          if (known) out.coarse = try_solve(pb, coarser.coarse, checks.front(), &points);
          out.quarter = try_solve(pb, coarser.quarter, checks.front(), &points);
          return out;
        },
        AfterTask::kSleep);  // (the study's last side task)
  finish(pb, o, spec.resample_per_interval, &r, &interval_worst);
  for (int k = 0; k < kMaxRefinements && o.solved && r.violation.worst > kExactTolerance; ++k) {
    if (speculative.valid()) speculative.wait();  // (the cache is this thread's again)
    if (!double_checks(k, interval_worst, exact_checks))
      exact_checks[r.violation.interval] *= 2;  // (its excess by the closed form rounds below)
    o = solve_exact(pb, grid, exact_checks, &points, &o);
    finish(pb, o, spec.resample_per_interval, &r, &interval_worst);
  }
  r.run_time = seconds_since(t_exact);
  r.checks_per_interval = exact_checks;
  r.method = exact_method(spec, grid, exact_checks, graded);
  res.solvers.push_back(r);
  if (!o.solved) {
    res.status = Status::kUnsolvable;
    // the arm's weight first: a limit that cannot hold it at rest is the culprit, whatever
    // conflict the solver met first (spec.exact.grid_points probes, as the solver's grid)
    const std::string holding =
        holding_trouble(pb, std::max(4 * static_cast<int>(grid.size()), 4000));
    res.message = holding.empty() ? o.message : holding + " (the solver: " + o.message + ")";
    return false;
  }
  return true;
}

// The converged duration over the case's grid and its refined one, solved into g, with the
// coarser grids (coarser_grids; `coarse_side` and `quarter_side`: their solutions where
// already solved)
void extrapolate_grids(const Problem& pb, const Spec& spec, const ProgressFn& progress,
                       const std::vector<double>& grid, const GradedGrid* graded,
                       ExactPointCache& points, std::optional<SolverOutput> coarse_side,
                       std::optional<SolverOutput> quarter_side, GridConvergence& g) {
  const CoarserGrids coarser = coarser_grids(pb, grid, graded != nullptr);
  if (coarser.coarse.empty()) return;
  report(progress, 0.11, "exact solver on coarser grids (extrapolation)");
  const int checks = spec.exact.checks_per_interval;
  const auto solved = [&](const std::vector<double>& nodes, std::optional<SolverOutput>& side) {
    const SolverOutput o =
        side ? std::move(*side)
             : solve_exact(pb, nodes, std::vector<int>(nodes.size() - 1, checks), &points);
    return o.solved ? o.duration : NAN;
  };
  g.coarse_points = static_cast<int>(coarser.coarse.size());
  g.coarse_duration = solved(coarser.coarse, coarse_side);
  if (!coarser.quarter.empty()) {
    g.quarter_points = static_cast<int>(coarser.quarter.size());
    g.quarter_duration = solved(coarser.quarter, quarter_side);
  }
  extrapolate(g, std::max(0, g.quarter_points - 1), g.coarse_points - 1,
              static_cast<int>(grid.size()) - 1);
}

// The exact duration's convergence with the grid: the halved grid's solve (from the side
// thread when its check points still hold) and the coarser grids of the extrapolation
// (extrapolate_grids). Returns the graded grid to solve the study again on when a uniform
// grid's headline is not converged to exact.tolerance_rel (headline_converged; the uniform
// grid's work is lost, and a case whose uniform grid converges pays nothing).
std::optional<GradedGrid> converge_grid(const Problem& pb, const Spec& spec,
                                        const ProgressFn& progress, const std::vector<double>& grid,
                                        const std::vector<int>& exact_checks,
                                        const SolverOutput& exact, ExactPointCache& points,
                                        const GradedGrid* graded,
                                        SideTask<SideResults>& speculative, Result& res) {
  std::optional<RefinedGrid> refined;
  SolverOutput stale;  // (the side thread's halved grid with check points since doubled)
  // (the coarser grid of a uniform one while the side thread still works: try_solve)
  std::optional<SolverOutput> coarse_side =
      graded ? std::nullopt
             : try_solve(pb, coarser_grids(pb, grid, false).coarse, spec.exact.checks_per_interval,
                         nullptr);
  std::optional<SolverOutput> quarter_side;
  if (speculative.valid()) {
    SideResults side = speculative.get();
    if (graded) coarse_side = std::move(side.coarse);
    quarter_side = std::move(side.quarter);
    if (side.refined.checks == exact_checks)
      refined.emplace(std::move(side.refined));
    else
      stale = std::move(side.refined.solution);
    res.mvc_sd = std::move(side.mvc_sd);
    res.mvc_velocity_sd = std::move(side.mvc_velocity_sd);
  } else {
    max_velocity_curve(pb, grid, &res.mvc_sd, &res.mvc_velocity_sd, &points);
  }
  if (!refined) refined.emplace(solve_refined_grid(pb, grid, exact_checks, &points, &stale));
  res.grid = grid_convergence(pb, res.solvers.front(), *refined, spec.exact, graded);
  if (res.grid.refined_solved)
    extrapolate_grids(pb, spec, progress, grid, graded, points, std::move(coarse_side),
                      std::move(quarter_side), res.grid);
  if (!graded && spec.exact.tolerance_rel > 0 && res.grid.refined_solved &&
      !headline_converged(res.grid, spec.exact.tolerance_rel) &&
      static_cast<int>(grid.size()) < spec.exact.max_grid_points) {
    report(progress, 0.12, "grading the exact solver's grid");
    return grade_grid(pb, grid, spec.exact.checks_per_interval, spec.exact, res.grid.change,
                      &points, exact, refined->solution);
  }
  return std::nullopt;
}

// DP and Complex enforce the limits at checks_per_segment + 1 points of each of their
// long segments; between them a limit can be overshot. Like the exact solver, each is
// solved again with doubled checks until its dense resampling meets every limit to
// kCoarseViolationTolerance (at most kMaxRefinements times); run time includes it.
SolverOutput run_coarse(const Problem& pb, const Spec& spec, SolverResult* r,
                        const std::function<SolverOutput(int)>& run) {
  const auto t0 = std::chrono::steady_clock::now();
  int checks = spec.dp.checks_per_segment;
  SolverOutput o = run(checks);
  finish(pb, o, dense_points(spec.dp.segments, spec.resample_per_interval), r);
  for (int k = 0; k < kMaxRefinements && o.solved && r->violation.worst > kCoarseViolationTolerance;
       ++k) {
    checks *= 2;
    o = run(checks);
    finish(pb, o, dense_points(spec.dp.segments, spec.resample_per_interval), r);
  }
  r->run_time = seconds_since(t0);
  r->method += ", limits enforced at " + std::to_string(checks + 1) + " points of every segment";
  return o;
}

// dynamic programming, one run per requested state, and Box's Complex method on the same
// discretisation
void coarse_solvers(const Problem& pb, const Spec& spec, const ProgressFn& progress, Result& res) {
  double done = 0.15;
  for (DpState state : spec.dp.states) {
    report(progress, done,
           state == DpState::kPathSpeed ? "dynamic programming (state s')"
                                        : "dynamic programming (state q1')");
    SolverResult r;
    r.name = state == DpState::kPathSpeed ? "dp" : "dp_joint1";
    r.method = std::string("dynamic programming, ") + std::to_string(spec.dp.segments) +
               " segments of constant " + (state == DpState::kPathSpeed ? "s''" : "q1''") + ", " +
               std::to_string(spec.dp.levels) + " levels of " +
               (state == DpState::kPathSpeed ? "path speed s'" : "joint-1 velocity q1'");
    r.intervals = spec.dp.segments;
    r.levels = spec.dp.levels;
    run_coarse(pb, spec, &r, [&](int checks) {
      return solve_dp(pb, spec.dp.segments, spec.dp.levels, checks, state);
    });
    res.solvers.push_back(r);
    done += 0.15;
  }
  if (spec.complex.enabled) {
    report(progress, done, "Box's Complex method");
    SolverResult r;
    r.name = "complex";
    r.method = "Box's Complex method, " + std::to_string(spec.dp.segments) +
               " segments of constant s'', node speeds as variables";
    r.intervals = spec.dp.segments;
    const SolverOutput o = run_coarse(pb, spec, &r, [&](int checks) {
      return solve_complex(pb, spec.dp.segments, checks, spec.complex);
    });
    r.method += ", restarted " + std::to_string(o.restarts) + " time(s) from its best point";
    res.solvers.push_back(r);
  }
}

// one row of the DP convergence table (path-speed state) at `segments` segments
void convergence_row(const Problem& pb, const Spec& spec, double exact_duration,
                     ConvergenceRow& row) {
  // the state grid grows with N (levels x N / N_case): a segment's reachable speeds span
  // ~1/N of the range, so fixed levels would leave finer segments few reachable states
  // and the quantisation loss, ~one level per segment, would grow with N
  const double grow = static_cast<double>(row.segments) / std::max(1, spec.dp.segments);
  row.levels = static_cast<int>(std::lround(spec.dp.levels * std::max(1.0, grow)));
  // fewer check points on shorter segments: about 80 over the path, at least 2 per segment
  // (doubled, as for the solvers above, while dense resampling finds a limit overshot by
  // more than the coarse tolerance between them)
  int checks = std::max(2, 80 / row.segments);
  const auto t0 = std::chrono::steady_clock::now();
  SolverOutput o;
  Violation v;
  for (int k = 0; k <= kMaxRefinements; ++k, checks *= 2) {
    o = solve_dp(pb, row.segments, row.levels, checks, DpState::kPathSpeed);
    if (!o.solved) break;
    MotionSamples ms;
    v = Violation{};
    resample(pb, o.profile, dense_points(row.segments, 4), 2, &ms, &v, nullptr);
    if (v.worst <= kCoarseViolationTolerance) break;
  }
  row.run_time = seconds_since(t0);
  row.solved = o.solved;
  if (!o.solved) {
    row.message = o.message;
    return;
  }
  row.duration = o.duration;
  row.excess = o.duration / exact_duration - 1;
  row.worst_violation = v.worst;
}

// the DP convergence table (path-speed state), rows spread over two threads
void dp_convergence_table(const Problem& pb, const Spec& spec, double exact_duration, Result& res) {
  res.convergence.resize(spec.dp.convergence_segments.size());
  const auto run_row = [&](size_t i) {
    res.convergence[i].segments = spec.dp.convergence_segments[i];
    convergence_row(pb, spec, exact_duration, res.convergence[i]);
  };
  if (res.convergence.size() > 1) {
    std::thread helper([&] {
      for (size_t i = 1; i < res.convergence.size(); i += 2) run_row(i);
    });
    for (size_t i = 0; i < res.convergence.size(); i += 2) run_row(i);
    helper.join();
  } else if (!res.convergence.empty()) {
    run_row(0);
  }
}

// the summary sentence: the exact duration (extrapolated when it could be), the others
std::string summary_message(const Problem& pb, const Result& res, double exact_duration) {
  std::ostringstream os;
  os << "fastest traversal of the " << fixed(res.path_length, 3) << " " << pb.path.unit()
     << (res.joint_space ? " joint-space path: " : " path: ");
  const GridConvergence& g = res.grid;
  if (g.extrapolation_computed && std::isfinite(g.extrapolated)) {
    // the headline is the converged duration with its error; the grid's own value follows
    os << significant(g.extrapolated, g.extrapolation_error) << " s +- " << std::setprecision(2)
       << g.extrapolation_error << " s (exact, "
       << "extrapolated over "
       << (g.quarter_points > 0  ? 4
           : g.coarse_points > 0 ? 3
                                 : 2)
       << " grids"
       << "; " << fixed(exact_duration, 4) << " s on its " << g.grid_points
       << (g.graded ? "-point graded grid)" : "-point grid)");
  } else {
    os << fixed(exact_duration, 4) << " s (exact)";
  }
  for (const SolverResult& r : res.solvers)
    if (r.name != "exact" && r.solved)
      os << ", " << fixed(r.duration, 4) << " s (" << r.words() << ")";
  for (const SolverResult& r : res.solvers)
    if (r.name != "exact" && !r.solved) os << "; " << r.words() << " failed: " << r.message;
  if (res.grid.computed && !(res.grid.change <= res.grid.tolerance))
    os << "; the exact duration is NOT converged in its grid: " << res.grid.text;
  return os.str();
}

// The halved uniform grid's points that the case's grid has not, into fine_points on the
// side thread while the exact solver runs (the halved grid's solve takes them; a point that
// fails is left to it, as is any error the case's grid raises here). None on a graded grid:
// the grading solved both grids' points already, and no task wakes the side thread.
SideTask<void> prefetch_halved(const Problem& pb, const ExactSettings& ex, const GradedGrid* graded,
                               ExactPointCache& fine_points) {
  if (graded) return {};
  return SideTask<void>([&pb, &fine_points, n = ex.grid_points, c = ex.checks_per_interval] {
    try {
      const std::vector<double> grid = make_nodes(pb.path, n - 1);
      const std::vector<int> checks(grid.size() - 1, c);
      prefetch_points(pb, halved(grid), halved_checks(checks), grid, checks, &fine_points);
    } catch (const std::exception&) {
    }
  });
}

// The study on the case's uniform grid, or (graded given) on the graded grid it asked for:
// path check, exact solver with its dense re-check, grid convergence, DP and Complex, the
// DP convergence table. The side thread checks the path and solves the halved grid while
// this thread runs the exact solver.
// (Over 60 lines, kept whole: the side tasks capture its locals by reference and must end
// in its frame.)
Result solve_grid(const Spec& spec, const ProgressFn& progress, const GradedGrid* graded) {
  check_spec(spec);
  Result res;
  res.limits = Limits{spec.velocity_limit, spec.torque_limit, spec.acceleration_limit};
  res.joint_space = spec.space == PathSpace::kJoint;
  const Problem pb = make_problem(spec, res.limits);
  res.path_length = pb.path.length();

  // the path must stay in the workspace and off singular poses: check it finely
  // (on the side thread while the exact solver starts: the solver's answer, or its failure,
  // counts only once the path has passed)
  report(progress, 0.02, "checking the path");
  // (on the graded grid the uniform grid's study has checked it already)
  SideTask<std::string> path_check;
  if (!graded)
    path_check = SideTask<std::string>(
        [&pb, probes = std::max(4 * spec.exact.grid_points, 4000), &range = spec.joint_path.range] {
          return path_trouble(pb, probes, range);
        });
  const auto path_passed = [&] {
    if (!path_check.valid()) return true;
    const std::string trouble = path_check.get();
    if (trouble.empty()) return true;
    res.status = Status::kUnsolvable;
    res.message = trouble;
    return false;
  };

  // the halved grid's new points on the side thread while the exact solver runs
  ExactPointCache fine_points(pb);
  SideTask<void> prefetch = prefetch_halved(pb, spec.exact, graded, fine_points);

  // exact solver
  report(progress, 0.05, "exact solver (reachability)");
  ExactPointCache own_points(pb);  // the re-solves and the halved grid evaluate only new points
  ExactPointCache& points = graded && graded->points ? *graded->points : own_points;
  const auto t_exact = std::chrono::steady_clock::now();
  std::vector<double> grid;
  std::vector<int> exact_checks;
  SolverOutput first;
  try {
    grid = graded ? graded->nodes : make_nodes(pb.path, spec.exact.grid_points - 1);
    exact_checks.assign(grid.size() - 1, spec.exact.checks_per_interval);
    first = graded && graded->solution ? *graded->solution  // (solved by the grading)
                                       : solve_exact(pb, grid, exact_checks, &points);
  } catch (...) {
    if (!path_passed()) return res;  // (the solver met the path's trouble first)
    throw;
  }
  if (!path_passed()) return res;
  SideTask<SideResults> speculative;  // (waited for by its destructor on every way out)
  if (!refine_exact(pb, spec, grid, exact_checks, points, fine_points, first, t_exact, graded,
                    speculative, res))
    return res;
  const double exact_duration = res.solvers.front().duration;  // (a copy: res.solvers grows)
  // the exact motion and the path's points, while the side thread solves the halved grid
  report(progress, 0.08, "sampling the exact motion");
  sample_exact_motion(pb, res.solvers.front(), std::max(1, spec.motion_steps), &res);
  res.path_p.resize(2, grid.size());
  for (size_t k = 0; k < grid.size(); ++k)
    res.path_p.col(k) = pb.tip(grid[k], k + 1 == grid.size());
  report(progress, 0.1, "exact solver on the refined grid");
  if (const std::optional<GradedGrid> gg = converge_grid(pb, spec, progress, grid, exact_checks,
                                                         first, points, graded, speculative, res))
    return solve_grid(spec, progress, &*gg);
  res.mvc_s = grid;

  coarse_solvers(pb, spec, progress, res);
  report(progress, 0.6, "DP convergence table");
  // the DP table's excess is over the converged exact duration where there is one
  dp_convergence_table(pb, spec, res.grid.reference_duration(exact_duration), res);

  res.status = Status::kSolved;
  res.message = summary_message(pb, res, exact_duration);
  report(progress, 1.0, "done");
  return res;
}
}  // namespace

Result solve(const Spec& spec, const ProgressFn& progress) {
  return solve_grid(spec, progress, nullptr);
}

LimitTolerance limit_tolerance(const Result& res, const SolverResult& r) {
  LimitTolerance out;
  const SolverResult& exact = res.solvers.front();
  const double ref = res.grid.reference_duration(exact.duration);
  std::ostringstream os;
  os.precision(2);
  if (r.name == "exact") {
    // the grid solution's own stated error: its distance from the converged duration and
    // the extrapolation's error estimate
    const double err =
        res.grid.extrapolation_computed && std::isfinite(res.grid.extrapolation_error)
            ? (std::abs(exact.duration - ref) + res.grid.extrapolation_error) / ref
            : 0.0;
    out.value = std::max(kExactTolerance, err);
    os << out.value << " relative, the larger of " << kExactTolerance
       << " and the exact duration's stated error on its grid (" << err << ")";
  } else {
    // the solution's own discretisation error, its excess over the converged exact duration
    const double err = std::max(0.0, r.duration / ref - 1);
    out.value = std::max(kCoarseViolationTolerance, err);
    os << out.value << " relative, the larger of " << kCoarseViolationTolerance
       << " and the solution's own discretisation error, its excess over the converged exact "
          "duration ("
       << err << ")";
  }
  os << ": slowing a motion by a fraction e lowers its joint rates by e and its inertial "
        "torques and accelerations by about 2 e, so an overshoot within that error is within "
        "the answer's stated accuracy";
  out.why = os.str();
  return out;
}

std::vector<Check> checks(const Result& res) {
  std::vector<Check> out;
  if (res.status != Status::kSolved || res.solvers.empty()) return out;
  const SolverResult& exact = res.solvers.front();
  for (const SolverResult& r : res.solvers) {
    if (!r.solved) continue;
    if (r.name != "exact") {
      out.push_back(make_check("exact_not_slower_than_" + r.name,
                               "exact duration / " + r.name +
                                   " duration - 1 (the reachability "
                                   "solution is never slower)",
                               exact.duration / r.duration - 1, 1e-9));
    }
    const LimitTolerance tol = limit_tolerance(res, r);
    out.push_back(make_check(r.name + "_meets_limits",
                             "largest relative limit overshoot of the " + r.name +
                                 " solution, densely resampled: " + r.violation.text +
                                 "; tolerance " + tol.why,
                             r.violation.worst, tol.value));
  }
  if (res.grid.computed)
    out.push_back(make_check("exact_grid_converged",
                             "relative change of the exact duration when every grid interval is "
                             "halved (fails beyond exact.grid_tolerance): " +
                                 res.grid.text,
                             res.grid.change, res.grid.tolerance));
  double worst = -1;
  bool any = false;
  for (const ConvergenceRow& row : res.convergence) {
    if (!row.solved) continue;
    any = true;
    worst = std::max(worst, -row.excess / (1 + row.excess));
  }
  if (any)
    out.push_back(make_check(
        "exact_not_slower_than_dp_table",
        "largest exact duration (converged, where extrapolated) / DP duration - 1 over the "
        "convergence table",
        worst, 1e-9));
  return out;
}

}  // namespace armstudy::studies::time_optimal
