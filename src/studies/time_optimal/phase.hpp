// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The limits of the time-optimal problem in the phase plane of the path: with x = s'^2
/// (m^2/s^2) and u = s'' (m/s^2), every limit at a path point is linear in (x, u):
///   velocity      |q'_j| s' <= qd_max_j          <=>  q'_j^2 x <= qd_max_j^2
///   torque        |a_j u + b_j x + c_j| <= tau_max_j
///   acceleration  |q'_j u + q''_j x| <= qdd_max_j
/// (TOPP-RA's formulation, Pham & Pham 2018). Along an interval [s_i, s_i + ds] with
/// constant u, x(theta) = x_i + 2 theta ds u, so a limit at any point of the interval is
/// still linear in (x_i, u): that is how the solvers enforce limits inside intervals.

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/types.hpp"
#include "studies/time_optimal/path.hpp"

namespace armstudy::studies::time_optimal {

enum class LimitKind { kVelocity = 0, kTorque = 1, kAcceleration = 2 };

/// "velocity", "torque", "acceleration".
const char* limit_name(LimitKind kind);
/// "rad/s", "N m", "rad/s^2".
const char* limit_unit(LimitKind kind);

/// Joint limits (per joint, >= 0).
struct Limits {
  core::JointVector velocity;  ///< one entry per joint
  core::JointVector torque;
  std::optional<core::JointVector> acceleration;
  double of(LimitKind kind, int joint) const;
  int joints() const { return static_cast<int>(velocity.size()); }
};

/// Which limit a row stands for; joint < 0 marks the reach-set row of the solver.
struct RowTag {
  int joint = -1;
  LimitKind kind = LimitKind::kVelocity;
  int point = 0;  ///< grid point (node index) the row was taken at
  double s = 0;   ///< m, where on the path
};

/// lo <= cx x + cu u <= hi (either bound may be infinite).
struct Row {
  double cx = 0, cu = 0, lo = 0, hi = 0;
  RowTag tag;
};

/// Appends the rows of every limit at `jp`, written in the variables (x_i, u) of an
/// interval whose point jp lies `shift` = 2 theta ds metres of x-travel from its start:
/// x(jp) = x_i + shift u. shift = 0 gives the rows at the point itself.
void append_rows(const JointPoint& jp, const Limits& limits, double shift, int point,
                 std::vector<Row>* rows);

/// Feasible interval of x >= 0 for which some u meets every row (an exact 2-variable
/// elimination: every pair of a lower and an upper bound on u gives one bound on x).
struct XInterval {
  double lo = 0;
  double hi = std::numeric_limits<double>::infinity();
  bool empty() const { return lo > hi; }
  RowTag lo_tag, hi_tag;    ///< rows that bind lo and hi (one of a pair)
  RowTag lo_tag2, hi_tag2;  ///< the other row of the binding pair, if any
};
XInterval feasible_x(const std::vector<Row>& rows);

/// The range [lo, hi] of u meeting every row at a given x; tags name the binding rows.
struct URange {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  RowTag lo_tag, hi_tag;
};
URange u_range(const std::vector<Row>& rows, double x);

/// True when (x, u) at jp meets every limit (no tolerance); the solvers' hot check.
inline bool within_limits(const JointPoint& jp, const Limits& lim, double x, double u) {
  const int n = static_cast<int>(jp.dq.size());
  for (int j = 0; j < n; ++j) {
    if (jp.dq[j] * jp.dq[j] * x > lim.velocity[j] * lim.velocity[j]) return false;
    const double tau = jp.a[j] * u + jp.b[j] * x + jp.c[j];
    if (tau > lim.torque[j] || tau < -lim.torque[j]) return false;
    if (lim.acceleration) {
      const double qdd = jp.dq[j] * u + jp.ddq[j] * x;
      if (qdd > (*lim.acceleration)[j] || qdd < -(*lim.acceleration)[j]) return false;
    }
  }
  return true;
}

/// Text naming a row's limit and place, e.g. "the joint 2 torque limit 4 N m at s = 0.310 m";
/// `unit` is the path parameter's ("m" for a tip path, "rad" for a joint-space path).
std::string describe(const RowTag& tag, const Limits& limits, const char* unit = "m");

}  // namespace armstudy::studies::time_optimal
