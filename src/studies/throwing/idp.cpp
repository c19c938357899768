#include "studies/throwing/idp.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <random>
#include <thread>

#include "studies/throwing/simulate_kernel.hpp"

namespace armstudy::studies {

bool better_profile(const ProfileEvaluation& a, const ProfileEvaluation& b) {
  if (!a.finite) return false;
  if (!b.finite) return true;
  if (a.feasible && b.feasible) return a.energy < b.energy;
  return a.violation < b.violation;
}

namespace {

// fn(i) for i in [begin, end) on `threads` threads: work stealing over an atomic index
template <typename F>
void parallel_for(int begin, int end, int threads, F&& fn) {
  const int nt = std::clamp(threads, 1, std::max(1, end - begin));
  if (nt == 1) {
    for (int i = begin; i < end; ++i) fn(i);
    return;
  }
  std::atomic<int> next{begin};
  auto worker = [&] {
    for (int i = next++; i < end; i = next++) fn(i);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < nt; ++t) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
}

}  // namespace

std::vector<ProfileEvaluation> evaluate_profiles(const ThrowSetup& setup,
                                                 const std::vector<VelocityProfile>& profiles,
                                                 int threads, double backoff,
                                                 bool stop_when_infeasible) {
  std::vector<ProfileEvaluation> out(profiles.size());
  const int n = static_cast<int>(profiles.size());
  if (setup.kernel_lanes >= 2 && kernel_applies(setup)) {
    // kernel_lanes profiles at once (the same evaluations); each group of slots written by
    // one thread
    const int w = setup.kernel_lanes;
    parallel_for(0, (n + w - 1) / w, threads, [&](int q) {
      std::vector<const VelocityProfile*> group;
      for (int i = q * w; i < std::min(n, (q + 1) * w); ++i) group.push_back(&profiles[i]);
      simulate_kernel_lanes(setup, group, w, backoff, stop_when_infeasible, &out[q * w]);
    });
    return out;
  }
  // each slot written by exactly one thread
  parallel_for(0, n, threads, [&](int i) {
    out[i] = simulate_profile(setup, profiles[i], nullptr, backoff, stop_when_infeasible);
  });
  return out;
}

std::vector<ProfileEvaluation> evaluate_neighbours(const ThrowSetup& setup,
                                                   const std::vector<VelocityProfile>& profiles,
                                                   const std::vector<int>& first_stage, int threads,
                                                   double backoff) {
  std::vector<ProfileEvaluation> out(profiles.size());
  if (profiles.empty()) return out;
  SimulationCheckpoints base;
  out[0] = simulate_profile(setup, profiles[0], base, backoff);
  // neighbours side by side in groups of the same first stage (the +h and -h of a node's
  // two rates)
  const int n = static_cast<int>(profiles.size());
  const int w = std::max(1, setup.kernel_lanes);
  std::vector<std::pair<int, int>> groups;  // [begin, end)
  for (int i = 1; i < n;) {
    int e = i + 1;
    while (e < n && e - i < w && first_stage[e] == first_stage[i]) ++e;
    groups.emplace_back(i, e);
    i = e;
  }
  parallel_for(0, static_cast<int>(groups.size()), threads, [&](int q) {
    const auto [b, e] = groups[q];
    std::vector<const VelocityProfile*> group;
    for (int i = b; i < e; ++i) group.push_back(&profiles[i]);
    simulate_group_from(setup, group, base, first_stage[b], backoff, &out[b]);
  });
  return out;
}

IdpResult run_idp(const ThrowSetup& setup, const VelocityProfile& initial,
                  const Eigen::Vector2d& delta, const IdpSettings& s, const ProgressFn& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  IdpResult r;
  r.seed = s.seed;
  r.threads = std::max(1, s.threads);
  r.best = initial;
  r.initial_evaluation = simulate_profile(setup, initial, nullptr, s.backoff);
  r.evaluation = r.initial_evaluation;
  r.evaluations = 1;
  std::mt19937 rng(s.seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int P = initial.stages();
  const int iterations = std::max(1, s.iterations);
  std::vector<VelocityProfile> cands(std::max(1, s.candidates));
  Eigen::Vector2d pass_region = s.region;
  int it = 0, quiet = 0;
  for (int pass = 1; pass <= std::max(1, s.max_passes); ++pass) {
    const ProfileEvaluation at_start = r.evaluation;
    Eigen::Vector2d region = pass_region;
    for (int i = 0; i < iterations; ++i) {
      IdpIteration rec;
      rec.iteration = ++it;
      rec.pass = pass;
      rec.region = region;
      // backward pass over the free stage nodes (frame A of Fig. 4)
      for (int k = P - 1; k >= 1; --k) {
        // a candidate changes the acceleration of stage k-1 by delta / h: every later rate
        // up to node P-1 moves by delta and the last stage returns to the release rate
        for (auto& c : cands) {
          c = r.best;
          const double d0 = region[0] * u(rng), d1 = region[1] * u(rng);
          for (int m = k; m < P; ++m) {
            c.v(0, m) += d0;
            c.v(1, m) += d1;
          }
          project_displacement(c, delta);
        }
        // a feasible best is replaced by a feasible candidate only (better_profile), so an
        // infeasible candidate's simulation may stop at its first certain violation
        const auto evs = evaluate_profiles(setup, cands, r.threads, s.backoff,
                                           s.stop_infeasible_candidates && r.evaluation.feasible);
        r.evaluations += static_cast<long>(evs.size());
        int best = -1;
        for (size_t j = 0; j < evs.size(); ++j)
          if (better_profile(evs[j], best < 0 ? r.evaluation : evs[best]))
            best = static_cast<int>(j);
        if (best >= 0) {
          r.best = cands[best];
          r.evaluation = evs[best];
          ++rec.improvements;
        }
      }
      // shift done (best kept); shrink the region (frame B)
      region *= s.shrink;
      rec.energy = r.evaluation.energy;
      rec.violation = r.evaluation.violation;
      rec.evaluations = r.evaluations;
      r.history.push_back(rec);
    }
    r.passes = pass;
    const bool both_feasible = at_start.feasible && r.evaluation.feasible;
    r.last_gain = both_feasible
                      ? (at_start.energy - r.evaluation.energy) / std::abs(r.evaluation.energy)
                      : NAN;
    r.pass_gains.push_back(r.last_gain);
    if (progress) progress(static_cast<double>(pass) / std::max(1, s.max_passes), "IDP");
    quiet = both_feasible && r.last_gain < s.tolerance ? quiet + 1 : 0;
    if (quiet >= std::max(1, s.quiet_passes)) {
      r.converged = true;
      break;
    }
    // multi-pass: restore the region (smaller each pass)
    pass_region *= s.restore;
  }
  r.run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

std::vector<IdpResult> run_idp_seeds(const ThrowSetup& setup, const VelocityProfile& initial,
                                     const Eigen::Vector2d& delta, const IdpSettings& s,
                                     const ProgressFn& progress) {
  const int n = std::max(1, s.seeds);
  std::vector<IdpResult> out(n);
  const int nt = std::clamp(s.threads, 1, n);
  std::atomic<int> next{0}, done{0};
  auto worker = [&](bool report) {
    for (int i = next++; i < n; i = next++) {
      IdpSettings one = s;
      one.seed = s.seed + static_cast<unsigned>(i);
      one.threads = 1;  // the seeds run side by side instead
      out[i] = run_idp(setup, initial, delta, one);
      ++done;
      if (report && progress) progress(static_cast<double>(done) / n, "IDP seeds");
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < nt; ++t) pool.emplace_back(worker, false);
  worker(true);
  for (auto& th : pool) th.join();
  for (auto& r : out) r.threads = nt;
  return out;
}

}  // namespace armstudy::studies
