// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// the time-optimal study's lines of the answer box (page 1): the share of the exact
// solver's samples at which each limit is within 1 % of its bound, and the path assumed
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "report/answer_box.hpp"
#include "report/number_format.hpp"
#include "report/results_record.hpp"
#include "report/study_sections.hpp"
#include "studies/time_optimal/study_results.hpp"

namespace armstudy::report {
namespace {

// a share of the samples in per cent: "100" only when it is all of them, whole per cents
// from 10 % (never "1e+02"), two digits below
std::string percent_of_samples(double share) {
  if (share >= 1) return "100";
  const double p = 100 * share;
  if (p >= 9.95) return std::to_string(std::min(99L, std::lround(p)));
  return format_sig(p, 2);
}

}  // namespace

void time_optimal_answer(const studies::time_optimal::StudyResults& to, const ResultsRecord&,
                         AnswerBox& a) {
  using TO = studies::time_optimal::StudyResults;
  if (!to.solvers.empty()) {
    static const TO::Samples none;
    const TO::Samples& s = to.solvers[0].samples ? *to.solvers[0].samples : none;
    const size_t n = s.t_s.size();
    struct Kind {
      const TO::Rows* samples;
      std::vector<double> limit;
      const char* words;
    };
    std::vector<std::pair<double, std::string>> shares;
    for (const Kind& k :
         {Kind{&s.tau_Nm, to.limits.torque_Nm, "torque"},
          Kind{&s.qd_rad_s, to.limits.velocity_rad_s, "velocity"},
          Kind{&s.qdd_rad_s2, to.limits.acceleration_rad_s2.value_or(std::vector<double>{}),
               "acceleration"}}) {
      const auto& l = k.limit;
      for (size_t j = 0; j < l.size() && n > 0; ++j) {
        if (j >= k.samples->size() || (*k.samples)[j].size() != n || !(l[j] > 0)) continue;
        size_t at = 0;
        for (double x : (*k.samples)[j]) at += std::isfinite(x) && std::abs(x) >= 0.99 * l[j];
        if (at > 0)
          shares.push_back(
              {double(at) / n, std::string(k.words) + " of joint " + std::to_string(j + 1)});
      }
    }
    std::stable_sort(shares.begin(), shares.end(),
                     [](const auto& x, const auto& y) { return x.first > y.first; });
    for (const auto& [share, what] : shares)
      a.binding.push_back("the " + what + " limit binds at " + percent_of_samples(share) +
                          " % of the samples (within 1 %)");
    if (shares.empty() && n > 0)
      a.binding.push_back("no limit is within 1 % of its bound at any sample");
  }
  const std::string& path = to.path.kind;
  if (to.path.space == "joint") {
    if (!path.empty())
      a.assumptions.push_back("the joints follow the given joint-space path (" + path +
                              "), parametrised by its chord length in joint space");
    a.assumptions.push_back("rigid links and ideal torque sources");
  } else {
    if (!path.empty())
      a.assumptions.push_back("the tip follows the given path (" + path +
                              "), parametrised by its arc length");
    a.assumptions.push_back("elbow configuration " +
                            (to.configuration ? as_text(*to.configuration) : "n/a") +
                            " throughout; rigid links and ideal torque sources");
  }
  if (!to.limits.acceleration_rad_s2)
    a.assumptions.push_back("no joint acceleration limit (only velocity and torque limits)");
}

}  // namespace armstudy::report
