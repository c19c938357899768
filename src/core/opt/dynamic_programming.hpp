// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Staged dynamic programming over discrete states (Bellman's backward recursion), arm
/// agnostic: nodes k = 0..K, node k has levels[k] states, and a transition from state i at
/// node k to state j at node k+1 costs cost(k, i, j) (+infinity: forbidden).
///
/// The recursion J(k, i) = min_j [cost(k, i, j) + J(k+1, j)], J(K, j) = 0, runs from the
/// last node back to the first (Ozkipcak 1994, steps 1-4 of its DP
/// algorithm); the optimal states are then read forward from node 0. Work is
/// sum_k levels[k] * levels[k+1] cost evaluations; transitions into states that cannot
/// reach the end are skipped without evaluating their cost.

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "core/check.hpp"

namespace armstudy::core::opt {

/// The optimal path of a staged problem.
struct DpSolution {
  double cost = std::numeric_limits<double>::infinity();  ///< total cost (inf: no path)
  std::vector<int> states;  ///< (K+1) chosen state index per node; empty if no path
  long evaluations = 0;     ///< cost evaluations made
  bool feasible() const { return std::isfinite(cost); }
};

/// The forward read-out of a finished backward recursion into `sol`: from the first
/// node's best state (the lowest of equal costs) along each state's successor; value[k][i]
/// is the least cost from state i at node k to the end (+inf: none), next[k][i] its
/// successor. Leaves `sol` without a path when no first state reaches the end.
inline void read_out_staged_dp(const std::vector<std::vector<double>>& value,
                               const std::vector<std::vector<int>>& next, DpSolution& sol) {
  const int nodes = static_cast<int>(value.size());
  int s0 = -1;
  for (int i = 0; i < static_cast<int>(value[0].size()); ++i)
    if (std::isfinite(value[0][i]) && (s0 < 0 || value[0][i] < value[0][s0])) s0 = i;
  if (s0 < 0) return;
  sol.cost = value[0][s0];
  sol.states.resize(nodes);
  sol.states[0] = s0;
  for (int k = 0; k + 1 < nodes; ++k) sol.states[k + 1] = next[k][sol.states[k]];
}

/// Minimises sum_k cost(k, s_k, s_{k+1}) over state paths s_0..s_K with 0 <= s_k < levels[k],
/// trying from state i at node k only the successors j in candidates(k, i) = [first, last)
/// (clamped to the node's states): a caller that knows every other transition is forbidden
/// (e.g. from bounds on the acceleration) saves their evaluations, and the result is the
/// same as with every successor. `cost` is any callable double(int k, int i, int j)
/// returning +inf for a forbidden transition (any finite cost, of either sign, is handled
/// exactly). @throws std::invalid_argument if levels has < 2 nodes or a node has no state.
template <typename Cost, typename Candidates>
DpSolution solve_staged_dp(const std::vector<int>& levels, Cost&& cost, Candidates&& candidates) {
  const int nodes = static_cast<int>(levels.size());
  ARM_THROW_UNLESS(nodes >= 2, "staged DP has " << nodes << " nodes; should have >= 2");
  for (int k = 0; k < nodes; ++k)
    ARM_THROW_UNLESS(levels[k] >= 1,
                     "staged DP node " << k << " has " << levels[k] << " states; should have >= 1");
  constexpr double kInf = std::numeric_limits<double>::infinity();
  DpSolution sol;
  // value[k][i]: least cost from state i at node k to the end; next[k][i]: its successor
  std::vector<std::vector<double>> value(nodes);
  std::vector<std::vector<int>> next(nodes);
  value[nodes - 1].assign(levels[nodes - 1], 0.0);
  next[nodes - 1].assign(levels[nodes - 1], -1);
  for (int k = nodes - 2; k >= 0; --k) {
    value[k].assign(levels[k], kInf);
    next[k].assign(levels[k], -1);
    const std::vector<double>& later = value[k + 1];
    for (int i = 0; i < levels[k]; ++i) {
      double best = kInf;
      int arg = -1;
      const std::pair<int, int> range = candidates(k, i);
      const int first = range.first < 0 ? 0 : range.first;
      const int last = range.second > levels[k + 1] ? levels[k + 1] : range.second;
      for (int j = first; j < last; ++j) {
        if (!std::isfinite(later[j])) continue;
        ++sol.evaluations;
        const double c = cost(k, i, j);
        if (!std::isfinite(c)) continue;
        if (c + later[j] < best) {
          best = c + later[j];
          arg = j;
        }
      }
      value[k][i] = best;
      next[k][i] = arg;
    }
  }
  read_out_staged_dp(value, next, sol);
  return sol;
}

/// solve_staged_dp over every successor of every state (sum_k levels[k] * levels[k+1]
/// transitions).
template <typename Cost>
DpSolution solve_staged_dp(const std::vector<int>& levels, Cost&& cost) {
  return solve_staged_dp(levels, std::forward<Cost>(cost),
                         [&](int k, int) { return std::pair<int, int>(0, levels[k + 1]); });
}

}  // namespace armstudy::core::opt
