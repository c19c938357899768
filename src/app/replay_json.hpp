// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// MuJoCo's dynamic replay (scene/dynamic_replay.hpp) as its typed results.json part
/// (studies/replay_results.hpp), shared by the placement and time-optimal sections.

#include <nlohmann/json.hpp>

#include "scene/dynamic_replay.hpp"
#include "studies/replay_results.hpp"

namespace armstudy::app {

studies::ReplayResults replay_results(const scene::DynamicReplay& replay);

}  // namespace armstudy::app
