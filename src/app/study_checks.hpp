// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The checks the pendulum and throwing pipelines run on a study's answer, each a function of
/// the measured figures and the case's limits (the placement and time-optimal studies have
/// theirs in studies/placement/checks.hpp and studies/time_optimal/solve.hpp).

#include <vector>

#include "studies/common.hpp"
#include "studies/pendulum/result.hpp"
#include "studies/pendulum/spec.hpp"
#include "studies/throwing/result.hpp"
#include "studies/throwing/spec.hpp"

namespace armstudy::app {

/// "pendulum_energy_drift": the relative energy drift against spec.drift_tolerance (none
/// unless the integration solved).
std::vector<studies::Check> pendulum_checks(const studies::PendulumSpec& spec,
                                            const studies::PendulumResult& result);

/// The throw's checks, in the order the report lists them: the answer's constraints at the
/// finer re-simulation (<who>_contact: contact margin - smallest normal force <= 0;
/// _friction, _ball_in_tray, _voltage, _current, _power, _release_theta3: the largest value
/// against its limit), <who>_converged (1 when not converged, allowed by
/// checks.allow_not_converged), open_loop_replay and rk4_accuracy (<= 1e-3); <who> is "idp"
/// when IDP is the answer, and "slsqp" whenever SLSQP ran. None before the IDP has a motion.
std::vector<studies::Check> throwing_checks(const studies::ThrowingSpec& spec,
                                            const studies::ThrowingResult& result);

}  // namespace armstudy::app
