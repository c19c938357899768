// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/arm_model_paragraphs.hpp"

namespace armstudy::report {

void arm_model_paragraphs(const std::optional<std::vector<std::string>>& arm_model,
                          Section& section) {
  if (!arm_model || arm_model->empty()) return;
  const std::vector<std::string>& lines = *arm_model;
  section.paragraph("The " + lines[0] + ".");
  if (lines.size() < 2) return;
  std::string from = "Where each limit came from: ";
  for (size_t i = 1; i < lines.size(); ++i) from += lines[i] + (i + 1 < lines.size() ? "; " : ".");
  section.paragraph(from);
}

}  // namespace armstudy::report
