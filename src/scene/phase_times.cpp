// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/phase_times.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

namespace armstudy::scene {
namespace {

long long now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

struct ThreadPhases {
  std::vector<std::pair<std::string, double>> totals;  // "outer.inner" -> seconds
  std::vector<const char*> open;                       // the scopes open now
  void add(const std::string& name, double s) {
    for (auto& [n, v] : totals)
      if (n == name) {
        v += s;
        return;
      }
    totals.emplace_back(name, s);
  }
  std::string path(const char* leaf) const {
    std::string p;
    for (const char* o : open) p += std::string(o) + ".";
    return p + leaf;
  }
};
thread_local ThreadPhases t_phases;

}  // namespace

bool phase_times_enabled() {
  static const bool on = [] {
    const char* v = std::getenv("ARMSTUDY_PHASE_TIMES");
    return v && *v && std::strcmp(v, "0") != 0;
  }();
  return on;
}

PhaseScope::PhaseScope(const char* name) : name_(name) {
  if (!phase_times_enabled()) return;
  // the full name is fixed at the start: registered in first-seen order, parent first
  t_phases.add(t_phases.path(name_), 0.0);
  t_phases.open.push_back(name_);
  start_ns_ = now_ns();
}

PhaseScope::~PhaseScope() {
  if (start_ns_ < 0) return;
  const double s = 1e-9 * static_cast<double>(now_ns() - start_ns_);
  t_phases.open.pop_back();
  t_phases.add(t_phases.path(name_), s);
}

std::string take_phase_times() {
  if (!phase_times_enabled()) return "";
  std::string out;
  for (const auto& [n, v] : t_phases.totals) {
    char b[32];
    std::snprintf(b, sizeof b, " %.3f s", v);
    out += (out.empty() ? "" : ", ") + n + b;
  }
  t_phases.totals.clear();
  return out;
}

}  // namespace armstudy::scene
