// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// `study: placement` case files -> studies::placement::Spec.
///
/// The arm (`arm:`, see arm_loader.hpp) must have 2 active links and `gravity:` must be 0
/// (the study lives in a horizontal plane); without `arm:` it is the thesis's arm of
/// Kopmaz (2016), Ch. 9: L1 = 0.4 m, m1 = 4 kg, rG1 = 0.2 m, IG1 = m1 L1^2/12;
/// L2 = 0.2 m, m2 = 2 kg, rG2 = 0.1 m, IG2 = m2 L2^2/12; payload 1 kg at the tip.
///
/// ```yaml
/// placement:
///   length_fraction: 0.5     # L / Lmax, in (0, 1]; Lmax = 4 sqrt(L1 L2) (eq. 4.6)
///   length_m: 0.5657         # or L in m, in (0, Lmax]; give exactly one of the two
///   duration_s: 1.0          # T, s, > 0 (default 1, the thesis's value)
///   programs: [cycloidal, poly345]  # motion programs (default both of the thesis; any of
///                            # cycloidal, poly345, poly4567, trapezoidal)
///   configurations: [1, 2]   # elbow configurations (default both): 1 has q2 in (0, pi)
///   nx_s: 50                 # start-point steps: nx_s + 1 start points (default 50)
///   phi_step_deg: 1.0        # direction-angle step, deg, in (0, 45] (default 1, the thesis's)
///   samples: 401             # samples per trajectory, uniform in time, in [21, 100001]
///                            # (default 401: energy converged to ~1e-5 and the signed
///                            # work of every candidate clear of the margin below 1e-9 J);
///                            # a candidate clear of the margin whose embedded error estimate
///                            # exceeds 1e-4, and every printed energy, is doubled until it
///                            # converges to 1e-4 (studies/placement/converge.hpp)
///   singularity_margin_m: 0.01  # least distance of the line to either workspace boundary,
///                            # m, > 0 (default 0.01: 1/20 of the inner radius of the thesis's
///                            # arm, keeps |sin q2| >= 0.22 there; closer lines are singular)
///   torque_limits_Nm: [15, 5]   # optional peak |torque| per joint (root, elbow), N m, > 0
///   power_limits_W: [40, 10]    # optional peak |power| per joint, W, > 0
///   refine: true             # constrained refinement of the grid optimum (default true):
///                            # NLopt COBYLA with the clearances and limits as constraints,
///                            # to 1e-7 relative in energy (studies/placement/refine.hpp);
///                            # an optimum set by a clearance is re-solved at margins
///                            # 0.005-0.05 m (the margin sensitivity)
///   map:                     # energy map over root locations in the line's frame
///     nx: 200                # nodes along X, in [2, 1000] (default 200)
///     ny: 100                # nodes along Y >= 0, in [2, 1000] (default 100; Y < 0 is the
///                            # mirror image with the configurations swapped)
///   evaluate:                # optional fixed placements to evaluate, each either
///     - {label: thesis-2, x_s_m: 0.4764, phi_deg: 155.18}  # the thesis's line (x_s, phi)
///     - {label: bench, root_xy_m: [0.3, 0.25]}             # or the root (X, Y) in the
///                                                           # line's frame, m (eq. 4.14)
///   threads: 0               # sweep threads, 0 = all cores (default 0)
/// ```

#include "cases/yaml_reader.hpp"
#include "core/planar_chain.hpp"
#include "studies/placement/spec.hpp"

namespace armstudy::cases {

/// The thesis's arm (Kopmaz 2016, Ch. 9), the default of placement cases.
core::PlanarChain placement_default_arm();

/// The work and memory `spec` asks for (cases/budget.hpp), reported at `mark`.
Demand placement_demand(const studies::placement::Spec& spec, const YAML::Mark& mark);

/// Reads `arm:`, `gravity:` and `placement:` from the case's root mapping. Every problem
/// is recorded in root.diag() at its file:line:col, and the demand too; the returned spec is
/// meaningful only when no error was recorded.
studies::placement::Spec load_placement(Map& root);

}  // namespace armstudy::cases
