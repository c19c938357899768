#pragma once
/// Iterative dynamic programming (Luus) over the velocity profiles of the active joints,
/// as in Sec. 4 and Fig. 4-5 of 003_a986fd825f31d3e2.txt.
///
/// IDP with a single grid point (Luus, Iterative Dynamic Programming, 2000, ch. 5: one
/// state trajectory, the current best): each iteration runs backward over the stage nodes
/// k = P-1 .. 1; at node k it draws R candidates of the two node rates uniformly in the
/// region [v_k - r, v_k + r] around the best profile (the other nodes keep the best values),
/// projects each onto the release angles (profile.hpp), simulates it and keeps the best if
/// it lowers the criterion (frame A of Fig. 4). After the pass the region is shrunk,
/// r <- gamma r (frame B). Luus's multi-pass variant restarts the region after every
/// `iterations` iterations at `restore` times the previous pass's start (a pass escapes the
/// early contraction of the region). Candidates are drawn in one fixed-seed sequence and evaluated on
/// `threads` threads, so the answer does not depend on the thread count.

#include <vector>

#include <Eigen/Dense>

#include "studies/common.hpp"
#include "studies/throwing/profile.hpp"
#include "studies/throwing/simulate.hpp"

namespace armstudy::studies {

/// IDP settings (the case's `idp:` section).
struct IdpSettings {
  int iterations = 20;                            ///< iterations (stage sweeps) per pass
  int passes = 3;                                 ///< region restarts
  double restore = 0.5;                           ///< region factor between passes
  int candidates = 8;                             ///< R, candidates per stage node
  double shrink = 0.85;                           ///< gamma, region factor per iteration
  Eigen::Vector2d region = {4.0, 4.0};            ///< rad/s, initial half-width per joint
  unsigned seed = 1;                              ///< std::mt19937 seed
  int threads = 2;                                ///< evaluation threads (>= 1)
};

/// One IDP iteration's outcome.
struct IdpIteration {
  int iteration = 0;         ///< 1-based, counted over all passes
  int pass = 0;              ///< 1-based
  double criterion = 0;      ///< J, best after the iteration
  double energy = 0;         ///< J, eq. 7 of the best
  Eigen::Vector2d region;    ///< rad/s, region used in the iteration
  long evaluations = 0;      ///< simulations so far
  int improvements = 0;      ///< stage nodes improved in this iteration
};

/// Outcome of IDP.
struct IdpResult {
  VelocityProfile best;
  ProfileEvaluation evaluation;
  ProfileEvaluation initial_evaluation;
  std::vector<IdpIteration> history;
  long evaluations = 0;
  double run_time = 0;  ///< s, wall clock
  int threads = 1;
};

/// Evaluates `profiles` on `threads` threads (results in input order).
std::vector<ProfileEvaluation> evaluate_profiles(const ThrowSetup& setup,
                                                 const std::vector<VelocityProfile>& profiles,
                                                 int threads);

/// Runs IDP from `initial` (which must already meet the displacement `delta`, rad).
/// `progress` receives the fraction of iterations done.
IdpResult run_idp(const ThrowSetup& setup, const VelocityProfile& initial,
                  const Eigen::Vector2d& delta, const IdpSettings& settings,
                  const ProgressFn& progress = {});

}  // namespace armstudy::studies
