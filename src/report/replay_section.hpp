#pragma once
/// The "MuJoCo dynamic replay" section of a placement or time-optimal page: what MuJoCo
/// simulates itself and what it does not, the replay's numbers and check, the deviation from
/// the plan over time, and the frames with the simulated motion drawn over the planned one.

#include <nlohmann/json.hpp>

#include "report/page.hpp"

namespace armstudy::report {

/// `replay` is a study's "mujoco_replay" (one object, or an array of objects with program
/// and configuration); `frames` is results.json "frames" (the files whose name holds
/// "planned-and-simulated" are shown). Adds nothing when `replay` is missing or empty.
void mujoco_replay_section(const nlohmann::json& replay, const nlohmann::json& frames,
                           FigureWriter& figures, CasePage& page);

}  // namespace armstudy::report
