// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Numbers for people and files, always in the C locale.

#include <string>

namespace armstudy::report {

/// `value` with `digits` significant digits ("%.*g" in the C locale).
std::string format_sig(double value, int digits = 6);

/// `value` to the digits its `error` leaves, plus one (2 to 12 significant digits), e.g.
/// 0.675235 for an error of 5e-5; `digits` significant digits when the error is not known.
std::string format_to_error(double value, double error, int digits = 6);

}  // namespace armstudy::report
