// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Per-study parts of a case page: each gets its study's part of results.json as the
/// study's typed result (read once by app::study_parts through report::read_study_results,
/// studies/<study>/study_results.hpp; a section that is not the study's is a ResultsError
/// naming the key) and adds sections
/// (method, results tables, plots, notes on the source document) to the page. A value that
/// is null in the file (not finite) is shown as "n/a", never invented.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/answer_box.hpp"
#include "report/page.hpp"
#include "studies/pendulum/study_results.hpp"
#include "studies/placement/study_results.hpp"
#include "studies/throwing/study_results.hpp"
#include "studies/time_optimal/study_results.hpp"

namespace armstudy::report {

struct ResultsRecord;

/// A placement case's typed results -> page sections. @throws what the plot writers throw.
void placement_sections(const studies::placement::StudyResults& pl, const ResultsRecord& record,
                        FigureWriter& figures, CasePage& page);
/// A pendulum case's typed results -> page sections.
void pendulum_sections(const studies::PendulumStudyResults& pe, const ResultsRecord& record,
                       FigureWriter& figures, CasePage& page);
/// A throwing case's typed results -> page sections.
void throwing_sections(const studies::ThrowingStudyResults& th, const ResultsRecord& record,
                       FigureWriter& figures, CasePage& page);
/// A time-optimal case's typed results -> page sections.
void time_optimal_sections(const studies::time_optimal::StudyResults& to,
                           const ResultsRecord& record, FigureWriter& figures, CasePage& page);
/// Each study's lines of its answer box (app::study_parts hands them the typed results).
void placement_answer(const studies::placement::StudyResults& pl, const ResultsRecord& record,
                      AnswerBox& box);
void pendulum_answer(const studies::PendulumStudyResults& pe, const ResultsRecord& record,
                     AnswerBox& box);
void throwing_answer(const studies::ThrowingStudyResults& th, const ResultsRecord& record,
                     AnswerBox& box);
void time_optimal_answer(const studies::time_optimal::StudyResults& to, const ResultsRecord& record,
                         AnswerBox& box);

/// The optimal root locations of several placement cases in one plot (the thesis's
/// Figure 9.30): per program and configuration, the locus of its optimum as the line length
/// changes from case to case. `cases` holds (case name, results.json). Writes `svg` and
/// returns true when at least two placement cases have an optimum; false (nothing written)
/// otherwise.
bool placement_loci_across_cases(
    const std::vector<std::pair<std::string, const nlohmann::json*>>& cases,
    const std::filesystem::path& svg);

/// A key/value table of a json object, nested keys joined with '.', arrays of numbers
/// written as [a, b]; arrays of strings (e.g. "choices") are left out.
Table json_table(const nlohmann::json& obj, std::string caption);

/// Axis label of a results.json key by its unit suffix: "energy_J" -> "energy (J)",
/// "q_rad" -> "q (rad)", "phi_deg" -> "phi (deg)".
std::string label_from_key(const std::string& key);
/// A placement optimum's active constraints after the first, in words ("; also active: the
/// power limit of joint 2"), from its results.json `decided_by.active` (constraint, joint);
/// "" when at most one is active.
std::string placement_also_active(
    const std::vector<std::pair<std::string, std::optional<int>>>& active);

}  // namespace armstudy::report
