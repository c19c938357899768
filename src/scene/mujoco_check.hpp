// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// MuJoCo's dynamics along a computed motion, as a check a study can put in results.json:
/// the inverse dynamics of the generated model (mj_inverse, projected onto the chain's
/// coordinates) must give the motion's torques, and MuJoCo's forward dynamics must give the
/// passive joints' accelerations. Exact up to rounding for any chain armstudy builds (coupling
/// spinners are eliminated exactly with q_mj = J q: M = J^T M_mj J, h = J^T qfrc_bias).

#include <span>

#include "core/planar_chain.hpp"
#include "core/types.hpp"
#include "studies/common.hpp"

namespace armstudy::scene {

/// Largest disagreements along a motion (relative to the largest |tau| resp. |qdd| of the
/// motion over the checked joints).
struct MujocoAgreement {
  double torque_rel = 0;        ///< active joints: |tau_mj - tau| / max |tau|
  double acceleration_rel = 0;  ///< passive joints: |qdd_mj - qdd| / max |qdd| (0 if none)
  int samples = 0;
  int worst_sample = 0;  ///< index of the worst torque disagreement
};

/// Replays the samples (q, qd, qdd, tau: equal sizes, (N) each) in the chain's generated
/// MJCF. @throws SceneError (ModelError) if MuJoCo cannot load the model;
/// std::invalid_argument on mismatched sizes.
MujocoAgreement mujoco_agreement(const core::PlanarChain& chain,
                                 std::span<const core::JointVector> q,
                                 std::span<const core::JointVector> qd,
                                 std::span<const core::JointVector> qdd,
                                 std::span<const core::JointVector> tau);

/// The agreement as two studies::Check ("mujoco_inverse_dynamics",
/// "mujoco_passive_accelerations"; the second only with passive joints), passing at
/// `tolerance` relative (1e-6 by default, the bound).
std::vector<studies::Check> mujoco_checks(const MujocoAgreement& a, bool has_passive,
                                          double tolerance = 1e-6);

}  // namespace armstudy::scene
