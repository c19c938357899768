// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Numbers in results.json: every finite double is written in full, in the shortest form
/// that reads back to the same double (at most 17 significant digits, C locale), so any
/// figure can be re-checked from the file; NaN and infinity as null. Report pages round
/// for display, never results.json.

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

namespace armstudy::app {

/// `v` as a JSON number (written by results_text); null when not finite.
inline nlohmann::json json_number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

/// The shortest decimal form of finite `v` that reads back to the same double
/// (std::to_chars), laid out as nlohmann-json lays out numbers: fixed notation with at
/// least one decimal ("2.0", "0.001") for 1e-5 <= |v| < 1e15, else "1.5e-07", "1e+20".
std::string shortest_number(double v);

/// `j.dump(2)` and a newline, with every floating-point number in its shortest_number
/// form: nlohmann-json's Grisu2 is exact but writes one digit more than needed for about
/// one number in 2000 (e.g. 1.5526199999999999 for 1.55262).
std::string results_text(const nlohmann::json& j);

}  // namespace armstudy::app
