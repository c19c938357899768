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

#include "cases/yaml_reader.hpp"
#include "core/planar_chain.hpp"

namespace armstudy::cases {

/// Reads `arm:` (falling back to `fallback`'s links and masses when absent) and
/// `gravity:` (falling back to fallback.gravity). `links_required` > 0 demands that many
/// links. Errors go to the map's Diagnostics; the fallback is returned on error.
core::PlanarChain load_arm(Map& root, const core::PlanarChain& fallback, int links_required);

/// Mass of the payload point mass at the tip of `chain` (the last point mass on the last
/// link at its tip), kg; 0 if none.
double payload_mass(const core::PlanarChain& chain);

}  // namespace armstudy::cases
