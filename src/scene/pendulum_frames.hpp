// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Frames of the pendulum test (003 Sec. 3, Fig. 2a): the tray and the rolling ball with
/// joints 1 and 2 locked, a snapshot every snapshot_step (0.13 s): a strip of the
/// snapshots and a stroboscopic locus of all of them with the ball's path.

#include <filesystem>
#include <string>
#include <vector>

#include "cases/case_info.hpp"
#include "scene/arm_scene.hpp"
#include "scene/rendered.hpp"
#include "scene/replay.hpp"
#include "studies/pendulum/solve.hpp"

namespace armstudy::scene {

/// The snapshots the strip shows (every snapshot_step).
std::vector<PoseSample> pendulum_snapshots(const studies::PendulumResult& result);

/// The scene of the frames (the tray arm framing the tray's swing).
ArmScene pendulum_scene(const studies::PendulumSpec& spec, const studies::PendulumResult& result,
                        const cases::RenderOptions& options);

/// Writes pendulum_snapshots_strip.png and pendulum_snapshots_locus.png into `dir`; returns
/// the file names and its animation (pendulum). @throws SceneError.
Rendered render_pendulum_frames(const studies::PendulumSpec& spec,
                                const studies::PendulumResult& result,
                                const cases::RenderOptions& options,
                                const std::filesystem::path& dir);

}  // namespace armstudy::scene
