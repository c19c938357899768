// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The answer box on page 1 of a case report: the one-sentence result, the key picture,
/// the key figures in words with units, the verdict of the study's checks (passed or
/// failed, and what binds the optimum) and the assumptions the case makes where its source
/// is silent. Everything is read from results.json; nothing is computed anew but counts
/// and shares of samples.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace armstudy::report {

struct CasePage;
struct ResultsRecord;

/// What page 1 says about a case.
struct AnswerBox {
  std::string sentence;  ///< the result in one sentence (the study's message)
  std::string picture;   ///< key image, relative to the case folder; empty: none
  std::string picture_caption;
  std::vector<std::pair<std::string, std::string>> figures;  ///< (label in words, value with unit)
  std::string verdict;  ///< "all 10 checks passed" / "2 of 10 checks FAILED: ..."
  bool verdict_ok = true;
  /// what qualifies the status badge ("not converged"); empty: the plain status
  std::string status_note;
  std::vector<std::string> binding;      ///< what binds / decides the optimum, in words
  std::vector<std::string> assumptions;  ///< where the source is silent: value used and why
  std::string source;  ///< the case's source beside armstudy, in one line; empty: no source
  /// the tornado chart of the case's sensitivity part (report/sensitivity_section.hpp)
  std::string sensitivity_chart, sensitivity_caption;
};

/// A study's own lines of its answer box (its registry record, app::StudyEntry::answer): what
/// binds or decides its answer and what the case assumes (`binding`, `assumptions`), read
/// from its typed results of `results`; it may name its key picture (one of record.frames),
/// else the box takes the first locus, else the first strip.
/// @throws ResultsError when results[study] is not the study's section.
/// (app::study_parts reads the section once and hands it to the study's typed function.)
using StudyAnswer =
    std::function<void(const nlohmann::json& results, const ResultsRecord& record, AnswerBox& box)>;

/// The answer box of a case from its results.json (read_record, report/results_record.hpp),
/// with the lines of `study` (none when null); `page` supplies the key figures and, when no
/// frame was rendered, the first figure of the page as the key picture.
/// @throws ResultsError naming the first key of `results` that does not read.
AnswerBox answer_box(const nlohmann::json& results, const CasePage& page, StudyAnswer study);

/// A check's name in words: "mujoco_dynamic_replay.poly345.1" -> "MuJoCo dynamic replay,
/// poly345, 1".
std::string check_label(const std::string& name);

}  // namespace armstudy::report
