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
/// the release angles. R candidates per node are simulated and the best is kept if it lowers
/// the criterion (frame A of Fig. 4). After the sweep the region is shrunk, r <- gamma r
/// (frame B). Luus's multi-pass variant restarts the region after every `iterations`
/// iterations at `restore` times the previous pass's start. (Moving one node alone, a
/// hat-shaped change of the rate, was tried first: it stalled at a 10 % saving on the
/// default case, where shifting the tail reaches about 30 %.) Candidates are drawn in one
/// fixed-seed sequence and evaluated on
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
  double shrink = 0.8;                            ///< gamma, region factor per iteration
  Eigen::Vector2d region = {10.0, 10.0};          ///< rad/s, initial half-width per joint
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
