// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/mujoco_check.hpp"

#include <algorithm>
#include <stdexcept>

#include "scene/chain_map.hpp"
#include "scene/mjcf_writer.hpp"
#include "scene/mujoco_model.hpp"

namespace armstudy::scene {

MujocoAgreement mujoco_agreement(const core::PlanarChain& chain,
                                 std::span<const core::JointVector> q,
                                 std::span<const core::JointVector> qd,
                                 std::span<const core::JointVector> qdd,
                                 std::span<const core::JointVector> tau) {
  if (qd.size() != q.size() || qdd.size() != q.size() || tau.size() != q.size())
    throw std::invalid_argument("mujoco_agreement: q, qd, qdd, tau differ in length");
  MujocoModel mm(write_mjcf(chain), "the generated model of the case's arm");
  const ChainMap map(chain, mm.model());
  mjModel* m = mm.model();
  mjData* d = mm.data();
  // the spin constraint holds exactly by construction: its (soft) force must not enter
  m->opt.disableflags |= mjDSBL_EQUALITY;
  const int n = chain.num_links(), nv = m->nv;
  const Eigen::MatrixXd& J = map.jacobian();
  double tau_scale = 0, qdd_scale = 0, tau_err = 0, qdd_err = 0;
  MujocoAgreement a;
  a.samples = static_cast<int>(q.size());
  Eigen::Matrix<mjtNum, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> M(nv, nv);
  for (size_t k = 0; k < q.size(); ++k) {
    mj_resetData(m, d);
    map.set_state(m, d, q[k], qd[k], &qdd[k]);
    mj_inverse(m, d);
    const core::JointVector tau_mj = map.project(d->qfrc_inverse);
    // MuJoCo's forward dynamics with the passive joints free: reduced M and bias
    mj_fullM(m, M.data(), d->qM);
    const Eigen::MatrixXd Mc = J.transpose() * M * J;
    const core::JointVector h = map.project(d->qfrc_bias);
    // active accelerations prescribed, passive ones solved with zero passive torque
    std::vector<int> act, pas;
    for (int i = 0; i < n; ++i) (chain.links[i].active ? act : pas).push_back(i);
    for (int i : act) {
      tau_scale = std::max(tau_scale, std::abs(tau[k][i]));
      const double e = std::abs(tau_mj[i] - tau[k][i]);
      if (e > tau_err) {
        tau_err = e;
        a.worst_sample = static_cast<int>(k);
      }
    }
    if (!pas.empty()) {
      const int np = static_cast<int>(pas.size());
      Eigen::MatrixXd Mpp(np, np);
      Eigen::VectorXd rhs(np);
      for (int r = 0; r < np; ++r) {
        rhs[r] = -h[pas[r]];
        for (int i : act) rhs[r] -= Mc(pas[r], i) * qdd[k][i];
        for (int c = 0; c < np; ++c) Mpp(r, c) = Mc(pas[r], pas[c]);
      }
      const Eigen::VectorXd qdd_p = Mpp.ldlt().solve(rhs);
      for (int r = 0; r < np; ++r) {
        qdd_scale = std::max(qdd_scale, std::abs(qdd[k][pas[r]]));
        qdd_err = std::max(qdd_err, std::abs(qdd_p[r] - qdd[k][pas[r]]));
      }
    }
  }
  a.torque_rel = tau_scale > 0 ? tau_err / tau_scale : tau_err;
  a.acceleration_rel = qdd_scale > 0 ? qdd_err / qdd_scale : qdd_err;
  return a;
}

std::vector<studies::Check> mujoco_checks(const MujocoAgreement& a, bool has_passive,
                                          double tolerance) {
  std::vector<studies::Check> out;
  out.push_back(studies::make_check(
      "mujoco_inverse_dynamics",
      "MuJoCo's mj_inverse on the generated MJCF gives the motion's joint torques: max |delta| "
      "over the largest |tau|, " +
          std::to_string(a.samples) + " samples",
      a.torque_rel, tolerance));
  if (has_passive)
    out.push_back(studies::make_check(
        "mujoco_passive_accelerations",
        "MuJoCo's mass matrix and bias forces give the passive joints' accelerations: max "
        "|delta| over the largest |qdd|",
        a.acceleration_rel, tolerance));
  return out;
}

}  // namespace armstudy::scene
