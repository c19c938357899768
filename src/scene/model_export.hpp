// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// model.xml in a case's output folder: the MJCF of the scene the case's frames are drawn
/// in, generated from the case's own chain (so its masses, centres of mass and inertias are
/// the case's, mjcf_writer.hpp; the MuJoCo checks compile the same chain's bodies without
/// the scene's decor), with one <key> per frame of the strip: its time, qpos and qvel in
/// MuJoCo's coordinates (q_mj = J q, chain_map.hpp, so a spinner's hinge follows its joint).
/// MuJoCo's viewer (`simulate model.xml`) then shows the motion pose by pose through its
/// keyframes.

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/planar_chain.hpp"
#include "scene/replay.hpp"
#include "scene/study_frames.hpp"

namespace armstudy::scene {

/// The file name in every case folder.
inline constexpr const char* kModelFile = "model.xml";

/// The poses of the strip of `motion` with `frames` frames: `frames` times spread evenly
/// over it and the state interpolated there, exactly as write_strip takes them.
std::vector<PoseSample> strip_keyframes(const SampledMotion& motion, int frames);

/// `mjcf` (a scene generated for `chain`) with a <keyframe> section of one <key> per pose
/// ("frame1", ...: time, qpos, qvel) and a comment naming `motion`. The text is compiled by
/// MuJoCo first (to map the chain's coordinates into its own), so it is known to load.
/// @throws SceneError (ModelError) if MuJoCo cannot load `mjcf`; std::invalid_argument for
/// a pose whose size is not the chain's.
std::string mjcf_with_keyframes(const core::PlanarChain& chain, const std::string& mjcf,
                                std::span<const PoseSample> keys, const std::string& motion,
                                const std::string& source);

/// Writes `dir`/model.xml (mjcf_with_keyframes) atomically; returns the file name.
std::string write_model_xml(const std::filesystem::path& dir, const core::PlanarChain& chain,
                            const std::string& mjcf, std::span<const PoseSample> keys,
                            const std::string& motion, const std::string& source);

}  // namespace armstudy::scene
