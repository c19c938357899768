// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The source's arm, apart from the solver: the case loader (src/cases/time_optimal_case.cpp)
// needs it, and the fuzz build of the loaders (tests/fuzz) then links no solver.
#include "studies/time_optimal/spec.hpp"

namespace armstudy::studies::time_optimal {

core::PlanarChain default_arm(double L1, double L2) {
  core::PlanarChain c;
  // massless links, 1.0 kg at the end of each (Ozkipcak 1994)
  c.links = {{L1, 0.0, L1 / 2, 0.0, 0.0, true}, {L2, 0.0, L2 / 2, 0.0, 0.0, true}};
  c.point_masses = {{0, L1, 0.0, 1.0}, {1, L2, 0.0, 1.0}};
  c.gravity = 0.0;
  return core::make_chain(c);
}

}  // namespace armstudy::studies::time_optimal
