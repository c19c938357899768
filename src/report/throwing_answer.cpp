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
  // a grid sequence still falling is no plain optimum: the status badge says so
  if (th.run && th.run->control_grids && th.run->control_grids->status == "not_converged")
    a.status_note = "not converged";
  // what the optimum exploits in the model: said before the values the source leaves open
  const auto& mo = th.parameters.motors;
  a.assumptions.push_back(
      "the optimum leans on: rotor inertia " + format_sig(mo.rotor_inertia_kg_m2, 3) + " kg m^2" +
      (mo.count_regeneration ? ", regeneration counted" : ", no regeneration counted") +
      ", no motor inductance");
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
