// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Fewer segments for a drawn polyline: a path sampled at a thousand points is drawn as a
/// thousand capsules in every frame, most of them collinear to well under a pixel.

#include <span>
#include <vector>

#include <Eigen/Dense>

namespace armstudy::scene {

/// Indices (increasing, first and last included) of the points of `points` that keep the
/// polyline within `tolerance` (m) of every dropped point (Douglas-Peucker: a dropped point
/// lies within `tolerance` of the segment that replaces it). All indices when tolerance <= 0;
/// {0} for a single point, {} for none.
std::vector<size_t> simplify_polyline(std::span<const Eigen::Vector2d> points, double tolerance);

/// A tolerance (m) that no frame of a view `span_x` x `span_y` m drawn at width x height px
/// can show: a tenth of the smaller of its metres per pixel along x and y.
double subpixel_tolerance(double span_x, double span_y, int width, int height);

}  // namespace armstudy::scene
