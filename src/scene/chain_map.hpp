// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The linear map between a PlanarChain's coordinates and those of its generated MuJoCo
/// model: q_mj = J q. Chain joint i is MuJoCo joint "joint<i+1>"; a coupling spinner's
/// hinge "spin<k>_joint" turns by psi = ratio * q[joint] (mjcf_writer.hpp). Because the map
/// is linear and constant, qd_mj = J qd, qdd_mj = J qdd and tau_chain = J^T qfrc_mj exactly.

#include <mujoco/mujoco.h>
#include <Eigen/Dense>

#include "core/planar_chain.hpp"
#include "core/types.hpp"

namespace armstudy::scene {

class ChainMap {
 public:
  /// Builds J (nv x N) from the joint names of `model`.
  /// @throws SceneError if the model lacks a chain joint, has non-hinge joints, or
  /// nq != nv.
  ChainMap(const core::PlanarChain& chain, const mjModel* model);

  /// (nv x N) dimensionless.
  const Eigen::MatrixXd& jacobian() const { return J_; }
  /// N, the chain's joint count.
  int num_chain() const { return static_cast<int>(J_.cols()); }

  /// Writes qpos = J q and qvel = J qd (and qacc = J qdd if qdd is given) into `data`.
  void set_state(const mjModel* model, mjData* data, const core::JointVector& q,
                 const core::JointVector& qd, const core::JointVector* qdd = nullptr) const;
  /// The chain coordinates read from data->qpos (rad).
  core::JointVector chain_q(const mjData* data) const;
  /// The chain velocities read from data->qvel (rad/s).
  core::JointVector chain_qd(const mjData* data) const;
  /// Projects MuJoCo generalized forces (nv) onto the chain: J^T f (N), N m.
  core::JointVector project(const mjtNum* f) const;
  /// Dof address of chain joint i in MuJoCo.
  int dof(int i) const { return dof_[i]; }

 private:
  Eigen::MatrixXd J_;
  Eigen::Matrix<int, Eigen::Dynamic, 1, 0, core::kMaxLinks, 1> dof_;
};

}  // namespace armstudy::scene
