// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/throwing/slsqp_starts.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <random>
#include <thread>

#include "studies/throwing/solve.hpp"

namespace armstudy::studies {

namespace {

using Start = std::pair<std::string, VelocityProfile>;

// `count` seeded perturbations of `p` (uniform in +-amplitude per node rate, then the
// displacement restored), named prefix 1, prefix 2, ...
void perturbations(const VelocityProfile& p, const Eigen::Vector2d& delta, int count,
                   double amplitude, unsigned seed, const std::string& prefix,
                   std::vector<Start>& out) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < count; ++k) {
    VelocityProfile q = p;
    for (int m = 1; m < q.stages(); ++m)
      for (int j = 0; j < 2; ++j) q.v(j, m) += amplitude * u(rng);
    project_displacement(q, delta);
    out.emplace_back(prefix + " " + std::to_string(k + 1), q);
  }
}

// `count` seeded whole-profile changes of `p`: per joint, sine modes k = 1 .. modes over the
// interior nodes, mode k's amplitude uniform in +-amplitude / k, then the displacement
// restored; named prefix 1, prefix 2, ...
void smooth_perturbations(const VelocityProfile& p, const Eigen::Vector2d& delta, int count,
                          double amplitude, int modes, unsigned seed, const std::string& prefix,
                          std::vector<Start>& out) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int P = p.stages();
  for (int c = 0; c < count; ++c) {
    VelocityProfile q = p;
    for (int j = 0; j < 2; ++j)
      for (int k = 1; k <= modes; ++k) {
        const double a = amplitude * u(rng) / k;
        for (int m = 1; m < P; ++m) q.v(j, m) += a * std::sin(k * core::kPi * m / P);
      }
    project_displacement(q, delta);
    out.emplace_back(prefix + " " + std::to_string(c + 1), q);
  }
}

// SLSQP from each start, side by side on `threads` threads, appended to r.slsqp_starts
void run_wave(const ThrowSetup& setup, const ThrowingSpec& spec, const std::vector<Start>& starts,
              const Eigen::Vector2d& delta, const NloptSettings& settings, ThrowingResult& r) {
  run_slsqp_wave(setup, spec, starts, delta, settings, r.slsqp_starts);
}

// the best start so far: lowest converged and re-checked feasible; else the lowest feasible;
// else the least violation; ties to the earlier start (-1: none gave a profile)
int best_start(const ThrowingResult& r) {
  auto rank = [](const ThrowingResult::SlsqpStart& s) {
    if (s.run.converged && s.check.feasible) return 0;
    if (s.run.feasible && s.check.feasible) return 1;
    return 2;
  };
  int best = -1;
  for (int i = 0; i < static_cast<int>(r.slsqp_starts.size()); ++i) {
    const auto& s = r.slsqp_starts[i];
    if (s.run.best.v.size() == 0) continue;
    if (best < 0) {
      best = i;
      continue;
    }
    const auto& b = r.slsqp_starts[best];
    const int ri = rank(s), rb = rank(b);
    if (ri < rb || (ri == rb && (ri < 2 ? s.run.evaluation.energy < b.run.evaluation.energy
                                        : s.run.evaluation.violation < b.run.evaluation.violation)))
      best = i;
  }
  return best;
}

}  // namespace

void run_slsqp_wave(const ThrowSetup& setup, const ThrowingSpec& spec,
                    const std::vector<std::pair<std::string, VelocityProfile>>& starts,
                    const Eigen::Vector2d& delta, const NloptSettings& settings,
                    std::vector<ThrowingResult::SlsqpStart>& out) {
  const int first = static_cast<int>(out.size());
  const int n = static_cast<int>(starts.size());
  out.resize(first + n);
  NloptSettings one = settings;
  if (n > 1) one.threads = 1;  // the starts run side by side instead
  std::atomic<int> next{0};
  std::vector<std::exception_ptr> failed(n);
  auto worker = [&] {
    for (int i = next++; i < n; i = next++) {
      auto& s = out[first + i];
      s.name = starts[i].first;
      try {
        s.run = run_nlopt(setup, starts[i].second, delta, one);
        s.check = verify_profile(setup, s.run.best, spec.check_refinement);
      } catch (...) {
        failed[i] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::clamp(settings.threads, 1, n); ++t) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

void run_slsqp_starts(const ThrowSetup& setup, const ThrowingSpec& spec,
                      const VelocityProfile& reference, const VelocityProfile& eq8,
                      const Eigen::Vector2d& delta, const NloptSettings& settings,
                      ThrowingResult& r) {
  r.slsqp_starts.clear();
  std::vector<Start> starts;
  // a start equal to an earlier one (eq. 8 feasible as it is, an IDP that never moved) would
  // only repeat it
  for (const Start& s :
       {Start{"reference", reference}, Start{"idp", r.idp_run.best}, Start{"eq8", eq8}})
    if (std::none_of(starts.begin(), starts.end(),
                     [&](const Start& t) { return t.second.v == s.second.v; }))
      starts.push_back(s);
  perturbations(reference, delta, settings.perturbed_starts, settings.perturbation, spec.idp.seed,
                "perturbed reference", starts);
  // the global phase: the same problem from whole-profile changes of eq. 8 (on the bundled
  // case about one in six of them reaches a basin 28 % below the others' best)
  smooth_perturbations(eq8, delta, settings.smooth_starts, settings.smooth_amplitude,
                       settings.smooth_modes, spec.idp.seed + 7919, "smooth", starts);
  run_wave(setup, spec, starts, delta, settings, r);
  // then hops from the best local optimum: smaller seeded perturbations of it
  int best = best_start(r);
  if (best >= 0 && settings.hops > 0) {
    starts.clear();
    perturbations(r.slsqp_starts[best].run.best, delta, settings.hops, settings.hop_size,
                  spec.idp.seed + 1, "hop from " + r.slsqp_starts[best].name, starts);
    run_wave(setup, spec, starts, delta, settings, r);
    best = best_start(r);
  }
  r.slsqp_best_start = best;
  if (best < 0) return;
  r.nlopt_run = r.slsqp_starts[best].run;
  r.nlopt_check = r.slsqp_starts[best].check;
  r.nlopt = record_motion(setup, spec, r.nlopt_run.best);
}

}  // namespace armstudy::studies
