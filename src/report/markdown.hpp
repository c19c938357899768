#pragma once
/// Markdown text helpers for the tables armstudy writes (summary.md, diff.md).

#include <string>

namespace armstudy::report {

/// `s` as one cell of a Markdown table: '|' escaped, line breaks as spaces.
std::string md_cell(const std::string& s);

}  // namespace armstudy::report
