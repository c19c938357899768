// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The physical sizes an arm may have (docs/budgets.md, "What a case or sweep file may be"):
/// a link from 1 mm to 1 km, a mass of none or from 1 mg to 1000 t, an inertia up to 1e6
/// kg m^2, an offset (a centre of mass, a point mass's place) within 1 km of its joint.
/// Beyond them MuJoCo refuses the arm's model ("fromto points too close" below about 1e-15
/// m once written with six digits) or the replay of a study no longer checks (MuJoCo's
/// stand-in masses of 2e-12 kg and its inverse dynamics at 1e-4 m links), so a case is
/// refused when it is read, by `validate` as by `run`, at the key that breaks them.

#include <string>
#include <vector>

#include "cases/yaml_reader.hpp"
#include "core/planar_chain.hpp"

namespace armstudy::cases {

inline constexpr double kMinLinkLength_m = 1e-3;
inline constexpr double kMaxLength_m = 1e3;
inline constexpr double kMinMass_kg = 1e-6;
inline constexpr double kMaxMass_kg = 1e6;
inline constexpr double kMaxInertia_kg_m2 = 1e6;

/// A link's length: [1e-3, 1e3] m.
inline NumberRule link_length_rule() {
  return NumberRule::range(kMinLinkLength_m, kMaxLength_m, "m");
}
/// An offset along or across a link (a centre of mass, a point mass): [-1e3, 1e3] m.
inline NumberRule offset_rule() { return NumberRule::range(-kMaxLength_m, kMaxLength_m, "m"); }
/// A mass that may be none: 0 or [1e-6, 1e6] kg.
inline NumberRule mass_or_zero_rule() {
  return NumberRule::zero_or_range(kMinMass_kg, kMaxMass_kg, "kg");
}
/// A mass there must be: [1e-6, 1e6] kg.
inline NumberRule mass_rule() { return NumberRule::range(kMinMass_kg, kMaxMass_kg, "kg"); }
/// An inertia: [0, 1e6] kg m^2 (a small one is as harmless as none).
inline NumberRule inertia_rule() { return NumberRule::range(0.0, kMaxInertia_kg_m2, "kg m^2"); }

/// What of `chain` (an arm read from a robot description) is beyond the bounds above, one
/// sentence each, naming the link by `joint_names` where given ("link 2 (joint 'elbow'): the
/// length is 1e-100 m; should be in [0.001, 1000] m"); empty when every size is within them.
std::vector<std::string> chain_size_problems(const core::PlanarChain& chain,
                                             const std::vector<std::string>& joint_names);

}  // namespace armstudy::cases
