// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The three solvers of the time-optimal study on a Problem. Each returns its profile at
/// its nodes, or a message when it cannot solve the problem.

#include <string>
#include <vector>

#include "studies/time_optimal/profile.hpp"
#include "studies/time_optimal/spec.hpp"

namespace armstudy::studies::time_optimal {

struct SolverOutput {
  bool solved = false;
  std::string message;  ///< why not (names the limit and the place on the path)
  Profile profile;
  double duration = 0;   ///< s
  long evaluations = 0;  ///< DP transitions, Complex objective calls
  int iterations = 0;    ///< Complex reflections (over every restart)
  int restarts = 0;      ///< Complex restarts from its best point
  /// the exact solver's controllable sets [reach_lo, reach_hi] of s'^2 at its nodes and its
  /// check points per interval: a later solve on a grid sharing nodes and intervals with it
  /// takes a set from it instead of computing it again (solve_exact's `previous`)
  std::vector<double> reach_lo, reach_hi;
  std::vector<int> reach_checks;
};

/// Joint points of earlier exact solves of one problem, by s and side, so that a re-solve
/// with more check points in some intervals, or on the grid with every interval halved,
/// evaluates only its new points (the same numbers: a point is found only at the same s,
/// from the same side unless no two pieces of the path join there). Tip paths only; on a
/// joint-space path it holds nothing. One cache per Problem, which must outlive it; one
/// thread at a time (find remembers where it last looked).
class ExactPointCache {
 public:
  explicit ExactPointCache(const Problem& problem);
  /// The solver's numbers of the point at s from that side (q', q'', a, b, c, one entry per
  /// joint each), or nullptr.
  const double* find(double s, bool from_left) const;
  /// Keeps the numbers of a point, to be found after the next `merge` (a solve's points
  /// come in increasing s).
  void add(const JointPoint& point, bool from_left);
  /// Room for `points` more points before the next `merge`.
  void reserve(size_t points);
  void merge();
  /// Keeps every point `other` (a cache of the same problem) can find, to be found after the
  /// next `merge`; the points must be none this one has.
  void absorb(const ExactPointCache& other);
  int stride() const { return 5 * joints_; }
  /// false on a joint-space path (nothing is kept).
  bool active() const { return path_ != nullptr; }
  /// Whether a point at s from that side is the one at s2 from side2 (the same s and side, or
  /// the same s where no two pieces of the path join).
  bool same_point(double s, bool from_left, double s2, bool from_left2) const;

 private:
  const PathGeometry* path_ = nullptr;
  int joints_ = 0;
  struct Entry {
    double s;
    bool from_left;
    size_t at;  // into coef_
  };
  std::vector<Entry> index_, fresh_;  // index_ sorted by s; fresh_ in increasing s
  std::vector<double> coef_;          // stride() numbers per point
  mutable size_t hint_ = 0;           // where find last looked (one thread at a time)
};

/// Evaluates into `cache` (found after its next merge) the points that solve_exact(problem,
/// nodes, checks, cache) takes and solve_exact on `known_nodes` with `known_checks` takes
/// none of: a solve on a refined grid can have them while the one on the coarse grid runs
/// (each cache on its own thread). A point that cannot be evaluated is left to the solve.
void prefetch_points(const Problem& problem, const std::vector<double>& nodes,
                     const std::vector<int>& checks, const std::vector<double>& known_nodes,
                     const std::vector<int>& known_checks, ExactPointCache* cache);

/// Exact solver on the grid `nodes` (TOPP-RA's reachability analysis, Pham & Pham 2018):
/// backward controllable sets K_i = {x_i : some u meets the limits over interval i and
/// lands in K_i+1}, then the greedy forward pass taking the largest u. Limits are enforced
/// at `checks` + 1 points of every interval (constant s'' per interval). Rest at both ends
/// and at every stop. Cost O(nodes * rows^2) with rows ~ 4-6 per check point.
SolverOutput solve_exact(const Problem& problem, const std::vector<double>& nodes, int checks);
/// The same with `checks[k]` + 1 points in interval k (one entry per interval, each >= 1):
/// more of them only where the dense re-check finds a limit overshot.
/// `previous`, an earlier solve_exact of the same problem: where an interval of `nodes` is one
/// of its grid's (the same ends and check points) and the set at its end is the one it found
/// there, the backward pass takes the set at its start from it (the same numbers: the same
/// rows and the same set give the same set; a grading round's grid is mostly its last one's).
SolverOutput solve_exact(const Problem& problem, const std::vector<double>& nodes,
                         const std::vector<int>& checks, ExactPointCache* cache = nullptr,
                         const SolverOutput* previous = nullptr);

/// solve_exact's plain implementation: every row with the tag of its limit, the arrays
/// allocated per solve, every point from Problem::at. solve_exact gives the same numbers to
/// rounding (its points from PointSource::solver_at; the tests: 1e-12 relative) without
/// allocating once its per-thread arrays have grown, and words its failures through this one.
SolverOutput solve_exact_reference(const Problem& problem, const std::vector<double>& nodes,
                                   int checks);
SolverOutput solve_exact_reference(const Problem& problem, const std::vector<double>& nodes,
                                   const std::vector<int>& checks);

/// Maximum velocity curve at `nodes`: the largest s' (m/s) at which some s'' meets every
/// limit at that point (`sd_all`), and the s' allowed by the velocity limits alone.
/// The points come from `cache` where it has them (the exact solver's numbers, equal to
/// Problem::at's to rounding), from Problem::at elsewhere; without a cache every point is
/// Problem::at's, so the DP's state grid does not depend on the solver's rounding.
void max_velocity_curve(const Problem& problem, const std::vector<double>& nodes,
                        std::vector<double>* sd_all, std::vector<double>* sd_velocity,
                        const ExactPointCache* cache = nullptr);

/// Dynamic programming as in Ozkipcak (1994): `segments` intervals, constant
/// acceleration in each, Bellman recursion over `levels` velocity levels per interior node;
/// a transition is rejected when any limit fails at one of `checks` + 1 points of its
/// segment. State kPathSpeed: s' levels in [0, MVC(s_k)], constant s''. State
/// kJoint1Velocity (the source's): q1' levels in [0, qd_max_1] towards the motion, constant
/// q1'', segment time 2 dq1 / (q1'(k) + q1'(k+1)); fails when q1 is not monotonic.
SolverOutput solve_dp(const Problem& problem, int segments, int levels, int checks, DpState state);
/// solve_dp's plain recursion (core::opt::solve_staged_dp, the cost of every transition in
/// the candidate bands evaluated; both states). solve_dp gives its numbers, states and transition
/// count (the tests compare the two bitwise) and evaluates only the transitions a lower bound on
/// the remaining time cannot rule out.
SolverOutput solve_dp_reference(const Problem& problem, int segments, int levels, int checks,
                                DpState state);

/// Box's Complex method on the same discretisation as the path-speed DP: the s' of every
/// interior node are the variables (bounds [0, MVC]), a profile is feasible when every
/// segment meets the limits at its check points, the objective is sum 2 ds / (s'_k + s'_k+1).
/// Starts from a feasible crawl (a fraction of the MVC, halved until feasible) and restarts
/// from its best point with fresh random points until a restart gains less than 1e-6
/// relative (at most 10 restarts).
SolverOutput solve_complex(const Problem& problem, int segments, int checks,
                           const ComplexSettings& settings);

}  // namespace armstudy::studies::time_optimal
