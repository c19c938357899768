// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// the pendulum study's lines of the answer box (page 1): no optimum, the energy check and
// the choices the case makes
#include "report/answer_box.hpp"
#include "report/number_format.hpp"
#include "report/results_record.hpp"
#include "report/study_sections.hpp"
#include "studies/pendulum/study_results.hpp"

namespace armstudy::report {

void pendulum_answer(const studies::PendulumStudyResults& pe, const ResultsRecord&, AnswerBox& a) {
  a.binding.push_back(
      "no optimum: a free swing of the passive tray and ball, checked by the "
      "conservation of its mechanical energy (drift " +
      format_sig(pe.energy.drift_relative, 3) + " of the energy exchanged, tolerance " +
      format_sig(pe.energy.tolerance_relative, 2) + ")");
  for (const std::string& c : pe.parameters.choices) a.assumptions.push_back(c);
}

}  // namespace armstudy::report
