// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
// Test helpers: a small factory of arms (2-link horizontal, 2-link vertical, 4-link tray
// with passive joints) and an AssertionResult that prints both operands and the delta.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/planar_chain.hpp"
#include "core/types.hpp"

namespace armstudy::testing {

/// One degree in radians.
inline constexpr double kDeg = core::kPi / 180;

inline ::testing::AssertionResult near_rel(double a, double b, double tol) {
  const double scale = std::max({1.0, std::abs(a), std::abs(b)});
  const double d = std::abs(a - b);
  if (d <= tol * scale) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << a << " vs " << b << ": |delta| " << d << " > " << tol << " x " << scale;
}

template <typename A, typename B>
::testing::AssertionResult near_rel_vec(const A& a, const B& b, double tol) {
  if (a.size() != b.size()) return ::testing::AssertionFailure() << "sizes differ";
  const double scale = std::max({1.0, a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff()});
  const double d = (a - b).cwiseAbs().maxCoeff();
  if (d <= tol * scale) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "[" << a.transpose() << "] vs [" << b.transpose()
                                       << "]: max |delta| " << d << " > " << tol << " x " << scale;
}

struct NamedArm {
  std::string name;
  core::PlanarChain chain;
};

/// The thesis's 2-link arm (000) in a horizontal plane, 1 kg payload.
inline core::PlanarChain thesis_arm() {
  core::PlanarChain c;
  c.links = {{0.4, 4.0, 0.2, 0.0, core::uniform_rod_inertia(4.0, 0.4), true},
             {0.2, 2.0, 0.1, 0.0, core::uniform_rod_inertia(2.0, 0.2), true}};
  c.point_masses = {{1, 0.2, 0.0, 1.0}};
  return core::make_chain(c);
}

/// 2-link arm in a vertical plane with a lateral centre of mass.
inline core::PlanarChain vertical_arm() {
  core::PlanarChain c;
  c.links = {{0.5, 3.0, 0.22, 0.01, 0.07, true}, {0.35, 1.5, 0.15, -0.02, 0.02, true}};
  c.point_masses = {{1, 0.35, 0.0, 0.5}};
  c.gravity = 9.81;
  return core::make_chain(c);
}

/// 4-coordinate tray arm of 003 (Table 1), tray and ball joints passive, ball spin coupled.
inline core::PlanarChain tray_arm() {
  core::PlanarChain c;
  c.links = {{0.080, 0.020, 0.044, 0.0, 1.7e-5, true},
             {0.115, 0.047, 0.078, 0.0, 8.4e-5, true},
             {0.028, 0.018, 0.028, 0.0, 1.2e-6, false},
             {0.005, 0.0, 0.0, 0.0, 0.0, false}};
  c.point_masses = {{3, 0.005, 0.0, 0.012}};
  core::SpinningInertia ball;
  ball.inertia = 4.8e-7;
  ball.coeffs.resize(4);
  ball.coeffs << 1, 1, 1, -0.005 / 0.010;
  c.spinners = {ball};
  c.gravity = 9.81;
  return core::make_chain(c);
}

inline std::vector<NamedArm> arm_factory() {
  return {{"horizontal_2link", thesis_arm()},
          {"vertical_2link", vertical_arm()},
          {"tray_4link", tray_arm()}};
}

inline core::JointVector random_joints(std::mt19937& rng, int n, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  core::JointVector v(n);
  for (int i = 0; i < n; ++i) v[i] = u(rng);
  return v;
}

}  // namespace armstudy::testing
