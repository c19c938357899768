// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// `arm:` and `gravity:` of a case file -> core::PlanarChain.
///
/// ```yaml
/// arm:
///   links:                 # base to tip
///     - length: 0.4        # m, > 0
///       mass: 4.0          # kg, >= 0
///       com: 0.2           # m from the joint along the link (default: length / 2)
///       com_lateral: 0.0   # m, perpendicular to the link (default 0)
///       inertia: rod       # kg m^2 about the centre of mass, or 'rod' for m L^2 / 12
///       joint: active      # or passive (default active)
///   payload: 1.0           # kg, a point mass at the tip (default 0)
///   point_masses:          # optional extra point masses
///     - {link: 2, at: 0.1, lateral: 0.0, mass: 0.5}
/// gravity: 9.81            # m/s^2 along -y; 0 for a horizontal plane
/// ```
///
/// or the arm of a robot description, read through MuJoCo (model_import/imported_arm.hpp):
///
/// ```yaml
/// arm:
///   model: scara.urdf      # URDF or MJCF, relative to the case file
/// ```

#include <optional>

#include "cases/yaml_reader.hpp"
#include "core/planar_chain.hpp"
#include "model_import/imported_arm.hpp"
#include "studies/arm_origin.hpp"

namespace armstudy::cases {

/// Reads `arm:` (falling back to `fallback`'s links and masses when absent) and
/// `gravity:` (falling back to fallback.gravity). `links_required` > 0 demands that many
/// links. Errors go to the map's Diagnostics; the fallback is returned on error.
/// `arm.model` (a URDF or MJCF file) fills `*imported` (when not null) with the model's
/// plane, joint names and limits; its gravity is the model's (a `gravity:` key is refused).
core::PlanarChain load_arm(Map& root, const core::PlanarChain& fallback, int links_required,
                           std::optional<model_import::ImportedArm>* imported = nullptr);

/// What model.xml and the report say of an imported arm (its limits are added by the
/// study's loader).
studies::ArmOrigin arm_origin(const model_import::ImportedArm& arm);

/// The model's joint ranges, [lo, hi] per joint, when it limits every joint (else empty).
std::vector<Eigen::Vector2d> model_ranges(const model_import::ImportedArm& arm);

/// Largest robot description `arm.model` reads, bytes.
inline constexpr std::size_t kMaxModelBytes = std::size_t(8) << 20;

/// Mass of the payload point mass at the tip of `chain` (the last point mass on the last
/// link at its tip), kg; 0 if none.
double payload_mass(const core::PlanarChain& chain);

}  // namespace armstudy::cases
