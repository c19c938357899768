// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/replay.hpp"

#include <cmath>

#include "scene/scene_error.hpp"

namespace armstudy::scene {

void begin_replay(MujocoModel& mm) { mj_resetData(mm.model(), mm.data()); }

void set_pose(MujocoModel& mm, const ChainMap& map, const PoseSample& s) {
  const core::JointVector qd =
      s.qd.size() == s.q.size() ? s.qd : core::JointVector::Zero(s.q.size());
  map.set_state(mm.model(), mm.data(), s.q, qd);
  mm.data()->time = s.t;
  mj_forward(mm.model(), mm.data());
}

std::vector<PoseSample> simulate(MujocoModel& mm, const ChainMap& map, const PoseSample& start,
                                 const std::vector<double>& times) {
  begin_replay(mm);
  set_pose(mm, map, start);
  const double h = mm.model()->opt.timestep;
  long step = 0;
  std::vector<PoseSample> out;
  out.reserve(times.size());
  for (double t : times) {
    if (t < start.t) throw SceneError("simulate: sample time before the start");
    const long target = std::lround((t - start.t) / h);
    for (; step < target; ++step) mj_step(mm.model(), mm.data());
    out.push_back({start.t + step * h, map.chain_q(mm.data()), map.chain_qd(mm.data())});
  }
  return out;
}

}  // namespace armstudy::scene
