// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The report's templates (case.html, index.html, report.css): where they are and how they
/// are read. Apart from the page writer (case_report.hpp) so that the fuzz build reads a
/// template folder as a run does (tests/fuzz/fuzz_entries.hpp).

#include <filesystem>
#include <string>

namespace armstudy::report {

/// The templates every report reads, in template_dir().
inline constexpr const char* kTemplateNames[] = {"case.html", "index.html", "report.css"};

/// The largest template read, bytes (they are a few kB each).
inline constexpr std::size_t kMaxTemplateBytes = std::size_t(1) << 20;

/// The folder holding the templates: $ARMSTUDY_TEMPLATE_DIR if set; else, for a program of
/// the build tree, the source tree's templates/ (compiled in); else, installed,
/// <prefix>/share/armstudy/templates beside the program's <prefix>/bin (from /proc/self/exe).
std::filesystem::path template_dir();

/// A template, read as every input is (cases/input_file.hpp): a regular file of at most
/// kMaxTemplateBytes, never a FIFO or a device that would block or never end. @throws
/// cases::InputFileError naming the file and the reason.
std::string read_template(const std::filesystem::path& p);

/// Reads every template of template_dir() as every input is read (a regular file of at most
/// 1 MiB, never a FIFO or a device) and parses the pages' templates, so that a run learns
/// before it solves anything that it could not write its pages. @throws
/// cases::InputFileError naming the template and the reason (runtime() for an I/O error).
void check_templates();

}  // namespace armstudy::report
