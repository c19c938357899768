// the placement study's lines of the answer box (page 1): what decides each optimum, the
// assumptions of the energy integral, and the locus of the optimum of least energy
#include <cmath>

#include "report/answer_box.hpp"
#include "report/number_format.hpp"
#include "report/results_record.hpp"
#include "report/study_sections.hpp"
#include "studies/placement/results_section.hpp"

namespace armstudy::report {
namespace {

using PS = studies::placement::ResultsSection;

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

}  // namespace

void placement_answer(const nlohmann::json& results, const ResultsRecord& record, AnswerBox& a) {
  const auto pl = read_section<PS>(results, "placement");
  for (const auto& o : pl.optima)
    a.binding.push_back(o.program + " " + as_text(o.configuration) + ": " +
                        binding_words(o.decided_by));
  for (const auto& u : pl.unsolved)
    a.binding.push_back(u.program + ", configuration " + as_text(u.configuration) +
                        ": no optimum (" + u.reason + ")");
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
