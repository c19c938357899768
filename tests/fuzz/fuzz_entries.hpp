// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
// The fuzz targets' entries, shared by the libFuzzer targets (tests/fuzz/*_fuzz.cpp, built
// by run_fuzz.sh with clang, ASan and UBSan) and the corpus replay in the normal build
// (tests/cases/fuzz_corpus_test.cpp), so that the replay runs every file exactly as the
// fuzzer does. Each returns "" when every reader loaded the input or refused it cleanly,
// else what was wrong; an exception other than the readers' own escapes (a finding too).

#include <string>

namespace armstudy::fuzz {

/// The input (1) as a case file through app::load_case_text, (2) as a sweep file over a
/// fixed valid base through app::load_sweep and (3) as the base case of a fixed sweep. A
/// loader may refuse an input only with cases::CaseErrors, each error with a message.
std::string case_and_sweep_loaders(const std::string& input);

/// The input (1) as a case's results.json through app::collect_outputs (how `armstudy
/// merge` and `armstudy diff` read output folders), then the merged summary.md, junit.xml,
/// sweep.csv and sweep.json of it: either it is read whole (status solved or unsolvable)
/// or it is a failed case "unreadable" with a warning naming the file; (2) as a `diff
/// --tolerances` file through app::load_diff_tolerances (refused only with
/// cases::CaseErrors, each with a message), and a lookup in what it read.
std::string results_and_tolerances_readers(const std::string& input);

/// The input as each report template in turn (case.html, index.html, report.css) of a
/// template folder given by ARMSTUDY_TEMPLATE_DIR, the other two the bundled ones'
/// stand-ins, through report::check_templates (how a run reads the folder before it
/// solves); a page template it accepts is then rendered. The reader may refuse it only with
/// cases::InputFileError, with a message; ARMSTUDY_TEMPLATE_DIR is put back after.
std::string template_folder_reader(const std::string& input);

}  // namespace armstudy::fuzz
