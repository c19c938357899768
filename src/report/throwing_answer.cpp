// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// the throwing study's lines of the answer box (page 1): what binds each optimiser's
// answer, the values the source leaves open, and the ball's flight as the key picture
#include <vector>

#include "report/answer_box.hpp"
#include "report/number_format.hpp"
#include "report/results_record.hpp"
#include "report/study_sections.hpp"
#include "studies/throwing/study_results.hpp"

namespace armstudy::report {
namespace {

std::string constraint_words(const std::string& c) {
  if (c == "contact") return "contact force";
  if (c == "friction") return "friction needed";
  if (c == "tray") return "ball within the tray";
  if (c == "release") return "release angle";
  return c;
}

}  // namespace

void throwing_answer(const studies::ThrowingStudyResults& th, const ResultsRecord& record,
                     AnswerBox& a) {
  if (th.run)
    for (const auto& row : th.run->comparison) {
      std::string b;
      for (const std::string& n : row.binding) b += (b.empty() ? "" : ", ") + constraint_words(n);
      a.binding.push_back(row.optimiser + ": " + (b.empty() ? "no constraint binds" : b + " bind") +
                          "; motor rating nearest its limit: " + row.binding_rating);
    }
  // what the optimum exploits in the model: said before the values the source leaves open
  const auto& mo = th.parameters.motors;
  a.assumptions.push_back(
      "the optimum leans on: a rotor inertia of " + format_sig(mo.rotor_inertia_kg_m2, 3) +
      " kg m^2" +
      (mo.rotor_inertia_kg_m2 == 0 ? " (the motors accelerate at no cost of their own)" : "") +
      (mo.count_regeneration ? "; regenerated energy counted as negative (eq. 7's signed e i)"
                             : "; only e i > 0 counted (no regeneration)") +
      "; no motor inductance (the current follows the voltage at once): its swings of rate "
      "and power are within the model, not shown to be realisable");
  for (const auto& x : th.assumptions)
    a.assumptions.push_back(x.name + ": " + format_sig(x.value, 4) +
                            (x.unit.empty() ? "" : " " + x.unit));
  // the key picture is the flight of the throw the study answers with
  const std::string flight = th.run && th.run->answer == "slsqp" ? "throwing_slsqp_flight_locus.png"
                                                                 : "throwing_flight_locus.png";
  for (const std::string& f : record.frames)
    if (f == flight) a.picture = f;
  if (a.picture.empty())
    for (const std::string& f : record.frames)
      if (f == "throwing_flight_locus.png") a.picture = f;
}

}  // namespace armstudy::report
