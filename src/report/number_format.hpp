#pragma once
/// Numbers for people and files, always in the C locale.

#include <string>

namespace armstudy::report {

/// `value` with `digits` significant digits ("%.*g" in the C locale).
std::string format_sig(double value, int digits = 6);
/// `value` with `decimals` digits after the point ("%.*f" in the C locale).
std::string format_fixed(double value, int decimals);

}  // namespace armstudy::report
