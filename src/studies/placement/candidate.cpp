// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/placement/candidate.hpp"

#include <cmath>

#include "studies/placement/geometry.hpp"

namespace armstudy::studies::placement {

bool within_limits(const Spec& spec, const LineMetrics& m) {
  if (spec.torque_limit) {
    for (int j = 0; j < 2; ++j)
      if (m.peak_torque[j] > (*spec.torque_limit)[j]) return false;
  }
  if (spec.power_limit) {
    for (int j = 0; j < 2; ++j)
      if (m.peak_power[j] > (*spec.power_limit)[j]) return false;
  }
  return true;
}

char status_char(CandidateStatus s) {
  switch (s) {
    case CandidateStatus::kUnreachable: return '.';
    case CandidateStatus::kSingular: return 's';
    case CandidateStatus::kOverLimit: return 'x';
    case CandidateStatus::kFeasible: return 'o';
  }
  return '?';
}

const char* status_name(CandidateStatus s) {
  switch (s) {
    case CandidateStatus::kUnreachable: return "unreachable";
    case CandidateStatus::kSingular: return "singular";
    case CandidateStatus::kOverLimit: return "over_limit";
    case CandidateStatus::kFeasible: return "feasible";
  }
  return "?";
}

CandidateStatus classify(const Spec& spec, double boundary_distance, const LineMetrics& m) {
  // a line that touches a boundary within roundoff (e.g. the thesis's (4.10) line) is on it
  if (boundary_distance < -kTouch) return CandidateStatus::kUnreachable;
  // a line closer to a boundary than the margin, or a sample at a folded/stretched elbow
  if (boundary_distance < spec.singularity_margin - kMarginTol || !m.finite())
    return CandidateStatus::kSingular;
  if (!within_limits(spec, m)) return CandidateStatus::kOverLimit;
  return CandidateStatus::kFeasible;
}

Candidate evaluate_candidate(const Spec& spec, const Arm2& arm, const ProgramTable& table,
                             int configuration, double x_s, double phi) {
  Candidate c;
  c.x_s = x_s;
  c.phi = phi;
  c.root = root_in_line_frame(x_s, phi);
  const Line line = thesis_line(x_s, phi);
  const LineCheck chk = check_line(arm.L1, arm.L2, line, spec.length);
  c.boundary_distance = chk.boundary_distance;
  c.inner_clearance = chk.r_min - std::abs(arm.L1 - arm.L2);
  c.outer_clearance = (arm.L1 + arm.L2) - chk.r_max;
  c.min_abs_sin = chk.min_abs_sin;
  if (chk.boundary_distance >= -kTouch) c.metrics = evaluate_line(arm, table, line, configuration);
  c.status = classify(spec, chk.boundary_distance, c.metrics);
  return c;
}

}  // namespace armstudy::studies::placement
