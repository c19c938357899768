// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The "MuJoCo dynamic replay" section of a placement or time-optimal page: what MuJoCo
/// simulates itself and what it does not, the replay's numbers and check, the deviation from
/// the plan over time, and the frames with the simulated motion drawn over the planned one.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/page.hpp"
#include "studies/replay_results.hpp"

namespace armstudy::report {

/// One replayed motion: a placement optimum (program and configuration) or the single plan
/// of a study (program empty).
struct ReplayOf {
  std::string program;
  int configuration = 0;
  const studies::ReplayResults* replay = nullptr;
};

/// `replays` are a study's "mujoco_replay"; `frames` is results.json "frames" (the files
/// whose name holds "planned-and-simulated" are shown). Adds nothing when `replays` is empty.
void mujoco_replay_section(const std::vector<ReplayOf>& replays,
                           const std::vector<std::string>& frames, FigureWriter& figures,
                           CasePage& page);

}  // namespace armstudy::report
