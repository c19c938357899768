// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The placement study re-solved from a known optimum (a sensitivity step,
/// app/sensitivity.hpp): each program and configuration that had an optimum in `nominal`
/// is refined (refine.hpp) from that optimum under `spec`, with no sweep, map, curve, Pareto
/// front, margin sweep or evaluations. Only `cases` (found, refined, decision, counts copied
/// from the nominal), status and message are filled.

#include <optional>

#include "studies/placement/result.hpp"
#include "studies/placement/spec.hpp"

namespace armstudy::studies::placement {

/// nullopt when an optimum of `nominal` is not admissible under `spec` (outside the new
/// margin or over a new limit): the caller then solves `spec` from scratch.
std::optional<Result> solve_warm(const Spec& spec, const Result& nominal);

}  // namespace armstudy::studies::placement
