// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "core/motion_program.hpp"

#include <algorithm>
#include <cmath>

#include "core/check.hpp"
#include "core/types.hpp"

namespace armstudy::core {
namespace {
constexpr double kTrapezoidRamp = 1.0 / 3.0;  // fraction of T spent accelerating
}

ProgramSample evaluate_program(MotionProgram program, double t, double T, double L) {
  ARM_THROW_UNLESS(T > 0, "motion duration " << T << " s should be > 0");
  const double u = std::clamp(t / T, 0.0, 1.0);
  // normalised f(u), f', f'', f''' on [0, 1]
  double f = 0, f1 = 0, f2 = 0, f3 = 0;
  switch (program) {
    case MotionProgram::kCycloidal: {
      // eq. 5.2
      const double w = 2.0 * kPi;
      f = u - std::sin(w * u) / w;
      f1 = 1.0 - std::cos(w * u);
      f2 = w * std::sin(w * u);
      f3 = w * w * std::cos(w * u);
      break;
    }
    case MotionProgram::kPoly345: {
      // eq. 5.3
      const double u2 = u * u, u3 = u2 * u;
      f = u3 * (10.0 - 15.0 * u + 6.0 * u2);
      f1 = 30.0 * u2 * (1.0 - 2.0 * u + u2);
      f2 = 60.0 * u * (1.0 - 3.0 * u + 2.0 * u2);
      f3 = 60.0 * (1.0 - 6.0 * u + 6.0 * u2);
      break;
    }
    case MotionProgram::kPoly4567: {
      const double u2 = u * u, u3 = u2 * u, u4 = u3 * u;
      f = u4 * (35.0 - 84.0 * u + 70.0 * u2 - 20.0 * u3);
      f1 = u3 * (140.0 - 420.0 * u + 420.0 * u2 - 140.0 * u3);
      f2 = u2 * (420.0 - 1680.0 * u + 2100.0 * u2 - 840.0 * u3);
      f3 = u * (840.0 - 5040.0 * u + 8400.0 * u2 - 4200.0 * u3);
      break;
    }
    case MotionProgram::kTrapezoidal: {
      const double r = kTrapezoidRamp;
      const double vmax = 1.0 / (1.0 - r);  // area of the trapezoid is 1
      const double acc = vmax / r;
      if (u < r) {
        f = 0.5 * acc * u * u;
        f1 = acc * u;
        f2 = acc;
      } else if (u <= 1.0 - r) {
        f = 0.5 * acc * r * r + vmax * (u - r);
        f1 = vmax;
      } else {
        const double d = 1.0 - u;
        f = 1.0 - 0.5 * acc * d * d;
        f1 = acc * d;
        f2 = -acc;
      }
      break;
    }
  }
  return {L * f, L * f1 / T, L * f2 / (T * T), L * f3 / (T * T * T)};
}

std::string_view program_name(MotionProgram program) {
  switch (program) {
    case MotionProgram::kCycloidal: return "cycloidal";
    case MotionProgram::kPoly345: return "poly345";
    case MotionProgram::kPoly4567: return "poly4567";
    case MotionProgram::kTrapezoidal: return "trapezoidal";
  }
  return "?";
}

std::string_view program_label(MotionProgram program) {
  switch (program) {
    case MotionProgram::kCycloidal: return "cycloidal";
    case MotionProgram::kPoly345: return "3-4-5 polynomial";
    case MotionProgram::kPoly4567: return "4-5-6-7 polynomial";
    case MotionProgram::kTrapezoidal: return "trapezoidal velocity";
  }
  return "?";
}

std::optional<MotionProgram> parse_program(std::string_view name) {
  for (MotionProgram p : {MotionProgram::kCycloidal, MotionProgram::kPoly345,
                          MotionProgram::kPoly4567, MotionProgram::kTrapezoidal}) {
    if (program_name(p) == name) return p;
  }
  return std::nullopt;
}

std::vector<std::string> program_names() {
  return {"cycloidal", "poly345", "poly4567", "trapezoidal"};
}

}  // namespace armstudy::core
