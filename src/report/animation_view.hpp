// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The moving pictures of a case page, from results.json "animations" (written by
/// scene/animation.hpp): a section of CSS animations over the sprite sheets, each with its
/// still and its video file, and the stylesheet rules that step through each sprite.

#include <string>
#include <vector>

#include "report/page.hpp"
#include "report/results_record.hpp"

namespace armstudy::report {

/// The shortest loop the page plays (s): a shorter motion is slowed down to it, and the
/// caption says by how much; the video file keeps the real speed.
inline constexpr double kShortestLoop_s = 2.5;

/// The "Motion" section (empty blocks when the case has no animations).
Section animation_section(const std::vector<AnimationRecord>& animations);

/// Stylesheet rules for `animations` (results.json "animations"): one class and one @keyframes per
/// sprite (frame k of a grid of `columns` at k / frames of the loop, held: step-end).
std::string animation_css(const std::vector<AnimationRecord>& animations);

/// The CSS class of animation `name` ("a-" + name, other characters than letters, digits,
/// '-' and '_' dropped).
std::string animation_class(const std::string& name);

}  // namespace armstudy::report
