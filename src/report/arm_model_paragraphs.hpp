// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// What a page says of an arm read from a robot description (`arm: {model: FILE}`): the
/// study's results.json `arm_model` lines (studies::ArmOrigin::lines: the file, the plane
/// and gravity it was solved in, then where each limit came from) as two paragraphs. One
/// wording for every study that takes such an arm (placement, time-optimal).

#include <optional>
#include <string>
#include <vector>

#include "report/page.hpp"

namespace armstudy::report {

/// "The arm read from FILE (...) through MuJoCo's parser; solved in ...", then "Where each
/// limit came from: ...; ...", added to `section`; nothing for an arm written in the case
/// (`arm_model` absent or empty).
void arm_model_paragraphs(const std::optional<std::vector<std::string>>& arm_model,
                          Section& section);

}  // namespace armstudy::report
