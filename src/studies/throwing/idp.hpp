// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Iterative dynamic programming (Luus) over the velocity profiles of the active joints,
/// as in Sec. 4 and Fig. 4-5 of Sato et al.
///
/// IDP with a single grid point (Luus, Iterative Dynamic Programming, 2000, ch. 5: one
/// state trajectory, the current best): each iteration runs backward over the stage nodes
/// k = P-1 .. 1. The paper's IDP chooses the active joints' ACCELERATION of each stage, so a
/// candidate at node k changes the acceleration of stage k-1 by delta/h: the rates of nodes
/// k .. P-1 all move by delta (drawn uniformly in [-r, r] per joint), the last stage brings
/// the rate back to the prescribed release rate, and the projection of profile.hpp restores
/// the release angles. R candidates per node are simulated and the best is kept if it is
/// better by the feasibility rules below (frame A of Fig. 4). After the sweep the region is shrunk,
/// r <- gamma r (frame B). Luus's multi-pass variant restarts the region after every `iterations`
/// iterations at `restore` times the previous pass's start. (Moving one node alone, a
/// hat-shaped change of the rate, was tried first: it stalled at a 10 % saving on the
/// default case, where shifting the tail reaches about 30 %.) Candidates are drawn in one
/// fixed-seed sequence and evaluated on
/// `threads` threads, so the answer does not depend on the thread count. While the best is
/// feasible, only a feasible candidate can replace it, so a candidate's simulation stops at
/// its first certain violation (simulate_profile's stop_when_infeasible): the same choices as
/// full simulations, in less time; such a candidate still counts as an evaluation.

#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "studies/common.hpp"
#include "studies/throwing/profile.hpp"
#include "studies/throwing/simulate.hpp"

namespace armstudy::studies {

/// IDP settings (the case's `idp:` section).
///
/// Constraints: a candidate replaces the best when it is better by the feasibility rules
/// (Deb 2000): between two feasible profiles the lower energy wins, otherwise the lower
/// total violation (simulate.hpp's constraint_values with `backoff`). So IDP solves the same
/// constrained problem as the gradient method, and from an infeasible start it first
/// reaches the feasible set.
///
/// Convergence: passes run until `quiet_passes` whole passes in a row each improve a
/// feasible best by a relative energy gain below `tolerance` ((E_start - E_end) / |E_end|);
/// a run that reaches `max_passes` first is not converged (IdpResult::converged false,
/// last_gain kept).
struct IdpSettings {
  int iterations = 6;                   ///< iterations (stage sweeps) per pass
  int max_passes = 40;                  ///< budget: passes at most
  double tolerance = 1e-3;              ///< relative energy gain of a pass
  int quiet_passes = 2;                 ///< passes in a row below the tolerance
  double restore = 0.8;                 ///< region factor between passes
  int candidates = 5;                   ///< R, candidates per stage node
  double shrink = 0.7;                  ///< gamma, region factor per iteration
  Eigen::Vector2d region = {1.0, 1.0};  ///< rad/s, initial half-width per joint
  unsigned seed = 1;                    ///< std::mt19937 seed
  int seeds = 4;                        ///< runs with seeds seed, seed + 1, ...
  double backoff = 0.02;                ///< constraint back-off (constraint_values)
  int threads = 2;                      ///< evaluation threads (>= 1)
  /// false: every candidate is simulated to the end (the reference of the early stop, which
  /// makes the same choices; see run_idp)
  bool stop_infeasible_candidates = true;
  /// true: the seeds of a thread (run_idp_seeds) advance one stage node at a time together,
  /// their candidates sharing the simulation kernel's lanes; false: one seed after the other
  /// (the reference; the same results)
  bool seeds_side_by_side = true;
};

/// One IDP iteration's outcome.
struct IdpIteration {
  int iteration = 0;       ///< 1-based, counted over all passes
  int pass = 0;            ///< 1-based
  double energy = 0;       ///< J, eq. 7 of the best
  double violation = 0;    ///< total constraint violation of the best (0: feasible)
  Eigen::Vector2d region;  ///< rad/s, region used in the iteration
  long evaluations = 0;    ///< simulations so far
  int improvements = 0;    ///< stage nodes improved in this iteration
};

/// Outcome of IDP.
struct IdpResult {
  VelocityProfile best;
  ProfileEvaluation evaluation;
  ProfileEvaluation initial_evaluation;
  std::vector<IdpIteration> history;
  std::vector<double> pass_gains;  ///< relative energy gain of each pass (NaN if infeasible)
  bool converged = false;          ///< a pass gained less than the tolerance, feasible
  double last_gain = NAN;          ///< the last pass's relative gain
  int passes = 0;                  ///< passes run
  unsigned seed = 1;
  long evaluations = 0;
  double run_time = 0;  ///< s, wall clock
  int threads = 1;
};

/// Is `a` better than `b` by the feasibility rules (see IdpSettings)?
bool better_profile(const ProfileEvaluation& a, const ProfileEvaluation& b);

/// Evaluates `profiles` on `threads` threads (results in input order), classified with
/// `backoff`; stop_when_infeasible as in simulate_profile.
std::vector<ProfileEvaluation> evaluate_profiles(const ThrowSetup& setup,
                                                 const std::vector<VelocityProfile>& profiles,
                                                 int threads, double backoff = 0.0,
                                                 bool stop_when_infeasible = false);

/// evaluate_profiles(setup, profiles, threads, backoff) for profiles[0] and neighbours of it:
/// profiles[i] has profiles[0]'s nodes 0 .. first_stage[i] (first_stage[0] = 0). profiles[0]
/// is simulated first with checkpoints, then every neighbour resumes from it at stage
/// first_stage[i] (simulate_profile_from): the same evaluations, bit for bit, in less time.
std::vector<ProfileEvaluation> evaluate_neighbours(const ThrowSetup& setup,
                                                   const std::vector<VelocityProfile>& profiles,
                                                   const std::vector<int>& first_stage, int threads,
                                                   double backoff = 0.0);

/// Runs IDP from `initial` (which must already meet the displacement `delta`, rad) with
/// settings.seed. `progress` receives the fraction of the pass budget done.
IdpResult run_idp(const ThrowSetup& setup, const VelocityProfile& initial,
                  const Eigen::Vector2d& delta, const IdpSettings& settings,
                  const ProgressFn& progress = {});

/// Runs IDP for settings.seeds seeds (seed, seed + 1, ...), the seeds side by side on
/// settings.threads threads (each seed serial; a thread's seeds one node at a time together,
/// see seeds_side_by_side): results in seed order, independent of the thread count.
std::vector<IdpResult> run_idp_seeds(const ThrowSetup& setup, const VelocityProfile& initial,
                                     const Eigen::Vector2d& delta, const IdpSettings& settings,
                                     const ProgressFn& progress = {});

}  // namespace armstudy::studies
