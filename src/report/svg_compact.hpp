// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Compaction of the SVG that PLplot draws through cairo, without changing what it draws.
/// A report embeds every figure; the browser that prints it to PDF pays per SVG element,
/// and a shaded map is ~9000 paths of ~30 colours.

#include <string>

namespace armstudy::report {

/// `svg` with
/// - every distinct `style` attribute turned into one CSS class of a `<style>` element
///   (cairo repeats a ~300-byte style on every path);
/// - every run of consecutive paths of one class and one transform merged into one path of
///   all their subpaths, where painting them one by one or at once gives the same picture:
///   the class is opaque and undashed, and either only strokes or fills a polygon (straight
///   edges, one subpath) in its stroke's colour under the non-zero rule; the polygons are
///   then oriented alike, so that their merged fill is the union of their fills.
/// Anything else is left as it is. Returns `svg` unchanged when it has no `<svg` element.
std::string compact_svg(const std::string& svg);

}  // namespace armstudy::report
