// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/placement/printed_limits.hpp"

#include <sstream>

#include "core/motion_program.hpp"

namespace armstudy::studies::placement {
namespace {

// "12.001" with 6 significant digits
std::string sig6(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

void check_point(const Spec& spec, const Candidate& c, const std::string& name,
                 PrintedLimitExcess& out) {
  if (c.status == CandidateStatus::kUnreachable) return;
  const LineMetrics& m = c.reported_metrics();
  if (!m.finite()) return;
  ++out.points;
  const char* joint[2] = {"root", "elbow"};
  const bool continuous = c.convergence.checked && c.convergence.peak_resolution > 0;
  const std::string at =
      continuous
          ? " on the continuous motion"
          : " at " + std::to_string(c.convergence.checked ? c.convergence.samples : spec.samples) +
                " samples";
  // one peak against its limit: the largest excess so far, and where
  const auto against = [&](double peak, double limit, const char* what, const char* unit, int j) {
    const double x = peak / limit - 1;
    if (!(x > out.relative)) return;
    out.relative = x;
    out.where = name + ": " + joint[j] + " " + what + " " + sig6(peak) + " " + unit + at;
  };
  for (int j = 0; j < 2; ++j) {
    if (spec.torque_limit)
      against(m.peak_torque[j], (*spec.torque_limit)[size_t(j)], "torque", "N m", j);
    if (spec.power_limit) against(m.peak_power[j], (*spec.power_limit)[size_t(j)], "power", "W", j);
  }
}

}  // namespace

PrintedLimitExcess printed_limit_excess(const Spec& spec, const Result& result) {
  PrintedLimitExcess out;
  for (const ProgramConfig& pc : result.cases) {
    const std::string name =
        std::string(core::program_name(pc.program)) + ", conf. " + std::to_string(pc.configuration);
    if (pc.found) check_point(spec, pc.refined, name + " optimum", out);
    for (const MarginPoint& mp : pc.margin_sensitivity)
      if (mp.found) check_point(spec, mp.optimum, name + ", margin " + sig6(mp.margin) + " m", out);
  }
  return out;
}

std::optional<Check> printed_limits_check(const Spec& spec, const Result& result) {
  if (!spec.torque_limit && !spec.power_limit) return std::nullopt;
  const PrintedLimitExcess e = printed_limit_excess(spec, result);
  std::string what =
      "largest relative excess of a printed point's peak torque or power over "
      "its limit on the continuous motion (peaks refined between the " +
      std::to_string(spec.samples) +
      " samples, resolution below 1e-13 relative; the refinement keeps the limits there), "
      "over " +
      std::to_string(e.points) + " printed points";
  if (e.relative > 0) what += "; largest: " + e.where;
  return make_check("limits_at_printed_samples", what, e.relative, 1e-12);
}

}  // namespace armstudy::studies::placement
