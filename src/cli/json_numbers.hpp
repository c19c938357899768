#pragma once
/// Numbers in results.json: rounded to a number of significant digits (files stay short
/// and stable across platforms), NaN and infinity as null.

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <nlohmann/json.hpp>

namespace armstudy::app {

/// `v` rounded to `digits` significant digits (0, NaN and infinity unchanged).
inline double round_sig(double v, int digits) {
  if (!std::isfinite(v) || v == 0.0) return v;
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return std::strtod(buf, nullptr);
}

/// `v` rounded to `digits` significant digits as JSON; null when not finite.
inline nlohmann::json json_number(double v, int digits) {
  return std::isfinite(v) ? nlohmann::json(round_sig(v, digits)) : nlohmann::json(nullptr);
}

}  // namespace armstudy::app
