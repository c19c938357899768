#pragma once
/// Numbers for people and files, always in the C locale.

#include <string>

namespace armstudy::report {

/// `value` with `digits` significant digits ("%.*g" in the C locale).
std::string format_sig(double value, int digits = 6);

}  // namespace armstudy::report
