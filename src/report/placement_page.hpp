// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
// The placement page's helpers and parts shared by report/placement_section.cpp (the page)
// and report/placement_maps.cpp (its maps, energy over direction, root loci and trade-off).

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "report/number_format.hpp"
#include "report/plot.hpp"
#include "report/results_fields.hpp"
#include "report/study_sections.hpp"
#include "studies/placement/study_results.hpp"

namespace armstudy::report::placement_page {

using PS = studies::placement::StudyResults;

inline std::string id_label(const PS::Id& o) {
  return o.program + ", conf. " + as_text(o.configuration);
}
inline std::string id_key(const PS::Id& o) { return o.program + "/" + as_text(o.configuration); }
// a motion whose energy is withheld (on the inner circle, or not converged): no energy, peak
// or saving is printed
inline bool no_energy(const PS::Metrics& o) {
  return o.singular_trajectory.value_or(false) && !std::isfinite(o.energy_J);
}
// a candidate's status in words ("singular" in results.json is "inside the margin": the
// word singular is kept for motions that are singular themselves)
inline std::string status_text(const std::string& st) {
  if (st == "singular") return "inside the margin";
  if (st == "over_limit") return "over a limit";
  return st;
}
// The thesis's figure of the same kind for its example at this line length (Kopmaz 2016,
// Ch. 9: each example draws angles, velocities, accelerations, torques and powers, then the
// energy over the direction angle), e.g. kind 0 at L = 0.5 Lmax -> "Figure 9.12"; a length
// of no example: its figures in general.
inline std::string thesis_figure(const PS& pl, int kind) {
  struct Example {
    double fraction;
    int first;
  };
  static const Example examples[] = {{1.0, 1}, {0.8, 6}, {0.5, 12}, {0.4, 18}, {0.2, 24}};
  for (const Example& e : examples)
    if (std::abs(pl.length_fraction - e.fraction) < 1e-9 && !(e.first == 1 && kind == 5))
      return "Figure 9." + std::to_string(e.first + kind);
  return kind == 5 ? "Figures 9.11, 9.17, 9.23, 9.29" : "figures of Ch. 9";
}

/// The thesis's printed placements among the case's evaluations, by the convention of the
/// bundled examples (reports/cases/placement-example-*.yaml, docs/placement.md): the
/// evaluation labelled "thesis-config-K" is the placement the thesis prints as the optimum
/// of configuration K (of both programs), "thesis-only-line" its only line (example 1,
/// printed for both configurations); any other label, e.g. "thesis-config-2-tangent" (the
/// line the printed digits mean), is not a printed placement. The evaluations of `program`,
/// each at the configuration it is printed for, configuration 1 first.
std::vector<const PS::Evaluation*> printed_placements(const PS& pl, const std::string& program);

/// The program whose motion the thesis draws at its placements (Ch. 9: "only figures of
/// cycloidal motion program is provided"): cycloidal, else the case's first program.
std::string printed_program(const PS& pl);

/// "thesis's conf. K" (a legend entry of the plots at the printed placements) and its colour
/// key "printed/K"
std::string printed_label(const PS::Evaluation& e);
std::string printed_key(const PS::Evaluation& e);

/// A triangle at each printed placement's root of `configuration` (0: every configuration),
/// labelled for the legend.
std::vector<Marker> printed_root_markers(const PS& pl, int configuration);

/// The placement maps (one per program and configuration) and the energy over the direction
/// angle.
Section maps_section(const PS& pl, FigureWriter& figures);

/// The least cycle time over root locations, one map per configuration of the cycle-time
/// objective (over the energy maps' crop and cells), into `s`; how many were drawn.
int cycle_time_maps(const PS& pl, FigureWriter& figures, Section& s);

/// The cycle-time objective (placement.cycle_time): the fastest placement, its limits, its
/// maps, the trade-off with the energy objective. Nothing when the case has no such block.
std::optional<Section> cycle_time_section(const PS& pl, FigureWriter& figures);

/// The optimal root locations (the thesis's Fig. 9.30) into `maps`; the torque trade-off
/// (Pareto fronts) as a section of its own.
Section loci_and_tradeoff(const PS& pl, FigureWriter& figures, Section& maps);

}  // namespace armstudy::report::placement_page
