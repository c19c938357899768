// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Geometry of the placement search: the thesis's start-point and direction intervals
/// (Kopmaz 2016, cases 4.7-4.13), the exact annulus check of a line, and the
/// root location in the frame fixed to the line (4.14).
///
/// Frames: the arm's frame A has the root at the origin; the thesis's lines start at
/// S = (x_s, 0) in A with direction u = (cos phi, sin phi). The line frame P has its origin
/// at S, X along u and Y along the left normal (-sin phi, cos phi); the root is at
/// (X, Y) = (-x_s cos phi, x_s sin phi) in P (4.14). Lengths in m, angles in rad.

#include <Eigen/Dense>

#include "studies/placement/arm2.hpp"

namespace armstudy::studies::placement {

/// The reachable annulus of links L1, L2 and the longest line that fits in it.
struct Annulus {
  double L1 = 0, L2 = 0;  ///< m, link lengths
  double inner = 0;       ///< m, |L1 - L2|
  double outer = 0;       ///< m, L1 + L2
  double lmax = 0;  ///< m, 4 sqrt(L1 L2) (4.6): the chord of the outer circle tangent to the inner
};

/// The annulus of a 2-link arm.
Annulus annulus(double L1, double L2);

/// Longest line that stays `margin` m inside both boundaries: the chord of the circle of
/// radius outer - margin tangent to the circle of radius inner + margin, m (0 if none).
double longest_line(const Annulus& a, double margin);

/// The thesis's interval of start abscissae x_s (cases 4.7-4.9), m; x_s runs from `init`
/// (= outer) down to `fin`.
struct XsInterval {
  double init = 0, fin = 0;
  int thesis_case = 0;  ///< 1 (4.7), 2 (4.8), 3 (4.9)
};

/// Cases 4.7-4.9 for a line of length L (L <= lmax).
XsInterval thesis_xs_interval(const Annulus& a, double L);

/// The thesis's interval of direction angles at x_s (cases 4.10-4.13), rad.
struct PhiInterval {
  double init = 0, fin = 0;
  int thesis_case = 0;  ///< 1 (4.10), 2 (4.11), 3 (4.12), 4 (4.13)
};

/// Cases 4.10-4.13 as printed (arguments of acos clamped to [-1, 1]). The printed (4.13b)
/// is lost in the source text; it is taken as pi, mirroring (4.13e).
PhiInterval thesis_phi_interval(const Annulus& a, double L, double x_s);

/// Exact geometry of a line segment against the annulus.
struct LineCheck {
  double r_min = 0;  ///< m, smallest distance of a line point from the root
  double r_max = 0;  ///< m, largest (at an end point)
  /// m, smallest distance of the line to either boundary: min(r_min - inner, outer - r_max);
  /// < 0 when part of the line is outside the annulus.
  double boundary_distance = 0;
  /// smallest |sin q2| along the line, exact: |sin q2| is unimodal in the radius, so its
  /// minimum sits at r_min or r_max (0 on either boundary)
  double min_abs_sin = 0;
};

/// Checks the segment line.start + s line.dir, s in [0, L], against the annulus of L1, L2.
LineCheck check_line(double L1, double L2, const Line& line, double L);

/// Root location (X, Y) in the line frame of the thesis's line (x_s, phi) (4.14), m.
inline Eigen::Vector2d root_in_line_frame(double x_s, double phi) {
  return {-x_s * std::cos(phi), x_s * std::sin(phi)};
}

/// The thesis's (x_s, phi) of a root location (X, Y) in the line frame: x_s = |(X, Y)|,
/// phi = atan2(Y, -X) in (-pi, pi] (Y < 0 gives phi < 0: the mirror half-plane).
inline Eigen::Vector2d line_of_root(const Eigen::Vector2d& root) {
  return {root.norm(), std::atan2(root.y(), -root.x())};
}

}  // namespace armstudy::studies::placement
