// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// MuJoCo draws overlay text as given: a line wider than the frame runs off its edge and is
/// cut ("... locked; e"). These wrap a label at spaces so that each line fits a width in
/// pixels, measured with the font's glyph widths (mjrContext::charWidth).
#include <span>
#include <string>

namespace armstudy::scene {

/// Width in pixels of the widest line of `text` (lines split at '\n').
int overlay_text_width(const std::string& text, std::span<const int> char_width);

/// `text` with its lines broken at spaces so that each fits `max_px`; a single word wider than
/// `max_px` stays whole on its own line. Lines that fit are unchanged.
std::string wrap_overlay_text(const std::string& text, std::span<const int> char_width, int max_px);

}  // namespace armstudy::scene
