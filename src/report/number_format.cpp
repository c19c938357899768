// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/number_format.hpp"

#include <algorithm>
#include <cmath>
#include <locale>
#include <sstream>

namespace armstudy::report {

std::string format_sig(double value, int digits) {
  if (std::isnan(value)) return "n/a";
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.precision(digits);
  os << value;
  return os.str();
}

std::string format_to_error(double value, double error, int digits) {
  if (!(error > 0) || !std::isfinite(error) || !std::isfinite(value) || value == 0)
    return format_sig(value, digits);
  const int known = static_cast<int>(std::ceil(std::log10(std::abs(value) / error))) + 1;
  return format_sig(value, std::clamp(known, 2, 12));
}

}  // namespace armstudy::report
