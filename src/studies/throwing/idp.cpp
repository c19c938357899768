// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/throwing/idp.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
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

namespace {

// run_idp's loops taken one stage node at a time (draw the node's candidates, take their
// evaluations), so that the seeds of one thread can share the kernel's lanes
class IdpStepper {
 public:
  IdpStepper(const ThrowSetup& setup, const VelocityProfile& initial, const Eigen::Vector2d& delta,
             const IdpSettings& s, const ProgressFn& progress = {})
      : s_(s), delta_(delta), progress_(progress), rng_(s.seed), u_(-1.0, 1.0) {
    t0_ = std::chrono::steady_clock::now();
    r_.seed = s.seed;
    r_.threads = std::max(1, s.threads);
    r_.best = initial;
    r_.initial_evaluation = simulate_profile(setup, initial, nullptr, s.backoff);
    r_.evaluation = r_.initial_evaluation;
    r_.evaluations = 1;
    P_ = initial.stages();
    iterations_ = std::max(1, s.iterations);
    cands_.resize(std::max(1, s.candidates));
    pass_region_ = s.region;
    start_pass();
    settle();
  }

  bool done() const { return done_; }
  int threads() const { return r_.threads; }

  // the current node's candidates: a candidate at node k changes the acceleration of stage
  // k-1 by delta / h: every later rate up to node P-1 moves by delta and the last stage
  // returns to the release rate
  const std::vector<VelocityProfile>& draw() {
    for (auto& c : cands_) {
      c = r_.best;
      const double d0 = region_[0] * u_(rng_), d1 = region_[1] * u_(rng_);
      for (int m = k_; m < P_; ++m) {
        c.v(0, m) += d0;
        c.v(1, m) += d1;
      }
      project_displacement(c, delta_);
    }
    return cands_;
  }

  // a feasible best is replaced by a feasible candidate only (better_profile), so an
  // infeasible candidate's simulation may stop at its first certain violation
  bool may_stop() const { return s_.stop_infeasible_candidates && r_.evaluation.feasible; }

  // the drawn candidates' evaluations (in order): the best replaces the best so far if better
  void take(const ProfileEvaluation* evs) {
    const int n = static_cast<int>(cands_.size());
    r_.evaluations += n;
    int best = -1;
    for (int j = 0; j < n; ++j)
      if (better_profile(evs[j], best < 0 ? r_.evaluation : evs[best])) best = j;
    if (best >= 0) {
      r_.best = cands_[best];
      r_.evaluation = evs[best];
      ++rec_.improvements;
    }
    --k_;
    settle();
  }

  IdpResult finish() {
    r_.run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    return std::move(r_);
  }

 private:
  void start_pass() {
    at_start_ = r_.evaluation;
    region_ = pass_region_;
    i_ = 0;
    start_iteration();
  }

  // backward pass over the free stage nodes (frame A of Fig. 4)
  void start_iteration() {
    rec_ = IdpIteration{};
    rec_.iteration = ++it_;
    rec_.pass = pass_;
    rec_.region = region_;
    k_ = P_ - 1;
  }

  // past the iteration's last node: the iteration's, and maybe the pass's, end
  void settle() {
    while (k_ < 1) {
      // shift done (best kept); shrink the region (frame B)
      region_ *= s_.shrink;
      rec_.energy = r_.evaluation.energy;
      rec_.violation = r_.evaluation.violation;
      rec_.evaluations = r_.evaluations;
      r_.history.push_back(rec_);
      if (++i_ < iterations_) {
        start_iteration();
        continue;
      }
      r_.passes = pass_;
      const bool both_feasible = at_start_.feasible && r_.evaluation.feasible;
      r_.last_gain =
          both_feasible ? (at_start_.energy - r_.evaluation.energy) / std::abs(r_.evaluation.energy)
                        : NAN;
      r_.pass_gains.push_back(r_.last_gain);
      if (progress_) progress_(static_cast<double>(pass_) / std::max(1, s_.max_passes), "IDP");
      quiet_ = both_feasible && r_.last_gain < s_.tolerance ? quiet_ + 1 : 0;
      if (quiet_ >= std::max(1, s_.quiet_passes)) {
        r_.converged = true;
        done_ = true;
        return;
      }
      if (pass_ >= std::max(1, s_.max_passes)) {
        done_ = true;
        return;
      }
      // multi-pass: restore the region (smaller each pass)
      pass_region_ *= s_.restore;
      ++pass_;
      start_pass();
    }
  }

  const IdpSettings s_;
  const Eigen::Vector2d delta_;
  ProgressFn progress_;
  std::chrono::steady_clock::time_point t0_;
  IdpResult r_;
  std::mt19937 rng_;
  std::uniform_real_distribution<double> u_;
  int P_ = 0, iterations_ = 1;
  std::vector<VelocityProfile> cands_;
  Eigen::Vector2d pass_region_, region_;
  ProfileEvaluation at_start_;
  IdpIteration rec_;
  int pass_ = 1, i_ = 0, k_ = 0, it_ = 0, quiet_ = 0;
  bool done_ = false;
};

// the profiles, each with its own stop_when_infeasible, on one thread: kernel_lanes at once
// where the kernel applies
std::vector<ProfileEvaluation> evaluate_each(const ThrowSetup& setup,
                                             const std::vector<const VelocityProfile*>& profiles,
                                             const std::vector<char>& stop, double backoff) {
  const int n = static_cast<int>(profiles.size());
  std::vector<ProfileEvaluation> out(n);
  if (setup.kernel_lanes >= 1 && kernel_applies(setup)) {
    bool st[5];
    const int w = std::clamp(setup.kernel_lanes, 1, 5);
    for (int i = 0; i < n; i += w) {
      const int g = std::min(w, n - i);
      for (int q = 0; q < g; ++q) st[q] = stop[i + q];
      const std::vector<const VelocityProfile*> group(profiles.begin() + i,
                                                      profiles.begin() + i + g);
      simulate_kernel_lanes(setup, group, w, backoff, false, &out[i], nullptr, 0, st);
    }
    return out;
  }
  for (int i = 0; i < n; ++i)
    out[i] = simulate_profile(setup, *profiles[i], nullptr, backoff, stop[i]);
  return out;
}

}  // namespace

IdpResult run_idp(const ThrowSetup& setup, const VelocityProfile& initial,
                  const Eigen::Vector2d& delta, const IdpSettings& s, const ProgressFn& progress) {
  IdpStepper run(setup, initial, delta, s, progress);
  while (!run.done()) {
    const std::vector<VelocityProfile>& cands = run.draw();
    const auto evs = evaluate_profiles(setup, cands, run.threads(), s.backoff, run.may_stop());
    run.take(evs.data());
  }
  return run.finish();
}

// (over 60 lines, kept whole: the worker's fill, retire and step lambdas share its runs and
// the seed counters)
std::vector<IdpResult> run_idp_seeds(const ThrowSetup& setup, const VelocityProfile& initial,
                                     const Eigen::Vector2d& delta, const IdpSettings& s,
                                     const ProgressFn& progress) {
  const int n = std::max(1, s.seeds);
  std::vector<IdpResult> out(n);
  const int nt = std::clamp(s.threads, 1, n);
  // each thread runs its share of the seeds side by side, one stage node of each at a time,
  // their candidates together in the kernel's lanes (each seed's candidates and choices are
  // its own: the results do not depend on which seeds share a thread)
  const int share = s.seeds_side_by_side ? (n + nt - 1) / nt : 1;
  std::atomic<int> next{0}, done{0};
  auto worker = [&](bool report) {
    std::vector<std::pair<int, std::unique_ptr<IdpStepper>>> runs;
    auto fill = [&] {
      while (static_cast<int>(runs.size()) < share) {
        const int i = next++;
        if (i >= n) break;
        IdpSettings one = s;
        one.seed = s.seed + static_cast<unsigned>(i);
        one.threads = 1;  // the seeds run side by side instead
        runs.emplace_back(i, std::make_unique<IdpStepper>(setup, initial, delta, one));
      }
    };
    // the runs that are done (a run without free nodes is done when it starts) give their
    // results; new seeds take their places
    auto retire = [&] {
      for (size_t q = 0; q < runs.size();) {
        if (runs[q].second->done()) {
          out[runs[q].first] = runs[q].second->finish();
          runs.erase(runs.begin() + static_cast<long>(q));
          ++done;
          if (report && progress) progress(static_cast<double>(done) / n, "IDP seeds");
          fill();
        } else {
          ++q;
        }
      }
    };
    fill();
    retire();
    std::vector<const VelocityProfile*> profiles;
    std::vector<char> stop;
    while (!runs.empty()) {
      profiles.clear();
      stop.clear();
      for (auto& [i, run] : runs) {
        const bool may = run->may_stop();
        for (const VelocityProfile& c : run->draw()) {
          profiles.push_back(&c);
          stop.push_back(may);
        }
      }
      const std::vector<ProfileEvaluation> evs = evaluate_each(setup, profiles, stop, s.backoff);
      size_t at = 0;
      for (auto& [i, run] : runs) {
        const size_t count = static_cast<size_t>(std::max(1, s.candidates));
        run->take(evs.data() + at);
        at += count;
      }
      retire();
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
