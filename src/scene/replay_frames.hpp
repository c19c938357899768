// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Frames of MuJoCo's dynamic replay: the planned motion (the arm, posed kinematically) with
/// the motion MuJoCo simulated from the plan's torques drawn over it as a magenta skeleton (links
/// as thin lines, joints as dots), at equal time steps; where the two agree the skeleton runs
/// along the middle of the arm.

#include <filesystem>
#include <string>
#include <vector>

#include "cases/case_info.hpp"
#include "scene/frames.hpp"
#include "scene/study_replays.hpp"

namespace armstudy::scene {

/// Writes `dir`/`name`_strip.png: `frames` frames of the replay; returns the file name.
/// `chain` is the chain `sr` draws (the replay's coordinates in its frame).
std::string write_replay_strip(SceneRenderer& sr, const core::PlanarChain& chain,
                               const DynamicReplay& replay, int frames, const std::string& title,
                               const std::filesystem::path& dir, const std::string& name);

/// The time-optimal replay's strip: "time_optimal_planned-and-simulated_strip.png".
std::vector<std::string> render_time_optimal_replay(const studies::time_optimal::Spec& spec,
                                                    const studies::time_optimal::Result& result,
                                                    const DynamicReplay& replay,
                                                    const cases::RenderOptions& options,
                                                    const std::filesystem::path& dir);

/// One strip per placement optimum, in the line's frame like the placement frames:
/// "placement_<program>_c<N>_planned-and-simulated_strip.png".
std::vector<std::string> render_placement_replay(const studies::placement::Spec& spec,
                                                 const studies::placement::Result& result,
                                                 const std::vector<PlacementReplay>& replays,
                                                 const cases::RenderOptions& options,
                                                 const std::filesystem::path& dir);

}  // namespace armstudy::scene
