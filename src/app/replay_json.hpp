#pragma once
/// MuJoCo's dynamic replay (scene/dynamic_replay.hpp) as its typed results.json part
/// (studies/replay_section.hpp), shared by the placement and time-optimal sections.

#include <nlohmann/json.hpp>

#include "scene/dynamic_replay.hpp"
#include "studies/replay_section.hpp"

namespace armstudy::app {

studies::ReplaySection replay_section(const scene::DynamicReplay& replay);

}  // namespace armstudy::app
