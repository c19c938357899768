// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Argument and invariant checks of the core (never print, never exit).
///
/// ARM_THROW_UNLESS(cond, msg): a caller's mistake; throws std::invalid_argument with `msg`,
/// which names the quantity, index, value and rule, e.g. "link 2 length -0.1 m should be > 0".
/// ARM_DEMAND(cond): an internal invariant, always on (Drake's DRAKE_DEMAND); throws
/// std::logic_error naming the file, line and condition.

#include <sstream>
#include <stdexcept>
#include <string>

namespace armstudy::core::internal {
[[noreturn]] inline void throw_demand(const char* cond, const char* file, int line) {
  std::ostringstream os;
  os << "internal check failed: " << cond << " at " << file << ":" << line;
  throw std::logic_error(os.str());
}
}  // namespace armstudy::core::internal

#define ARM_THROW_UNLESS(cond, msg)               \
  do {                                            \
    if (!(cond)) {                                \
      std::ostringstream arm_os_;                 \
      arm_os_ << msg;                             \
      throw std::invalid_argument(arm_os_.str()); \
    }                                             \
  } while (0)

#define ARM_DEMAND(cond)                                                              \
  do {                                                                                \
    if (!(cond)) ::armstudy::core::internal::throw_demand(#cond, __FILE__, __LINE__); \
  } while (0)
