// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "studies/time_optimal/joint_path.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/check.hpp"
#include "core/dynamics.hpp"
#include "core/kinematics.hpp"
#include "studies/time_optimal/natural_spline.hpp"

namespace armstudy::studies::time_optimal {

JointPathGeometry::JointPathGeometry(const JointPathSpec& spec)
    : kind_(spec.kind), pts_(spec.points) {
  const int n = static_cast<int>(pts_.size());
  ARM_THROW_UNLESS(n >= 2, "joint path has " << n << " waypoints; should have >= 2");
  ARM_THROW_UNLESS(kind_ != PathKind::kLine || n == 2,
                   "a line joint path has " << n << " waypoints; should have 2");
  dof_ = static_cast<int>(pts_[0].size());
  ARM_THROW_UNLESS(dof_ >= 1 && dof_ <= core::kMaxLinks, "joint path waypoints have "
                                                             << dof_ << " angles; should have 1 to "
                                                             << core::kMaxLinks);
  for (int i = 1; i < n; ++i)
    ARM_THROW_UNLESS(pts_[i].size() == dof_, "joint path waypoint "
                                                 << i + 1 << " has " << pts_[i].size()
                                                 << " angles; waypoint 1 has " << dof_);
  knot_.assign(n, 0.0);
  for (int i = 1; i < n; ++i) {
    const double h = (pts_[i] - pts_[i - 1]).norm();
    ARM_THROW_UNLESS(h > 1e-9, "joint path waypoints " << i << " and " << i + 1 << " coincide");
    knot_[i] = knot_[i - 1] + h;
  }
  length_ = knot_.back();
  if (kind_ == PathKind::kSpline && n == 2)
    kind_ = PathKind::kPolyline;  // a 2-point spline is a line
  m_.assign(n, core::JointVector::Zero(dof_));
  if (kind_ != PathKind::kSpline) {
    for (int i = 1; i + 1 < n; ++i) {
      // a corner only where the direction changes
      const core::JointVector d0 = (pts_[i] - pts_[i - 1]).normalized();
      const core::JointVector d1 = (pts_[i + 1] - pts_[i]).normalized();
      if ((d1 - d0).norm() > 1e-12) stops_.push_back(knot_[i]);
    }
    return;
  }
  // natural cubic spline through the waypoints, each joint at once
  natural_spline_second_derivatives(knot_, pts_, m_);
}

JointPathPoint JointPathGeometry::at(double s, bool from_left) const {
  s = std::clamp(s, 0.0, length_);
  const int pieces = static_cast<int>(knot_.size()) - 1;
  int i =
      from_left
          ? static_cast<int>(std::lower_bound(knot_.begin(), knot_.end(), s) - knot_.begin()) - 1
          : static_cast<int>(std::upper_bound(knot_.begin(), knot_.end(), s) - knot_.begin()) - 1;
  i = std::clamp(i, 0, pieces - 1);
  const double h = knot_[i + 1] - knot_[i];
  JointPathPoint out;
  if (kind_ != PathKind::kSpline) {
    out.dq = (pts_[i + 1] - pts_[i]) / h;
    out.q = pts_[i] + out.dq * (s - knot_[i]);
    out.ddq = core::JointVector::Zero(dof_);
    return out;
  }
  // cubic piece i (Numerical Recipes 3.3.3 form)
  const double A = (knot_[i + 1] - s) / h, B = (s - knot_[i]) / h;
  out.q = A * pts_[i] + B * pts_[i + 1] +
          ((A * A * A - A) * m_[i] + (B * B * B - B) * m_[i + 1]) * (h * h / 6.0);
  out.dq = (pts_[i + 1] - pts_[i]) / h - ((3 * A * A - 1) / 6.0 * h) * m_[i] +
           ((3 * B * B - 1) / 6.0 * h) * m_[i + 1];
  out.ddq = A * m_[i] + B * m_[i + 1];
  return out;
}

namespace {
std::string fixed_digits(double v, int digits) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(digits);
  os << v;
  return os.str();
}
}  // namespace

std::optional<RangeExcursion> range_excursion(const JointPathGeometry& path,
                                              const std::vector<Eigen::Vector2d>& range) {
  if (range.empty()) return std::nullopt;
  ARM_THROW_UNLESS(
      static_cast<int>(range.size()) == path.dof(),
      "joint range has " << range.size() << " entries; the path has " << path.dof() << " joints");
  const auto outside = [&](const core::JointVector& q, int j) {
    return q[j] < range[j][0] || q[j] > range[j][1];
  };
  const int samples = std::max(1000, path.waypoints() * 64);
  std::optional<RangeExcursion> out;
  double s_prev = 0;
  for (int k = 0; k <= samples; ++k) {
    // the knots exactly, and evenly between them
    const double s = path.length() * k / samples;
    const core::JointVector q = path.at(s).q;
    for (int j = 0; j < path.dof(); ++j) {
      if (!outside(q, j)) continue;
      const double excess = q[j] < range[j][0] ? q[j] - range[j][0] : q[j] - range[j][1];
      if (!out) {
        RangeExcursion e;
        e.joint = j;
        e.lo = range[j][0];
        e.hi = range[j][1];
        // the crossing between the previous sample (inside) and this one
        double a = s_prev, b = s;
        if (k > 0 && !outside(path.at(a).q, j)) {
          while (b - a > 1e-9) {
            const double m = 0.5 * (a + b);
            (outside(path.at(m).q, j) ? b : a) = m;
          }
        }
        e.s = b;
        e.q = path.at(b).q[j];
        e.worst = q[j];
        out = e;
      } else if (out->joint == j) {
        const double worst_excess =
            out->worst < out->lo ? out->worst - out->lo : out->worst - out->hi;
        if (std::abs(excess) > std::abs(worst_excess)) out->worst = q[j];
      }
    }
    s_prev = s;
  }
  if (!out) return std::nullopt;
  out->piece = 0;
  while (out->piece + 2 < path.waypoints() && path.knot(out->piece + 1) <= out->s) ++out->piece;
  std::ostringstream os;
  os << "the path leaves joint " << out->joint + 1 << "'s range [" << fixed_digits(out->lo, 4)
     << ", " << fixed_digits(out->hi, 4) << "] rad at s = " << fixed_digits(out->s, 4) << " rad of "
     << fixed_digits(path.length(), 4) << " (between waypoints " << out->piece + 1 << " and "
     << out->piece + 2 << "), where q" << out->joint + 1 << " reaches "
     << fixed_digits(out->worst, 4) << " rad";
  out->text = os.str();
  return out;
}

JointPoint joint_space_point(const core::PlanarChain& chain, const JointPathGeometry& path,
                             double s, bool from_left) {
  ARM_THROW_UNLESS(path.dof() == chain.num_links(), "joint path has "
                                                        << path.dof() << " joints; the arm has "
                                                        << chain.num_links() << " links");
  const JointPathPoint pp = path.at(s, from_left);
  JointPoint jp;
  jp.s = s;
  jp.q = pp.q;
  jp.dq = pp.dq;
  jp.ddq = pp.ddq;
  jp.p = core::end_effector(chain, jp.q);
  jp.sin_q2 = 1.0;
  // tau = M (q' s'' + q'' s'^2) + C(q, q' s') q' s' + g = a s'' + b s'^2 + c
  const core::JointVector zero = core::JointVector::Zero(chain.num_links());
  jp.c = core::inverse_dynamics(chain, jp.q, zero, zero);
  jp.a = core::mass_matrix(chain, jp.q) * jp.dq;
  jp.b = core::inverse_dynamics(chain, jp.q, jp.dq, jp.ddq) - jp.c;
  return jp;
}

}  // namespace armstudy::studies::time_optimal
