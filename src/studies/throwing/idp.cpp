#include "studies/throwing/idp.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <random>
#include <thread>

namespace armstudy::studies {

std::vector<ProfileEvaluation> evaluate_profiles(const ThrowSetup& setup,
                                                 const std::vector<VelocityProfile>& profiles,
                                                 int threads) {
  std::vector<ProfileEvaluation> out(profiles.size());
  const int n = static_cast<int>(profiles.size());
  const int nt = std::clamp(threads, 1, std::max(1, n));
  if (nt == 1) {
    for (int i = 0; i < n; ++i) out[i] = simulate_profile(setup, profiles[i]);
    return out;
  }
  // work stealing over an atomic index; each slot written by exactly one thread
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int i = next++; i < n; i = next++) out[i] = simulate_profile(setup, profiles[i]);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < nt; ++t) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  return out;
}

IdpResult run_idp(const ThrowSetup& setup, const VelocityProfile& initial,
                  const Eigen::Vector2d& delta, const IdpSettings& s, const ProgressFn& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  IdpResult r;
  r.threads = std::max(1, s.threads);
  r.best = initial;
  r.initial_evaluation = simulate_profile(setup, initial);
  r.evaluation = r.initial_evaluation;
  r.evaluations = 1;
  std::mt19937 rng(s.seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int P = initial.stages();
  std::vector<VelocityProfile> cands(std::max(1, s.candidates));
  const int total = std::max(1, s.passes) * s.iterations;
  Eigen::Vector2d pass_region = s.region;
  Eigen::Vector2d region = s.region;
  for (int it = 1; it <= total; ++it) {
    const int pass = (it - 1) / std::max(1, s.iterations) + 1;
    if (it > 1 && (it - 1) % s.iterations == 0) {
      // multi-pass: restart the region (smaller each pass)
      pass_region *= s.restore;
      region = pass_region;
    }
    IdpIteration rec;
    rec.iteration = it;
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
      const auto evs = evaluate_profiles(setup, cands, r.threads);
      r.evaluations += static_cast<long>(evs.size());
      int best = -1;
      for (size_t i = 0; i < evs.size(); ++i) {
        if (evs[i].finite && evs[i].criterion < (best < 0 ? r.evaluation.criterion : evs[best].criterion))
          best = static_cast<int>(i);
      }
      if (best >= 0) {
        r.best = cands[best];
        r.evaluation = evs[best];
        ++rec.improvements;
      }
    }
    // shift done (best kept); shrink the region (frame B)
    region *= s.shrink;
    rec.criterion = r.evaluation.criterion;
    rec.energy = r.evaluation.energy;
    rec.evaluations = r.evaluations;
    r.history.push_back(rec);
    if (progress) progress(static_cast<double>(it) / total, "IDP");
  }
  r.run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace armstudy::studies
