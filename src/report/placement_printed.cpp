// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// The thesis's printed placements among a placement case's evaluations (Kopmaz 2016, Ch. 9):
// which evaluation is the placement printed for which configuration, and its marks on the
// maps (the thesis's Fig. 9.30 draws these roots)
#include <algorithm>
#include <cmath>

#include "report/placement_page.hpp"

namespace armstudy::report::placement_page {

namespace {

// the configurations an evaluation's label says the thesis printed it for (none: not printed)
std::vector<int> printed_for(const std::string& label) {
  if (label == "thesis-only-line") return {1, 2};
  if (label == "thesis-config-1") return {1};
  if (label == "thesis-config-2") return {2};
  return {};
}

}  // namespace

std::vector<const PS::Evaluation*> printed_placements(const PS& pl, const std::string& program) {
  std::vector<const PS::Evaluation*> out;
  for (const auto& e : pl.evaluations) {
    if (e.program != program) continue;
    const std::vector<int> confs = printed_for(e.label);
    if (std::find(confs.begin(), confs.end(), e.configuration) != confs.end()) out.push_back(&e);
  }
  std::stable_sort(out.begin(), out.end(), [](const PS::Evaluation* a, const PS::Evaluation* b) {
    return a->configuration < b->configuration;
  });
  return out;
}

std::string printed_program(const PS& pl) {
  for (const auto& e : pl.evaluations)
    if (e.program == "cycloidal") return e.program;
  return pl.evaluations.empty() ? std::string() : pl.evaluations.front().program;
}

std::string printed_label(const PS::Evaluation& e) {
  return "thesis's conf. " + as_text(e.configuration);
}
std::string printed_key(const PS::Evaluation& e) { return "printed/" + as_text(e.configuration); }

std::vector<Marker> printed_root_markers(const PS& pl, int configuration) {
  std::vector<Marker> out;
  for (const PS::Evaluation* e : printed_placements(pl, printed_program(pl))) {
    if (configuration != 0 && e->configuration != configuration) continue;
    const double X = e->root_xy_m[0], Y = e->root_xy_m[1];
    if (!std::isfinite(X) || !std::isfinite(Y)) continue;
    // one line printed for both configurations (example 1): one mark
    const auto same =
        std::find_if(out.begin(), out.end(), [&](const Marker& o) { return o.x == X && o.y == Y; });
    if (same != out.end()) {
      same->label += " and " + as_text(e->configuration);
      continue;
    }
    Marker m{X, Y, "thesis's printed root, conf. " + as_text(e->configuration),
             colour_for(printed_key(*e)), false};
    m.printed = true;
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace armstudy::report::placement_page
