// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// results["sensitivity"], typed: the case's answer re-solved at -step and +step of each key
/// its `sensitivity:` part lists (app/sensitivity.hpp; docs/sensitivity.md).

#include <optional>
#include <string>
#include <vector>

#include "report/results_fields.hpp"

namespace armstudy::report {

/// One re-solve: the key at one side of its nominal value.
struct SensitivityStepRecord {
  std::vector<double> key_value;  ///< the key's value(s) at this step
  /// "solved", "not_converged" (an answer the study would not accept), "unsolvable" (no
  /// answer at this value) or "invalid" (the case refuses the value)
  std::string status;
  std::string message;               ///< the study's sentence, or why not
  std::optional<double> value;       ///< the headline figure (null: none)
  std::optional<double> change;      ///< value minus the nominal value
  std::vector<std::string> binding;  ///< the constraints that bind the answer here
  bool binding_changed = false;      ///< binding differs from the nominal's
  bool warm = false;                 ///< warm-started from the nominal answer
  double seconds = 0;                ///< wall time of the re-solve
};

/// One key of `sensitivity:`.
struct SensitivityKeyRecord {
  std::string key;
  std::string step_kind;  ///< "relative" or "absolute"
  double step = 0;
  std::vector<double> nominal;  ///< the key's value(s) in the case file
  std::string why;
  SensitivityStepRecord minus, plus;
  /// central difference: ((f+ - f-) / f0) / ((k+ - k-) / k0); null when a step has no value
  std::optional<double> elasticity;
  std::string range;  ///< where the case stays solvable, in words ("" when both steps solve)
};

/// results["sensitivity"].
struct SensitivityRecord {
  std::string figure;  ///< the key figure's name (results["key_figures"])
  std::string label, unit;
  double nominal = 0;                ///< its value in the case's answer
  std::vector<std::string> binding;  ///< what binds the nominal answer
  std::vector<SensitivityKeyRecord> keys;
  double seconds = 0;  ///< wall time of every re-solve
  /// the steps whose answers met the case's own limits for less than its first answer: the
  /// case was solved again with them as starts, and this part is around that answer (absent:
  /// none)
  std::optional<std::string> resolved_from;
  /// steps whose answers still met the case's limits for less than the answer it reports
  /// (absent: none): the answer is then not the optimum of its problem, and the check says so
  std::optional<std::string> undercut;
};

template <class V>
void fields(V& v, SensitivityStepRecord& x) {
  v("key_value", x.key_value, "the key's value(s) at this step");
  v("status", x.status, "how the re-solve ended",
    {{"enum", nlohmann::json::array({"solved", "not_converged", "unsolvable", "invalid"})}});
  v("message", x.message, "the study's sentence, or why it has no answer");
  v.optional("value", x.value, "the headline figure at this step (null: none)");
  v.optional("change", x.change, "the headline figure minus its nominal value");
  v("binding", x.binding, "the constraints that bind the answer at this step");
  v("binding_changed", x.binding_changed, "they differ from the nominal answer's");
  v("warm", x.warm, "warm-started from the nominal answer");
  v("seconds", x.seconds, "wall time of the re-solve", {{"minimum", 0}});
}
template <class V>
void fields(V& v, SensitivityKeyRecord& x) {
  v("key", x.key, "the case key (dotted path, [N] 1-based)", {{"minLength", 1}});
  v("step_kind", x.step_kind, "a share of the value or in the key's own unit",
    {{"enum", nlohmann::json::array({"relative", "absolute"})}});
  v("step", x.step, "the step", {{"minimum", 0}});
  v("nominal", x.nominal, "the key's value(s) in the case file");
  v("why", x.why, "what the key stands for (empty: not given)");
  v("minus", x.minus, "the re-solve at the nominal value minus the step");
  v("plus", x.plus, "the re-solve at the nominal value plus the step");
  v.optional("elasticity", x.elasticity,
             "((f+ - f-) / f0) / ((k+ - k-) / k0), central (null: a step has no value)");
  v("range", x.range, "where the case stayed solvable, when a step had no answer");
}
template <class V>
void fields(V& v, SensitivityRecord& x) {
  v("figure", x.figure, "the headline key figure varied (its name in key_figures)");
  v("label", x.label, "the figure in words");
  v("unit", x.unit, "its unit, empty for none");
  v("nominal", x.nominal, "the figure in the case's own answer");
  v("binding", x.binding, "the constraints that bind the nominal answer");
  v("keys", x.keys, "every key of the case's sensitivity part, in its order");
  v("seconds", x.seconds, "wall time of every re-solve", {{"minimum", 0}});
  v.optional("resolved_from", x.resolved_from,
             "the steps whose answers met the case's own limits for less than its first answer, "
             "with their energies: the case was solved again from them (absent: none)");
  v.optional("undercut", x.undercut,
             "steps whose answers still meet the case's limits for less than the reported "
             "answer (absent: none; otherwise the answer is not the optimum of its problem)");
}

}  // namespace armstudy::report
