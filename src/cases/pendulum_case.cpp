// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/pendulum_case.hpp"

#include <cmath>

#include "cases/tray_arm_case.hpp"
#include "core/types.hpp"

namespace armstudy::cases {
namespace {
// a number read with its default (number_or: the key reference shows the loader's default),
// the default kept when the file's value was refused (the error is recorded)
double keep(double read, double fallback) { return std::isnan(read) ? fallback : read; }
}  // namespace

studies::PendulumSpec load_pendulum_spec(Map& root) {
  using core::kDeg;
  studies::PendulumSpec s = studies::default_pendulum_spec();
  auto sec = root.map("pendulum");
  if (!sec) return s;
  read_tray_arm(*sec, s.arm, nullptr);
  if (const auto v = sec->numbers("locked_deg", NumberRule::range(-360, 360, "deg"), 2,
                                  {s.theta1 / kDeg, s.theta2 / kDeg})) {
    s.theta1 = (*v)[0] * kDeg;
    s.theta2 = (*v)[1] * kDeg;
  }
  if (const auto v = sec->numbers("start_deg", NumberRule::range(-360, 360, "deg"), 2,
                                  {s.theta3 / kDeg, s.theta4 / kDeg})) {
    s.theta3 = (*v)[0] * kDeg;
    s.theta4 = (*v)[1] * kDeg;
  }
  if (const auto v = sec->numbers("start_rate_deg_s", NumberRule::range(-1e4, 1e4, "deg/s"), 2,
                                  {s.theta3_rate / kDeg, s.theta4_rate / kDeg})) {
    s.theta3_rate = (*v)[0] * kDeg;
    s.theta4_rate = (*v)[1] * kDeg;
  }
  s.duration = keep(sec->number_or("duration_s", s.duration, NumberRule::range(1e-3, 60.0, "s")),
                    s.duration);
  s.sample_step = keep(sec->number_or("sample_s", s.sample_step, NumberRule::range(1e-4, 1.0, "s")),
                       s.sample_step);
  s.snapshot_step =
      keep(sec->number_or("snapshot_s", s.snapshot_step, NumberRule::range(1e-3, 60.0, "s")),
           s.snapshot_step);
  s.rtol = keep(sec->number_or("rtol", s.rtol, NumberRule::range(1e-14, 1e-3, "")), s.rtol);
  s.atol = keep(sec->number_or("atol", s.atol, NumberRule::range(1e-16, 1e-3, "")), s.atol);
  s.drift_tolerance =
      keep(sec->number_or("drift_tolerance", s.drift_tolerance, NumberRule::positive("")),
           s.drift_tolerance);
  s.max_steps = sec->integer_or("max_steps", s.max_steps, 100, 100'000'000);
  // the strip and the locus draw every snapshot
  const double snapshots = std::floor(s.duration / s.snapshot_step + 1e-9) + 1;
  if (snapshots > kMaxPendulumSnapshots)
    sec->error("snapshot_s", "'pendulum.snapshot_s' is " + format_number(s.snapshot_step) +
                                 " s: " + format_number(snapshots) +
                                 " snapshots over duration_s = " + format_number(s.duration) +
                                 " s; expected at most " + std::to_string(kMaxPendulumSnapshots) +
                                 " (the strip and the locus draw every snapshot)");
  sec->finish();
  if (sec->diag().empty()) {
    Demand d;
    d.what = "the pendulum simulation";
    d.keys = "pendulum.duration_s and pendulum.sample_s";
    d.unit = "output samples";
    d.work = s.duration / s.sample_step + snapshots;
    d.work_budget = 1e7;
    d.work_per_second = 3e4;  // the bundled case: 416 samples in 0.012 s
    // the animation, and every snapshot in the strip and the locus (fainter poses too)
    d.frames_rendered = 40.0 + 3.0 * snapshots;
    d.memory_bytes = d.work * 300.0;  // time, states, energies and the ball's path per sample
    d.detail = format_number(d.work) + " samples of ~300 B";
    d.strip_frames = static_cast<int>(snapshots);
    d.mark = sec->node().Mark();
    sec->diag().demand(d);
  }
  return s;
}

}  // namespace armstudy::cases
