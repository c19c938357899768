// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The pendulum study's answer (plain data): the free swing sampled, its energies and drift.

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/types.hpp"
#include "studies/common.hpp"

namespace armstudy::studies {

/// Output of the pendulum study (plain data).
struct PendulumResult {
  Status status = Status::kUnsolvable;
  std::string message;
  std::string integrator;  ///< e.g. "DOPRI5 (Dormand-Prince 5(4), adaptive)"
  double rtol = 0, atol = 0;
  long steps_accepted = 0, steps_rejected = 0, evaluations = 0;
  std::vector<double> t;                          ///< s
  std::vector<core::JointVector> q, qd;           ///< (4) rad, rad/s: all four coordinates
  std::vector<double> kinetic, potential, total;  ///< J
  std::vector<Eigen::Vector2d> ball;              ///< m, ball centre
  std::vector<Eigen::Vector2d> circle_centre;     ///< m, the centre C of the ball's circle
  std::vector<double> snapshot_t;                 ///< s, every snapshot_step
  std::vector<int> snapshot_index;                ///< index into t of each snapshot
  double energy_initial = 0;                      ///< J
  double energy_scale = 0;      ///< J, largest kinetic energy (the energy exchanged)
  double energy_drift = 0;      ///< J, max |E(t) - E(0)|
  double energy_drift_rel = 0;  ///< energy_drift / energy_scale
  double run_time = 0;          ///< s, wall clock
};

}  // namespace armstudy::studies
