// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/chain_map.hpp"

#include <string>

#include "scene/mjcf_writer.hpp"
#include "scene/scene_error.hpp"

namespace armstudy::scene {

ChainMap::ChainMap(const core::PlanarChain& chain, const mjModel* m) {
  const int n = chain.num_links();
  if (m->nq != m->nv) throw SceneError("MuJoCo model has nq != nv; expected hinge joints only");
  for (int j = 0; j < m->njnt; ++j)
    if (m->jnt_type[j] != mjJNT_HINGE)
      throw SceneError("MuJoCo model joint " + std::to_string(j) + " is not a hinge");
  J_.setZero(m->nv, n);
  dof_.resize(n);
  for (int i = 0; i < n; ++i) {
    const std::string name = "joint" + std::to_string(i + 1);
    const int id = mj_name2id(m, mjOBJ_JOINT, name.c_str());
    if (id < 0) throw SceneError("MuJoCo model has no joint '" + name + "' of the chain");
    dof_[i] = m->jnt_dofadr[id];
    J_(dof_[i], i) = 1.0;
  }
  // coupling spinners: psi = ratio * q[joint]
  for (const SpinnerBody& b : spinner_bodies(chain)) {
    if (b.joint < 0) continue;
    const int id = mj_name2id(m, mjOBJ_JOINT, b.joint_name.c_str());
    if (id < 0) throw SceneError("MuJoCo model has no joint '" + b.joint_name + "' of a spinner");
    J_(m->jnt_dofadr[id], b.joint) = b.ratio;
  }
}

void ChainMap::set_state(const mjModel* m, mjData* d, const core::JointVector& q,
                         const core::JointVector& qd, const core::JointVector* qdd) const {
  const Eigen::VectorXd qm = J_ * q, vm = J_ * qd;
  for (int k = 0; k < m->nv; ++k) {
    d->qpos[k] = qm[k];
    d->qvel[k] = vm[k];
  }
  if (qdd) {
    const Eigen::VectorXd am = J_ * *qdd;
    for (int k = 0; k < m->nv; ++k) d->qacc[k] = am[k];
  }
}

core::JointVector ChainMap::chain_q(const mjData* d) const {
  core::JointVector q(num_chain());
  for (int i = 0; i < num_chain(); ++i) q[i] = d->qpos[dof_[i]];
  return q;
}

core::JointVector ChainMap::chain_qd(const mjData* d) const {
  core::JointVector qd(num_chain());
  for (int i = 0; i < num_chain(); ++i) qd[i] = d->qvel[dof_[i]];
  return qd;
}

core::JointVector ChainMap::project(const mjtNum* f) const {
  const Eigen::Map<const Eigen::VectorXd> fm(f, J_.rows());
  return J_.transpose() * fm;
}

}  // namespace armstudy::scene
