// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Rest-to-rest motion programs s(t) over [0, T] from 0 to L, with s', s'', s'''.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace armstudy::core {

enum class MotionProgram {
  kCycloidal,    ///< eq. 5.2 of Kopmaz (2016); zero end accelerations
  kPoly345,      ///< eq. 5.3; zero end accelerations
  kPoly4567,     ///< 35 t^4 - 84 t^5 + 70 t^6 - 20 t^7; zero end accelerations and jerks
  kTrapezoidal,  ///< trapezoidal velocity, accelerating over T/3 (accelerations jump)
};

/// One sample of a motion program: m, m/s, m/s^2, m/s^3 (or the units of L).
struct ProgramSample {
  double s = 0, sd = 0, sdd = 0, sddd = 0;
};

/// Evaluates `program` at time t (clamped to [0, T]) for a move of length L in time T.
/// For kTrapezoidal the jerk is 0 except at the two corners, where it is not defined.
ProgramSample evaluate_program(MotionProgram program, double t, double T, double L);

/// The program's identifier: "cycloidal", "poly345", "poly4567", "trapezoidal".
std::string_view program_name(MotionProgram program);

/// A person's label, e.g. "cycloidal", "3-4-5 polynomial".
std::string_view program_label(MotionProgram program);

/// Parses an identifier (see program_name); nullopt if unknown.
std::optional<MotionProgram> parse_program(std::string_view name);

/// Every program's identifier, in enum order.
std::vector<std::string> program_names();

}  // namespace armstudy::core
