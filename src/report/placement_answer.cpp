// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// the placement study's lines of the answer box (page 1): what decides each optimum, the
// assumptions of the energy integral, and the locus of the optimum of least energy
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "report/answer_box.hpp"
#include "report/number_format.hpp"
#include "report/results_record.hpp"
#include "report/study_sections.hpp"
#include "studies/placement/study_results.hpp"

namespace armstudy::report {
namespace {

using PS = studies::placement::StudyResults;

std::string binding_words(const PS::Decision& d) {
  const std::string& b = d.binding;
  const std::string margin = format_sig(d.margin_m, 3) + " m";
  const std::string joint = d.joint ? as_text(*d.joint) : "n/a";
  if (b == "interior")
    return "interior, nothing binds (clearances beyond the " + margin +
           " margin: " + format_sig(d.inner_slack_m, 3) + " m inner, " +
           format_sig(d.outer_slack_m, 3) + " m outer)";
  if (b == "inner_clearance")
    return "the " + margin + " clearance margin to the inner circle (a setting)";
  if (b == "outer_clearance")
    return "the " + margin + " clearance margin to the outer circle (a setting)";
  if (b == "torque_limit") return "the torque limit of joint " + joint + " binds";
  if (b == "power_limit") return "the power limit of joint " + joint + " binds";
  return b.empty() ? "not reported" : b;
}

// the active constraints of `d` as (constraint, joint) pairs
std::vector<std::pair<std::string, std::optional<int>>> active_of(const PS::Decision& d) {
  std::vector<std::pair<std::string, std::optional<int>>> out;
  for (const auto& a : d.active) out.emplace_back(a.constraint, a.joint);
  return out;
}

// lines of the answer box that share their text: (text, who), in order of first appearance
using GroupedLines = std::vector<std::pair<std::string, std::string>>;

// adds `who` to the line of `text`, or a new line
void add_to_group(GroupedLines& lines, const std::string& text, const std::string& who) {
  auto it =
      std::find_if(lines.begin(), lines.end(), [&](const auto& d) { return d.first == text; });
  if (it == lines.end())
    lines.emplace_back(text, who);
  else
    it->second += ", " + who;
}

}  // namespace

std::string placement_also_active(
    const std::vector<std::pair<std::string, std::optional<int>>>& active) {
  std::string out;
  for (size_t k = 1; k < active.size(); ++k) {
    const auto& [c, joint] = active[k];
    const std::string j = joint ? as_text(*joint) : "";
    out += (out.empty() ? "" : ", ") +
           (c == "inner_clearance"   ? std::string("the clearance margin to the inner circle")
            : c == "outer_clearance" ? std::string("the clearance margin to the outer circle")
            : c == "torque_limit"    ? "the torque limit of joint " + j
            : c == "power_limit"     ? "the power limit of joint " + j
                                     : c);
  }
  return out.empty() ? "" : "; also active: " + out;
}

void placement_answer(const PS& pl, const ResultsRecord& record, AnswerBox& a) {
  // optima decided alike share one line: "cycloidal 1, poly345 1: ..."
  GroupedLines decided;
  for (const auto& o : pl.optima)
    add_to_group(decided,
                 binding_words(o.decided_by) + placement_also_active(active_of(o.decided_by)),
                 o.program + " " + as_text(o.configuration));
  for (const auto& [words, who] : decided) a.binding.push_back(who + ": " + words);
  // configurations 1 and 2 tie at mirrored optima: say so once, and why (docs/defects.md)
  std::string ties;
  bool mirrored = true;
  for (const auto& o1 : pl.optima) {
    if (o1.configuration != 1) continue;
    for (const auto& o2 : pl.optima) {
      if (o2.configuration != 2 || o2.program != o1.program) continue;
      const double gap = std::abs(o1.energy_J - o2.energy_J) / std::max(o1.energy_J, o2.energy_J);
      if (!(gap <= 1e-6)) continue;
      mirrored = mirrored && std::hypot(o1.root_xy_m[0] + o2.root_xy_m[0] - pl.length_m,
                                        o1.root_xy_m[1] - o2.root_xy_m[1]) <= 1e-3;
      ties += (ties.empty() ? "" : ", ") + o1.program + " " + format_sig(o1.energy_J, 6) + " J";
    }
  }
  if (!ties.empty())
    a.binding.push_back(
        "configurations 1 and 2 tie (" + ties + ")" +
        (mirrored ? ": mirrored in the line's perpendicular bisector and run backwards in time, "
                    "each is the other (docs/defects.md, kopmaz-configuration-symmetry)"
                  : ""));
  // the fastest cycle's limits (the study's sentence gives its time and place)
  if (pl.cycle_time)
    for (const auto& c : pl.cycle_time->configurations) {
      if (!c.optimum.found || !c.optimum.converged) continue;
      std::string on;
      for (const auto& u : c.optimum.converged->limits)
        if (u.binding)
          on += (on.empty() ? "" : ", ") + ("joint " + as_text(u.joint) + "'s " + u.kind);
      a.binding.push_back(
          "fastest cycle, configuration " + as_text(c.configuration) + ": " +
          (on.empty() ? std::string("no joint limit binds") : "runs on " + on) +
          (c.optimum.set_by_margin.value_or(false) ? "; the clearance margin sets its place" : ""));
    }
  GroupedLines unsolved;
  for (const auto& u : pl.unsolved)
    add_to_group(unsolved, u.reason, u.program + " " + as_text(u.configuration));
  for (const auto& [reason, who] : unsolved)
    a.binding.push_back(who + ": no optimum (" + reason + ")");
  a.assumptions.push_back(
      "energy integral (8.1): adaptive Gauss-Kronrod quadrature to 1e-9 "
      "for the printed motions (the sweep: " +
      as_text(pl.samples) + " samples, doubled until it changes by < 1e-4)");
  a.assumptions.push_back("singular: a line within " + format_sig(pl.singularity_margin_m, 3) +
                          " m of the annulus' boundary (a setting)");
  a.assumptions.push_back(pl.torque_limits_Nm || pl.power_limits_W
                              ? "actuator limits as the case gives them"
                              : "no actuator limits (any torque, as in the thesis)");
  a.assumptions.push_back(
      "rest to rest, zero end accelerations; no actuator masses (as the thesis)");
  if (pl.cycle_time)
    a.assumptions.push_back(
        "cycle time: the exact time-optimal solver under the case's joint velocity and torque "
        "limits, rest to rest; its energy is the same integral (8.1) over that motion");
  // the key picture: the locus of the optimum of least energy; energies equal within their
  // error estimates (mirror-image optima) are a tie and the first stays, as in the answer
  double least = INFINITY, least_error = 0;
  std::string best;
  for (const auto& o : pl.optima) {
    const double error = o.energy_error_J.value_or(0.0);
    if (o.energy_J < least - (error + least_error)) {
      least = o.energy_J;
      least_error = error;
      best = "placement_" + o.program + "_c" + as_text(o.configuration) + "_locus.png";
    }
  }
  for (const std::string& f : record.frames)
    if (f == best) a.picture = f;
}

}  // namespace armstudy::report
