// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Markdown text helpers for the tables armstudy writes (summary.md, diff.md).

#include <string>

namespace armstudy::report {

/// `s` as one cell of a Markdown table: '|' escaped, '<' as &lt;, line breaks and tabs as
/// spaces, other control characters and bytes that are not UTF-8 as `\xNN`
/// (report/text_escape.hpp).
std::string md_cell(const std::string& s);

}  // namespace armstudy::report
